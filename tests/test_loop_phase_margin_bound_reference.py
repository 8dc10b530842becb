"""A loop without a gain crossover has no phase-margin finding: the evidence's default, against the
sensitivity bound of docs/requirements.md.

docs/requirements.md ("Magnetic-bearing loops"): "The peak bounds the margins from below
(M = |S|max: |1 + L| ≥ 1/M everywhere, so ... at a gain crossover 2 sin(PM/2) ≥ 1/M)", and the
``loop_phase_margin`` row: "smallest phase margin over each axis's gain crossovers".
:class:`~flexshaft.verdict.evidence.LoopEvidence` says ``phase_margin`` is None when the loop has
no gain crossover.

By hand (derived here from that bound): a loop of sensitivity peak M = 1.5 has at any gain
crossover PM ≥ 2 arcsin(1/(2M)) = 2 arcsin(1/3) = 38.94°, above the 30° default
``min_phase_margin_deg``: whatever crossover it might have, it cannot fail the check, so a loop
given with its peak alone (no crossover, no phase margin) must pass the check with no finding.
A loop with a measured 40° margin (consistent with the bound) has one finding, 40° against 30°.
The values are set by hand, the check compares them directly: 1e-12 absolute on angles of order 1
rad (a few roundings of the degree-radian conversion).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.evidence import Evidence, LoopEvidence

PEAK = 1.5
LIMIT_DEG = 30.0


def _check(**margins):
    loop = LoopEvidence(actuator="amb", axis="w", speed=500.0, peak_sensitivity=PEAK, peak_frequency=250.0, **margins)
    requirements = Requirements(min_phase_margin_deg=LIMIT_DEG)
    return evaluate(Evidence(operating_speed=500.0, loops=(loop,)), requirements).check("loop_phase_margin")


def test_the_sensitivity_bound_puts_any_crossover_of_this_loop_above_the_limit():
    bound = 2.0 * math.asin(1.0 / (2.0 * PEAK))
    assert math.degrees(bound) == pytest.approx(38.94, abs=0.01)
    assert math.degrees(bound) > LIMIT_DEG


def test_a_loop_without_a_gain_crossover_has_no_phase_margin_finding():
    check = _check()
    assert check.status == "pass"
    assert check.findings == ()
    assert check.limit == pytest.approx(math.radians(LIMIT_DEG), abs=1e-12)


def test_a_measured_phase_margin_is_the_one_finding():
    check = _check(phase_margin=math.radians(40.0), phase_margin_frequency=300.0)
    assert check.status == "pass"
    assert len(check.findings) == 1
    assert check.value == pytest.approx(math.radians(40.0), abs=1e-12)
    assert check.margin == pytest.approx(math.radians(10.0), abs=1e-12)
