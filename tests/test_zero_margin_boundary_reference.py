"""A requirement met exactly (margin 0) passes, in every reader of the verdict.

Reference (docs/requirements.md, "The checks"): the margin is "value − limit for a minimum, limit
− value for a maximum: negative fails", so a margin of exactly zero passes; and ("Separation
margin") "a critical inside the range has none (0: it passes only when its AF needs no margin)",
with "AF < 2.5: the resonance is considered critically damped; no margin". A critically damped
critical inside the operating speed range is therefore the product's own zero-margin finding:
separation 0 of 0 required, exactly (the separation is the literal 0.0 and the requirement 0.0,
so the margin 0.0 − 0.0 is exact on any machine).

Its normalised margin (the measure of the governing point, the optimizer's constraints and the
margins figure; docs/optimizer.md: "normalised margin (≥ 0 passes)") cannot be a violation: a
finding with nothing required and nothing short of it is +inf, and the check's normalised margin
is that of its other critical, derived here from API 684's rule as docs/requirements.md states it:
a critical at 300 rad/s with AF 5 below a range of 480-520 rad/s needs SM = 17 (1 − 1/(5 − 1.5)) %
= 17 · 2.5/3.5 % = 0.121428... and has (480 − 300)/480 = 0.375, so its share is
0.375/0.121428... − 1 = 131.25/42.5 − 1 = 2.0882352941... (a few roundings of values near 1:
compared to 1e-12 relative, far above the 1e-16 scale of those roundings).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.analyses.criticals import LateralCritical
from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import separation
from flexshaft.verdict.envelope import PointAssessment, governing_point
from flexshaft.verdict.evidence import Evidence
from flexshaft.verdict.result import Check, Verdict, normalised_margin

OPERATING = 500.0  # rad/s
RANGE = (480.0, 520.0)  # rad/s
INSIDE = LateralCritical(490.0, 2.0, {"station": 1.0})  # critically damped, inside the range
BELOW = LateralCritical(300.0, 5.0, {"station": 0.5})  # AF 5, below the range


def _separation(*criticals: LateralCritical) -> Check:
    ev = Evidence(operating_speed=OPERATING, operating_range=RANGE, critical_speeds=tuple(criticals))
    return separation(ev, Requirements())


def test_a_critically_damped_critical_inside_the_range_passes_with_zero_margin():
    check = _separation(INSIDE)
    (finding,) = check.findings
    assert (finding.value, finding.limit, finding.margin) == (0.0, 0.0, 0.0)
    assert check.status == "pass" and finding.passed
    # results.json's finding says so too: a zero margin is not a failure
    (written,) = check.to_dict()["findings"]
    assert written["margin"] == 0.0 and written["passed"] is True


def test_a_finding_met_exactly_does_not_pull_the_normalised_margin_down():
    """The zero-margin finding reads +inf; the check's normalised margin is the AF-5 critical's
    2.0882352941... (module docstring), not a violation."""
    assert normalised_margin(_separation(INSIDE)) == math.inf
    share = 131.25 / 42.5 - 1.0
    assert normalised_margin(_separation(INSIDE, BELOW)) == pytest.approx(share, rel=1e-12)


def _point(name: str, *checks: Check) -> PointAssessment:
    evidence = Evidence(operating_speed=OPERATING)
    return PointAssessment(name=name, analyses=None, evidence=evidence, verdict=Verdict(checks))  # type: ignore[arg-type]


def test_a_point_with_a_finding_met_exactly_does_not_govern():
    """Point "exact": the separation above (share 2.088). Point "orbit": an actuator excursion at
    3/4 of its 0.4 mm limit (margin 1e-4 m, share 0.25). The tightest check is the orbit's (0.25 <
    2.088), so "orbit" governs; a zero-margin finding read as a violation would make "exact" govern."""
    orbit = Check("actuator_orbit", "actuator excursion", "length", "at most", "pass", 3e-4, 4e-4, 4e-4 - 3e-4)
    exact, other = _point("exact", _separation(INSIDE, BELOW)), _point("orbit", orbit)
    assert governing_point([exact, other]) == "orbit"
