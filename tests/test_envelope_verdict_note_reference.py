"""The note of an envelope's combined check (flexshaft.verdict.envelope.envelope_verdict), on
hand-built stand-ins of each point's check (no analysis, no number the code produced).

The reference: API contract, the note format of flexshaft.verdict.envelope.envelope_verdict
(its lines ~64-71: "worst of N points: <point>", or "at each of N points" for a check passed
without a number); docs/requirements.md "The operating envelope" states only that the location
names the point and the note gives the count ("its location names the point [...]; its note
says how many points were checked"). A check that passes with a number at every point has a
worst point, the one of the smallest normalised margin (margin / |limit|,
flexshaft.verdict.result.normalised_margin): the location names it (the documented rule) and
the note names it beside the count (the API contract). A check passed *without* a number
everywhere (no phase crossover, no critical speed: nothing to measure) has no worst point; its
note gives the count alone and its location names no point.

Stand-ins: a Tsai-Wu factor of 2.4 at "cold" and 1.8 at "hot" against 1.5 (margins 0.9 and 0.3:
normalised 0.6 and 0.2, "hot" the worst, derived here by hand), and a gain-margin check passed
with no value at both points.
"""

from __future__ import annotations

from flexshaft.verdict.envelope import PointAssessment, envelope_verdict
from flexshaft.verdict.result import Check, Finding, Verdict


def _factor(value: float) -> Check:
    limit = 1.5
    finding = Finding(value, limit, value - limit, {"station": 1.0})
    return Check(
        "tsai_wu",
        "Tsai-Wu safety factor",
        "ratio",
        "at least",
        "pass",
        value,
        limit,
        value - limit,
        {"station": 1.0},
        "",
        (finding,),
    )


def _unmeasured() -> Check:
    return Check("gain_margin", "gain margin", "decibel", "at least", "pass", note="no phase crossover")


def _points() -> list[PointAssessment]:
    return [
        PointAssessment(name=name, analyses=None, evidence=None, verdict=Verdict((_factor(value), _unmeasured())))  # type: ignore[arg-type]
        for name, value in (("cold", 2.4), ("hot", 1.8))
    ]


def test_a_check_passed_with_a_number_names_its_worst_point_in_the_note():
    """Tsai-Wu passes at both points; the worst is "hot" (0.3/1.5 = 0.2 < 0.9/1.5 = 0.6): the
    note counts the two points and names "hot", and the location names it too. The note's
    assertions guard its wording only (a message test of a user-facing message): the worst
    point itself is checked through the value and the location, which also reach
    results.json."""
    check = envelope_verdict(_points()).check("tsai_wu")
    assert check.status == "pass" and check.value == 1.8
    assert check.location["point"] == "hot"
    assert "2 points" in check.note and "hot" in check.note
    assert "cold" not in check.note  # the best point is not named as the worst


def test_a_check_passed_without_a_number_names_no_worst_point():
    """The gain margin passes with no value at both points: nothing to compare, so the note
    counts the points and names neither, and the location has no point."""
    check = envelope_verdict(_points()).check("gain_margin")
    assert check.status == "pass" and check.value is None
    assert "2 points" in check.note and "no phase crossover" in check.note
    assert "hot" not in check.note and "cold" not in check.note
    assert "point" not in check.location
