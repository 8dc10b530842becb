"""The headline row of study 2 in the run report's "design studies" section names the best
laminate in the order the study's result holds it.

Reference: DesignStudies.best_two_angle is documented by the field's comment as "(alpha, beta)
deg" (thesis/design_studies.py:140), and the row's own label reads "(α/−α/β/−β)s": α in the outer pair,
β in the inner one. docs/studies.md's headline table writes the best of the 15° grid as
"best (55/−55/30/−30)s, R = 49.7", so the stand-in best pair (55, 30) with R = 49.7 must read
55/−55 before 30/−30. Hand-built stand-in studies (tests/test_studies_section_reference.py's
helper), no model solved, no figure drawn: about 0.2 s, nearly all xarray's first use.
"""

from __future__ import annotations

import re

from flexshaft.report.studies_section import studies_section_and_jobs
from tests.test_studies_section_reference import _studies, _table


def test_best_two_angle_pair_named_alpha_outer_beta_inner(tmp_path):
    section, _ = studies_section_and_jobs(
        _studies(best_two_angle=(55.0, 30.0), best_two_angle_safety_factor=49.7), tmp_path
    )
    rows = {row[0]: row[1] for row in _table(section, "Headline").rows}
    text = rows["2. two ply angles (α/−α/β/−β)s, no imbalance"].replace("−", "-")
    match = re.fullmatch(r"\((\d+)/-(\d+)/(\d+)/-(\d+)\)s \(R = ([\d.]+)\)", text)
    assert match, text
    a1, a2, b1, b2, r = match.groups()
    assert (a1, a2, b1, b2) == ("55", "55", "30", "30")
    assert r == "49.7"
