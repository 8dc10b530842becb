"""The point a report section is drawn at: where its check governs, not the assessment's
governing point (flexshaft.verdict.assess.check_point).

Documented rule, docs/requirements.md ("The checks"): a check's "value, limit, margin and
location are the worst point's (its location names the point ...)"; the assessment's governing
point is "the point of the tightest check (a failing one first, ...)"; and "A figure drawn at
another point says so in its caption: ... the strength table and figure where the Tsai-Wu check
governs". check_point's docstring: the check's location's ``"point"``, "the governing point when
the check names none or the verdict has no such check".

Stand-in points (hand-built evidence, no analysis): at "cold" the whirl onset is 0.9 Ω_op,
below the required 1.15 Ω_op (a failing check), Tsai-Wu 3.0; at "hot" no onset up to 1.5 Ω_op,
Tsai-Wu 2.0. Both pass the Tsai-Wu limit 1.5, so "cold" governs (its failing check first) while
the Tsai-Wu check's worst point, its smaller factor, is "hot". No magnetic bearing: the verdict
has no loop checks. Exact name comparisons (no arithmetic); microseconds of CPU.
"""

from __future__ import annotations

from types import SimpleNamespace

from flexshaft.verdict.assess import check_point
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.envelope import PointAssessment, envelope_verdict, governing_point
from flexshaft.verdict.evidence import Evidence, ModeDamping

OP = 500.0  # rad/s


def _point(name: str, **values) -> PointAssessment:
    ev = Evidence(
        operating_speed=OP, stability_max_speed=1.5 * OP, modes_at_operating=(ModeDamping("1", 300.0, 0.2),), **values
    )
    return PointAssessment(name=name, analyses=None, evidence=ev, verdict=evaluate(ev))


def test_a_check_is_shown_at_its_own_worst_point():
    cold = _point(
        "cold", onset_speed=0.9 * OP, onset_location={"mode": "1"}, safety_factor=3.0, safety_factor_location={}
    )
    hot = _point("hot", safety_factor=2.0, safety_factor_location={"station": 2.0})
    points = [hot, cold]  # the governing point is not the first: "first" and "governing" differ
    assessment = SimpleNamespace(
        verdict=envelope_verdict(points), governing_point=governing_point(points), points=points
    )
    # the premises: a failing check at "cold" governs; Tsai-Wu passes at both, worst at "hot"
    assert assessment.governing_point == "cold"
    assert cold.verdict.check("whirl_onset").status == "fail"
    assert assessment.verdict.check("tsai_wu").status == "pass"
    assert check_point(assessment, "tsai_wu") == "hot"
    assert check_point(assessment, "whirl_onset") == "cold"
    # a check evaluated nowhere names no point, and a check the verdict lacks: the governing one
    # ("cold", the second point), not the first point ("hot")
    assert assessment.verdict.check("buckling").status == "not evaluated"
    assert check_point(assessment, "buckling") == "cold"
    assert "loop_sensitivity" not in [c.key for c in assessment.verdict.checks]
    assert check_point(assessment, "loop_sensitivity") == "cold"
