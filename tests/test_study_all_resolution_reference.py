"""``flexshaft study all --resolution report|full``: the studies run at the grids asked for.

Reference: the documented rule of docs/studies.md's resolution table, quoted:

* ``report``: "α every 2.5°; 8 × 8 two-angle (0, 15, 30, 45, 55, 60, 75, 90)";
* ``full``: "α every 1° from 0° to 90°, both ends included; 19 × 19 two-angle, 0° to 90° every 5°".

Derived counts: 2.5° steps strictly inside (0°, 90°) are 2.5, 5, …, 87.5, i.e. 35 angles; 1°
steps from 0° to 90° both included are 91; 0° to 90° every 5° is 19. The option is
case-insensitive (``case_sensitive=False``), so ``FULL`` is ``full``.

The studies are a stand-in that records the resolution the command hands them and stops there
(CliRunner on the embedded design, the pattern of tests/test_actuator_gap_options_reference.py):
nothing is computed. The angles are compared with an absolute 1e-9 deg tolerance: every grid
value is a multiple of 0.5, exact in binary, but numpy's arange computes start + i·step and a
grid written another way (a linspace, a sum of steps) may differ by an ulp (1e-14 deg); 1e-9 deg
is far below the smallest step, 1°.
"""

from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

from flexshaft.cli import app


class _Handed(Exception):
    pass


@pytest.fixture
def handed(monkeypatch):
    seen: dict[str, str] = {}

    def design_studies(design, resolution, **kwargs):
        seen["resolution"] = resolution
        raise _Handed

    monkeypatch.setattr("flexshaft.thesis.design_studies.design_studies", design_studies)
    return seen


@pytest.mark.parametrize(
    ("option", "angles", "two_angles"),
    [
        ([], np.arange(1, 36) * 2.5, [0, 15, 30, 45, 55, 60, 75, 90]),  # the default: report
        (["--resolution", "report"], np.arange(1, 36) * 2.5, [0, 15, 30, 45, 55, 60, 75, 90]),
        (["--resolution", "full"], np.arange(91) * 1.0, np.arange(19) * 5.0),
        (["--resolution", "FULL"], np.arange(91) * 1.0, np.arange(19) * 5.0),
    ],
    ids=["default", "report", "full", "FULL"],
)
def test_study_all_runs_the_grids_of_the_resolution_asked_for(tmp_path, handed, option, angles, two_angles):
    from flexshaft.thesis.design_studies import STUDY_GRIDS

    CliRunner().invoke(app, ["study", "all", "-o", str(tmp_path / "out"), *option])
    assert "resolution" in handed, "the studies were reached"
    grids = STUDY_GRIDS[handed["resolution"]]
    np.testing.assert_allclose(grids["angles"], angles, rtol=0, atol=1e-9)
    np.testing.assert_allclose(grids["two_angles"], two_angles, rtol=0, atol=1e-9)
