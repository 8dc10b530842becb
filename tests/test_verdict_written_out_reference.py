"""How checks become a verdict and how it is written out (the verdict's dict, dataset and
dataframe; the tightest check; which checks apply to which driveline), against hand-worked
numbers of small evidence filled in directly.

References (derived from the definitions the modules' docstrings state, each worked by hand
below): a minimum requirement's margin is value − limit and passes at ≥ 0; the whirl-onset
requirement is (1 + margin)·Ω_op, so 0.15 above 500 rad/s is 575 rad/s, and a stability
analysis stable up to 700 rad/s gives the lower bound 700 rad/s, margin 125 rad/s; 1 rpm =
2π/60 rad/s, 1 Hz = 2π rad/s; a check that could not be evaluated does not fail the verdict
(docs/requirements.md); the tightest check is the failing one first, then the smallest margin
relative to its limit. Every comparison is of a copy, one subtraction or one unit factor:
tolerance round-off (1e-12) or exact strings.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import CHECKS, evaluate, whirl_onset_check
from flexshaft.verdict.envelope import tightest_check
from flexshaft.verdict.envelope_text import governing_text
from flexshaft.verdict.evidence import Evidence, LoopEvidence, ModeDamping
from flexshaft.verdict.result import Check, Verdict
from flexshaft.verdict.text import limit_text, location_text

RPM = 2.0 * math.pi / 60.0  # rad/s per rpm
HZ = 2.0 * math.pi  # rad/s per Hz


def _onset_lower_bound() -> Check:
    """Stable up to 700 rad/s against (1 + 0.15)·500 = 575 rad/s: a lower bound, margin 125."""
    return whirl_onset_check(None, 700.0, 500.0, 0.15)


def test_onset_lower_bound_is_kept_by_the_check_and_its_dict():
    check = _onset_lower_bound()
    assert check.status == "pass"
    assert check.lower_bound is True
    assert (check.value, check.limit, check.margin) == pytest.approx((700.0, 575.0, 125.0), rel=1e-12)
    data = check.to_dict()
    assert data["lower_bound"] is True
    assert (data["value"], data["limit"], data["margin"]) == pytest.approx((700.0, 575.0, 125.0), rel=1e-12)
    (finding,) = data["findings"]
    assert (finding["value"], finding["limit"], finding["margin"]) == pytest.approx((700.0, 575.0, 125.0), rel=1e-12)


def test_verdict_dataset_and_dataframe_columns():
    """Two checks: onset 700 ≥ 575 rad/s (margin 125) and a safety factor 1.2 against ≥ 1.5
    (margin 1.2 − 1.5 = −0.3): each column holds its own quantity."""
    sf = Check("tsai_wu", "Tsai-Wu", "ratio", "at least", "fail", 1.2, 1.5, 1.2 - 1.5)
    verdict = Verdict((_onset_lower_bound(), sf))
    ds = verdict.to_dataset()
    np.testing.assert_allclose(ds["value"].values, [700.0, 1.2], rtol=1e-12)
    np.testing.assert_allclose(ds["limit"].values, [575.0, 1.5], rtol=1e-12)
    np.testing.assert_allclose(ds["margin"].values, [125.0, -0.3], rtol=1e-12)
    df = verdict.to_dataframe()
    np.testing.assert_allclose(df["value"].to_numpy(float), [700.0, 1.2], rtol=1e-12)
    np.testing.assert_allclose(df["limit"].to_numpy(float), [575.0, 1.5], rtol=1e-12)
    np.testing.assert_allclose(df["margin"].to_numpy(float), [125.0, -0.3], rtol=1e-12)


def test_a_check_not_evaluated_does_not_fail_the_verdict():
    skipped = Check("spinup_deflection", "spin-up orbit", "length", "at most", "not evaluated")
    verdict = Verdict((_onset_lower_bound(), skipped))
    assert verdict.passed is True
    assert verdict.to_dict()["passed"] is True


def test_tightest_check_is_a_failing_one_then_the_smallest_relative_margin():
    """Margins relative to the limit: 125/575 = 0.217 and (1.6 − 1.5)/1.5 = 0.067: the safety
    factor is the tighter; a failing check (1.2 < 1.5) is tighter than both."""
    onset = _onset_lower_bound()
    sf = Check("tsai_wu", "Tsai-Wu", "ratio", "at least", "pass", 1.6, 1.5, 1.6 - 1.5)
    assert tightest_check(Verdict((onset, sf))).key == "tsai_wu"
    assert tightest_check(Verdict((sf, onset))).key == "tsai_wu"
    failing = Check("buckling", "buckling", "ratio", "at least", "fail", 1.2, 1.5, 1.2 - 1.5)
    assert tightest_check(Verdict((onset, failing, sf))).key == "buckling"


def _loop(**margins) -> LoopEvidence:
    return LoopEvidence("amb_1", "v", 500.0, 2.5, 300.0, **margins)


def test_gain_margin_without_a_phase_crossover_shows_its_own_requirement():
    """No phase crossover: a pass with nothing to measure, its limit the gain requirement (8 dB),
    not the phase requirement (40°)."""
    req = Requirements(min_gain_margin_db=8.0, min_phase_margin_deg=40.0)
    verdict = evaluate(Evidence(operating_speed=500.0, loops=(_loop(),)), req)
    check = verdict.check("loop_gain_margin")
    assert check.status == "pass"
    assert check.limit == pytest.approx(8.0, rel=1e-12)
    assert limit_text(check) == "≥ 8 dB"
    phase = verdict.check("loop_phase_margin")
    assert phase.limit == pytest.approx(math.radians(40.0), rel=1e-12)


def test_limit_text_sense_of_a_maximum_and_a_minimum():
    """The sensitivity peak is a maximum (≤ 4), the phase margin a minimum (≥ 30°)."""
    ev = Evidence(operating_speed=500.0, loops=(_loop(phase_margin=math.radians(45.0), phase_margin_frequency=250.0),))
    verdict = evaluate(ev, Requirements())
    assert limit_text(verdict.check("loop_sensitivity")) == "≤ 4"
    assert limit_text(verdict.check("loop_phase_margin")) == "≥ 30°"


def test_whirl_damping_location_frequency_in_rad_s():
    """A mode at 55.32 Hz (347.59 rad/s) is located at that frequency in rad/s and printed 55.32 Hz."""
    ev = Evidence(operating_speed=500.0, modes_at_operating=(ModeDamping("1F", 55.32 * HZ, 0.05),))
    check = evaluate(ev, Requirements()).check("whirl_damping")
    assert check.status == "fail"  # 0.05 < the default 0.1
    assert check.location["frequency"] == pytest.approx(55.32 * HZ, rel=1e-12)
    assert location_text(check.location) == "mode 1F, 55.32 Hz"


def test_no_critical_speed_note_gives_the_search_top_in_rpm():
    """No resonance peak searched up to 6000 rpm (628.3 rad/s): the note says 6000 rpm."""
    ev = Evidence(operating_speed=500.0, critical_speeds=(), critical_search_max_speed=6000.0 * RPM)
    check = evaluate(ev, Requirements()).check("separation")
    assert check.status == "pass"
    assert check.note.endswith("up to 6000 rpm")


def _model(*, laminated: bool, actuators: tuple, couplings: tuple):
    """What the check table's rules read of a model: a metal (isotropic) one-segment shaft or a
    laminated one, its actuators and couplings."""
    kind = "lamina" if laminated else "isotropic"
    return SimpleNamespace(
        shaft=SimpleNamespace(laminate=object() if laminated else None),
        design=SimpleNamespace(materials={"m": SimpleNamespace(kind=kind)}),
        segments=(SimpleNamespace(material="m"),),
        actuators=actuators,
        couplings=couplings,
    )


def test_checks_applying_to_each_kind_of_driveline():
    """Which checks the optimizer constrains (``CheckRule.applies``, read by
    ``flexshaft.optimize.evaluate.applicable_checks``, whose docstring states the rule):
    buckling, whirl, separation and spin-up for every shaft; Tsai-Wu and temperature for a
    one-piece laminated one; metal strength for a metal one; the actuator and loop checks with
    active bearings; the coupling angle with couplings. (The verdict itself lists every check
    and reports one it cannot compute as not evaluated: docs/requirements.md.)"""
    every = ["buckling", "whirl_onset", "whirl_damping", "separation", "torsional_separation", "spinup_deflection"]
    active = ["actuator_orbit", "actuator_force", "loop_sensitivity", "loop_gain_margin", "loop_phase_margin"]

    def keys(model):
        return sorted(rule.key for rule in CHECKS if rule.applies(model))

    metal_coupled = _model(laminated=False, actuators=(), couplings=("c",))
    assert keys(metal_coupled) == sorted([*every, "metal_strength", "coupling_angle"])
    laminated_active = _model(laminated=True, actuators=("amb_1",), couplings=())
    assert keys(laminated_active) == sorted([*every, *active, "tsai_wu", "temperature"])


def test_governing_text_names_the_governing_points_own_tightest_check():
    """Two points: at "cold" the onset passes by 125 rad/s of 575 (22 %); at "hot" (governing) a
    safety factor 1.6 ≥ 1.5 passes by 7 %: the line names hot and its safety factor, ≥ 1.5."""
    cold = SimpleNamespace(name="cold", verdict=Verdict((_onset_lower_bound(),)))
    sf = Check("tsai_wu", "Tsai-Wu safety factor", "ratio", "at least", "pass", 1.6, 1.5, 1.6 - 1.5)
    hot = SimpleNamespace(name="hot", verdict=Verdict((sf,)))
    points = {"cold": cold, "hot": hot}
    assessment = SimpleNamespace(points=[cold, hot], point=points.__getitem__, governing_point="hot")
    assert governing_text(assessment) == "hot (Tsai-Wu safety factor 1.6, ≥ 1.5)"
