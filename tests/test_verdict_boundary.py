"""The verdict's boundary: a value exactly at its limit passes, one ulp beyond fails.

docs/requirements.md states each requirement as "at least" or "at most" a limit, so a margin of
exactly zero meets it. The evidence below puts every check of :func:`evaluate` exactly on its
limit, with numbers whose sums and products are exact in binary floating point (0.125, 1500 =
500 + 1000, (1 + 0.25) × 400 = 500, ...), so the margin is 0.0 exactly and the test does not
depend on round-off. Then each check is moved one ulp (``math.nextafter``) to either side of its
limit: the failing side must fail and the passing side pass, which pins the sign convention of
the margins (value − limit for "at least", limit − value for "at most").
"""

from __future__ import annotations

import dataclasses
import math

import pytest

from flexshaft.analyses.criticals import LateralCritical
from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import evaluate, whirl_onset_check
from flexshaft.verdict.evidence import ActuatorEvidence, CouplingEvidence, Evidence, MetalEvidence, ModeDamping
from flexshaft.verdict.result import Finding

OP = 400.0  # operating speed [rad/s]
REQ = Requirements(
    min_safety_factor=1.5,
    min_buckling_safety_factor=2.0,
    min_onset_margin=0.25,
    min_log_decrement=0.125,
    max_spinup_deflection=0.005,
)
REQUIRED_ONSET = 500.0  # (1 + 0.25) × 400, exact
GAP = 0.5**12  # m
ALLOWABLE_ANGLE = 0.5**7  # rad
CRITICAL_BELOW, CRITICAL_ABOVE = 336.0, 504.0  # rad/s, at the API 684 caps (16 %, 26 %) from OP


def evidence_on_every_limit(**changes) -> Evidence:
    """Every requirement met with a margin of exactly zero."""
    on_limits = Evidence(
        operating_speed=OP,
        safety_factor=1.5,
        buckling_safety_factor=2.0,
        stability_max_speed=2 * OP,
        onset_speed=REQUIRED_ONSET,
        modes_at_operating=(ModeDamping("1 (forward, shaft)", 300.0, 0.125), ModeDamping("2", 350.0, 0.5)),
        # API 684 caps: 16 % below and 26 % above for an undamped peak (AF = inf); the criticals
        # sit exactly there: |336 − 400|/400 = 0.16 and |504 − 400|/400 = 0.26.
        critical_speeds=(LateralCritical(CRITICAL_BELOW, math.inf), LateralCritical(CRITICAL_ABOVE, math.inf)),
        critical_search_max_speed=2 * OP,
        actuators=(
            ActuatorEvidence(
                "amb",
                GAP / 2,
                0.5 * OP,
                1000.0,
                0.5 * OP,
                static_offset=GAP / 2,
                static_force=500.0,
                gap=GAP,
                force_capacity=1500.0,
            ),
        ),
        max_temperature=373.15,
        allowable_temperature=373.15,
        spinup_peak=0.005,
        metal_strength=(MetalEvidence("tube_2", "fatigue (modified Goodman)", 1.5, 2.0),),
        coupling_angles=(
            CouplingEvidence("coupling_1", 0.79, ALLOWABLE_ANGLE / 2, ALLOWABLE_ANGLE / 2, ALLOWABLE_ANGLE),
        ),
    )
    return dataclasses.replace(on_limits, **changes)


def test_the_boundary_evidence_is_exact():
    # The separation margins are computed by the package from the speeds: the quotients
    # |N_c − N_op|/N_op round to the same doubles as the caps 16/100 and 26/100.
    assert abs(CRITICAL_BELOW - OP) / OP == 16.0 / 100.0 and abs(CRITICAL_ABOVE - OP) / OP == 26.0 / 100.0
    assert (1.0 + REQ.min_onset_margin) * OP == REQUIRED_ONSET


def test_a_margin_of_exactly_zero_passes_every_check():
    verdict = evaluate(evidence_on_every_limit(), REQ)
    keys = [c.key for c in verdict.checks]
    assert keys == [
        "tsai_wu",
        "metal_strength",
        "buckling",
        "whirl_onset",
        "whirl_damping",
        "separation",
        "actuator_orbit",
        "actuator_force",
        "temperature",
        "spinup_deflection",
        "coupling_angle",
    ]
    for check in verdict.checks:
        assert check.status == "pass", check
        assert check.passed is True
        assert check.margin == 0.0, check
        assert check.value == check.limit, check
        governing = min(check.findings, key=lambda f: f.margin)
        assert governing.margin == 0.0 and governing.passed
    assert verdict.passed and not verdict.failed and not verdict.not_evaluated


def test_finding_passes_at_zero_margin_and_fails_below():
    assert Finding(1.0, 1.0, 0.0).passed
    assert Finding(1.0, 1.0, -0.0).passed
    assert not Finding(1.0, 1.0, -math.ulp(0.0)).passed
    assert Finding(1.0, 1.0, math.ulp(0.0)).passed


def _beyond(limit: float, sense: str) -> float:
    """One ulp on the failing side of ``limit``."""
    return math.nextafter(limit, -math.inf if sense == "at least" else math.inf)


def _within(limit: float, sense: str) -> float:
    return math.nextafter(limit, math.inf if sense == "at least" else -math.inf)


# check key -> (sense, evidence changes for a value v on the check's own scale)
SINGLE = {
    "tsai_wu": ("at least", 1.5, lambda v: {"safety_factor": v}),
    "metal_strength": (
        "at least",
        1.5,
        lambda v: {"metal_strength": (MetalEvidence("tube_2", "fatigue (modified Goodman)", v, 2.0),)},
    ),
    "buckling": ("at least", 2.0, lambda v: {"buckling_safety_factor": v}),
    "whirl_onset": ("at least", REQUIRED_ONSET, lambda v: {"onset_speed": v}),
    "whirl_damping": ("at least", 0.125, lambda v: {"modes_at_operating": (ModeDamping("1", 300.0, v),)}),
    "temperature": ("at most", 373.15, lambda v: {"max_temperature": v}),
    "spinup_deflection": ("at most", 0.005, lambda v: {"spinup_peak": v}),
    "actuator_force": (
        "at most",
        1500.0,
        lambda v: {"actuators": (ActuatorEvidence("amb", 0.0, OP, v, OP, gap=GAP, force_capacity=1500.0),)},
    ),
    "actuator_orbit": (
        "at most",
        GAP,
        lambda v: {"actuators": (ActuatorEvidence("amb", v, OP, 0.0, OP, gap=GAP, force_capacity=1500.0),)},
    ),
    "coupling_angle": (
        "at most",
        ALLOWABLE_ANGLE,
        lambda v: {"coupling_angles": (CouplingEvidence("c", 0.79, 0.0, v, ALLOWABLE_ANGLE),)},
    ),
}


@pytest.mark.parametrize("key", sorted(SINGLE))
def test_one_ulp_beyond_the_limit_fails_and_one_ulp_within_passes(key):
    sense, limit, change = SINGLE[key]
    bad = evaluate(evidence_on_every_limit(**change(_beyond(limit, sense))), REQ)
    good = evaluate(evidence_on_every_limit(**change(_within(limit, sense))), REQ)
    assert bad.check(key).sense == sense
    assert bad.check(key).status == "fail" and bad.check(key).margin < 0
    assert [c.key for c in bad.failed] == [key] and not bad.passed
    assert good.check(key).status == "pass" and good.check(key).margin > 0
    assert good.passed


def test_separation_one_ulp_inside_the_required_margin_fails():
    below, above = CRITICAL_BELOW, CRITICAL_ABOVE
    for speeds in ((math.nextafter(below, OP), above), (below, math.nextafter(above, OP))):
        ev = evidence_on_every_limit(critical_speeds=tuple(LateralCritical(s, math.inf) for s in speeds))
        check = evaluate(ev, REQ).check("separation")
        assert check.status == "fail" and check.margin < 0
    for speeds in ((math.nextafter(below, 0.0), above), (below, math.nextafter(above, math.inf))):
        ev = evidence_on_every_limit(critical_speeds=tuple(LateralCritical(s, math.inf) for s in speeds))
        assert evaluate(ev, REQ).check("separation").status == "pass"


def test_whirl_onset_lower_bound_at_exactly_the_required_speed_passes():
    # Stable up to exactly (1 + margin) Ω_op: the requirement is met (a lower bound, margin 0);
    # one ulp short of it the analysis did not reach the required speed: not evaluated.
    check = whirl_onset_check(None, REQUIRED_ONSET, OP, REQ.min_onset_margin)
    assert check.status == "pass" and check.margin == 0.0 and check.lower_bound
    short = whirl_onset_check(None, math.nextafter(REQUIRED_ONSET, 0.0), OP, REQ.min_onset_margin)
    assert short.status == "not evaluated"
    verdict = evaluate(evidence_on_every_limit(onset_speed=None, stability_max_speed=REQUIRED_ONSET), REQ)
    assert verdict.check("whirl_onset").status == "pass" and verdict.passed


def test_thermal_runaway_fails_even_at_zero_margin():
    verdict = evaluate(evidence_on_every_limit(thermal_runaway=True), REQ)
    assert verdict.check("temperature").status == "fail"
    assert verdict.check("temperature").margin == 0.0


def test_the_least_margin_governs_a_check_with_several_findings():
    # two modes: δ = 0.125 (margin 0) and δ = 0.5; the governing one is the first, and the
    # check passes; replacing it by one an ulp short fails the check at that mode.
    ev = evidence_on_every_limit()
    check = evaluate(ev, REQ).check("whirl_damping")
    assert check.location["mode"] == "1 (forward, shaft)" and check.status == "pass"
    modes = (ModeDamping("2", 350.0, 0.5), ModeDamping("1 (forward, shaft)", 300.0, math.nextafter(0.125, 0.0)))
    check = evaluate(dataclasses.replace(ev, modes_at_operating=modes), REQ).check("whirl_damping")
    assert check.status == "fail" and check.location["mode"] == "1 (forward, shaft)" and check.n_failed == 1
