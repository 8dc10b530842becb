"""The requirements verdict: each check failed in turn at a known place, "not evaluated" cases,
the [requirements] schema and the new active-bearing limits, and the adapter on a real run.

The evidence is built by hand (SI units); each failing variant changes one number of a passing
design, so the expected value, limit, margin and location are known exactly.
"""

from __future__ import annotations

import dataclasses
import json
import math

import pytest
from conftest import SMALLEST

from flexshaft.analyses.criticals import LateralCritical
from flexshaft.design import DesignError, baseline_design, baseline_text, loads_design
from flexshaft.design.requirements import Requirements, log_decrement_from_damping_ratio
from flexshaft.verdict.checks import evaluate, whirl_onset_check
from flexshaft.verdict.evidence import ActuatorEvidence, Evidence, LoopEvidence, ModeDamping, TorsionalEvidence

OP = 4800.0 * 2.0 * math.pi / 60.0  # operating speed [rad/s]
KEYS = [
    "tsai_wu",
    "buckling",
    "whirl_onset",
    "whirl_damping",
    "separation",
    "torsional_separation",
    "actuator_orbit",
    "actuator_force",
    "loop_sensitivity",
    "loop_gain_margin",
    "loop_phase_margin",
    "temperature",
    "spinup_deflection",
]
REQUIREMENTS = Requirements(max_spinup_deflection=5e-3)  # defaults + a spin-up limit


def passing_evidence() -> Evidence:
    return Evidence(
        operating_speed=OP,
        safety_factor=3.0,
        safety_factor_location={"station": 3.21, "ply": "1 (+55°)"},
        buckling_safety_factor=4.0,
        buckling_location={"detail": "positive torque"},
        stability_max_speed=1.5 * OP,
        onset_speed=None,
        modes_at_operating=(ModeDamping("1 (planar, boom)", 31.0, 0.3), ModeDamping("6 (forward, shaft)", 347.0, 0.2)),
        critical_speeds=(
            LateralCritical(0.5 * OP, 50.0, {"station": 8.05}),
            LateralCritical(1.4 * OP, 30.0, {"station": 4.42}),
        ),
        critical_search_max_speed=1.5 * OP,
        actuators=(
            ActuatorEvidence("amb_1", 5e-5, 0.8 * OP, 500.0, 0.8 * OP, 2e-5, 200.0, 2.5e-4, 1500.0),
            ActuatorEvidence("amb_2", 6e-5, 0.9 * OP, 600.0, 0.9 * OP, 1e-5, 100.0, 2.5e-4, 1500.0),
        ),
        max_temperature=320.0,
        temperature_location={"station": 3.21},
        allowable_temperature=373.15,
        spinup_peak=1e-3,
        spinup_location={"station": 4.42, "speed": 0.7 * OP},
        torsional_modes=(
            TorsionalEvidence(
                "T1", 2 * math.pi * 7.0, 0.23, "main rotor 2/rev", (2 * math.pi * 9.15, 2 * math.pi * 10.1)
            ),
            TorsionalEvidence(
                "T2", 2 * math.pi * 140.0, 0.43, "tail rotor 4/rev", (2 * math.pi * 88.9, 2 * math.pi * 98.2)
            ),
        ),
        loops=(
            LoopEvidence("amb_1", "v", OP, 1.8, 2 * math.pi * 50.0, 12.0, -8.0, math.radians(40.0), 2 * math.pi * 49.0),
            LoopEvidence("amb_1", "w", OP, 1.9, 2 * math.pi * 51.0, None, None, math.radians(35.0), 2 * math.pi * 50.0),
        ),
    )


def only_failure(verdict, key: str):
    """The one failed check is ``key``; every other check passes."""
    assert [c.key for c in verdict.checks] == KEYS
    assert [c.key for c in verdict.failed] == [key], verdict
    assert all(c.status == "pass" for c in verdict.checks if c.key != key)
    assert not verdict.passed
    return verdict.check(key)


def test_the_passing_design_passes_every_check() -> None:
    verdict = evaluate(passing_evidence(), REQUIREMENTS)
    assert verdict.passed and not verdict.not_evaluated
    assert [c.status for c in verdict.checks] == ["pass"] * 13
    assert repr(verdict) == "Verdict(PASS: 13 pass)"
    json.dumps(verdict.to_dict())  # JSON-ready


def test_tsai_wu_failure_names_the_ply_and_station() -> None:
    ev = dataclasses.replace(passing_evidence(), safety_factor=1.2)
    check = only_failure(evaluate(ev, REQUIREMENTS), "tsai_wu")
    assert (check.value, check.limit, check.margin) == pytest.approx((1.2, 1.5, -0.3))
    assert check.location == {"station": 3.21, "ply": "1 (+55°)"}


def test_buckling_failure() -> None:
    ev = dataclasses.replace(passing_evidence(), buckling_safety_factor=1.8)
    check = only_failure(evaluate(ev, REQUIREMENTS), "buckling")
    assert (check.value, check.limit, check.margin) == pytest.approx((1.8, 2.0, -0.2))
    assert check.location == {"detail": "positive torque"}


def test_whirl_onset_below_the_margin_fails_at_the_unstable_mode() -> None:
    # onset at 0.74 Ω_op; required (1 + 0.15) Ω_op
    ev = dataclasses.replace(passing_evidence(), onset_speed=0.74 * OP, onset_location={"mode": "6 (forward)"})
    check = only_failure(evaluate(ev, REQUIREMENTS), "whirl_onset")
    assert check.value == pytest.approx(0.74 * OP)
    assert check.limit == pytest.approx(1.15 * OP)
    assert check.margin == pytest.approx(-0.41 * OP)
    assert check.location == {"mode": "6 (forward)"}
    # an onset above the required speed passes, with the same numbers
    ev = dataclasses.replace(ev, onset_speed=1.2 * OP)
    assert evaluate(ev, REQUIREMENTS).check("whirl_onset").margin == pytest.approx(0.05 * OP)


def test_whirl_damping_fails_at_the_least_damped_mode() -> None:
    modes = (
        ModeDamping("1 (planar, boom)", 31.0, 0.3),
        ModeDamping("6 (forward, shaft)", 347.0, -0.004),
        ModeDamping("8 (forward, shaft)", 436.0, 0.05),
    )
    ev = dataclasses.replace(passing_evidence(), modes_at_operating=modes)
    check = only_failure(evaluate(ev, REQUIREMENTS), "whirl_damping")
    assert (check.value, check.limit) == pytest.approx((-0.004, 0.1))
    assert check.location == {"mode": "6 (forward, shaft)", "frequency": 347.0}
    assert check.n_failed == 2 and len(check.findings) == 3
    assert check.note.startswith("2 of 3 fail")


def test_a_damping_ratio_requirement_is_checked_as_its_log_decrement() -> None:
    # ζ ≥ 0.02 ⇔ δ ≥ 2π 0.02/√(1 − 0.0004) = 0.12569
    requirements = Requirements(min_damping_ratio=0.02, max_spinup_deflection=5e-3)
    check = evaluate(passing_evidence(), requirements).check("whirl_damping")
    assert check.limit == pytest.approx(2 * math.pi * 0.02 / math.sqrt(1 - 0.02**2))
    assert check.status == "pass"


def test_separation_fails_for_the_critical_too_close_to_the_operating_speed() -> None:
    # N_c = 0.95 Ω_op with AF = 10: required 17 (1 − 1/8.5) = 15 %, actual 5 %.
    criticals = passing_evidence().critical_speeds + (
        LateralCritical(0.95 * OP, 10.0, {"station": 6.84, "mode": "10"}),
    )
    ev = dataclasses.replace(passing_evidence(), critical_speeds=criticals)
    check = only_failure(evaluate(ev, REQUIREMENTS), "separation")
    assert (check.value, check.limit, check.margin) == pytest.approx((0.05, 0.15, -0.10))
    assert check.location["station"] == 6.84 and check.location["mode"] == "10"
    assert check.location["speed"] == pytest.approx(0.95 * OP)
    assert check.location["position"] == "below" and check.location["amplification_factor"] == 10.0
    assert check.n_failed == 1
    # the same critical with AF 2 needs no margin
    ev = dataclasses.replace(
        ev, critical_speeds=passing_evidence().critical_speeds + (LateralCritical(0.95 * OP, 2.0, {}),)
    )
    assert evaluate(ev, REQUIREMENTS).passed


def test_actuator_orbit_adds_the_static_offset_and_names_the_actuator() -> None:
    # amb_2: static 0.1 mm + orbit 0.2 mm = 0.3 mm > gap 0.25 mm; amb_1 passes.
    amb_1, amb_2 = passing_evidence().actuators
    amb_2 = dataclasses.replace(amb_2, peak_orbit=2e-4, static_offset=1e-4)
    ev = dataclasses.replace(passing_evidence(), actuators=(amb_1, amb_2))
    check = only_failure(evaluate(ev, REQUIREMENTS), "actuator_orbit")
    assert (check.value, check.limit, check.margin) == pytest.approx((3e-4, 2.5e-4, -5e-5))
    assert check.location == {"actuator": "amb_2", "speed": pytest.approx(0.9 * OP)}
    assert [f.passed for f in check.findings] == [True, False]


def test_actuator_force_over_capacity() -> None:
    amb_1, amb_2 = passing_evidence().actuators
    amb_1 = dataclasses.replace(amb_1, peak_force=1400.0)  # + 200 N static = 1600 N > 1500 N
    ev = dataclasses.replace(passing_evidence(), actuators=(amb_1, amb_2))
    check = only_failure(evaluate(ev, REQUIREMENTS), "actuator_force")
    assert (check.value, check.limit, check.margin) == pytest.approx((1600.0, 1500.0, -100.0))
    assert check.location["actuator"] == "amb_1"


def test_temperature_over_the_allowable_and_runaway() -> None:
    ev = dataclasses.replace(passing_evidence(), max_temperature=380.0, temperature_location={"station": 5.0})
    check = only_failure(evaluate(ev, REQUIREMENTS), "temperature")
    assert (check.value, check.limit, check.margin) == pytest.approx((380.0, 373.15, -6.85))
    assert check.location == {"station": 5.0}
    # a runaway fails even when the last iterate was below the allowable
    ev = dataclasses.replace(passing_evidence(), thermal_runaway=True)
    check = only_failure(evaluate(ev, REQUIREMENTS), "temperature")
    assert "runaway" in check.note


def test_spinup_orbit_over_the_limit() -> None:
    ev = dataclasses.replace(passing_evidence(), spinup_peak=6e-3)
    check = only_failure(evaluate(ev, REQUIREMENTS), "spinup_deflection")
    assert (check.value, check.limit, check.margin) == pytest.approx((6e-3, 5e-3, -1e-3))
    assert check.location == {"station": 4.42, "speed": pytest.approx(0.7 * OP)}


def test_torsional_separation_fails_at_the_mode_inside_an_excitation_band() -> None:
    """T2 at 95 Hz inside the tail rotor's 4/rev band 88.9-98.2 Hz: margin 0 < 10 %; T1 passes."""
    modes = (
        passing_evidence().torsional_modes[0],
        TorsionalEvidence("T2", 2 * math.pi * 95.0, 0.0, "tail rotor 4/rev", (2 * math.pi * 88.9, 2 * math.pi * 98.2)),
    )
    ev = dataclasses.replace(passing_evidence(), torsional_modes=modes)
    check = only_failure(evaluate(ev, REQUIREMENTS), "torsional_separation")
    assert (check.value, check.limit, check.margin) == pytest.approx((0.0, 0.1, -0.1))
    assert check.location["mode"] == "T2" and check.location["case"] == "tail rotor 4/rev"
    assert check.location["frequency"] == pytest.approx(2 * math.pi * 95.0)
    assert [f.passed for f in check.findings] == [True, False]


def test_loop_checks_fail_at_the_worst_axis() -> None:
    """A zone-C peak (4.5 > 4), a 3 dB gain fall (< 6 dB) and a 20° phase margin (< 30°) on
    amb_1 w; amb_1 v passes all three."""
    v, w = passing_evidence().loops
    for changes, key, expected in (
        ({"peak_sensitivity": 4.5}, "loop_sensitivity", (4.5, 4.0, -0.5)),
        ({"gain_margin_lower": -3.0}, "loop_gain_margin", (3.0, 6.0, -3.0)),
        ({"phase_margin": math.radians(20.0)}, "loop_phase_margin", tuple(map(math.radians, (20.0, 30.0, -10.0)))),
    ):
        ev = dataclasses.replace(passing_evidence(), loops=(v, dataclasses.replace(w, **changes)))
        check = only_failure(evaluate(ev, REQUIREMENTS), key)
        assert (check.value, check.limit, check.margin) == pytest.approx(expected)
        assert check.location["actuator"] == "amb_1 (w)"
    # a loop with neither phase crossover has no finite gain margin: it is not a finding
    gm = evaluate(passing_evidence(), REQUIREMENTS).check("loop_gain_margin")
    assert len(gm.findings) == 2 and gm.value == 8.0  # amb_1 v's gain fall, the nearer of its two


# ------------------------------------------------------------------------------------------------
# Not evaluated


def test_missing_evidence_and_limits_are_not_evaluated_with_the_reason() -> None:
    amb_1, amb_2 = passing_evidence().actuators
    ev = Evidence(
        operating_speed=OP,
        actuators=(
            dataclasses.replace(amb_1, gap=None, force_capacity=None),
            dataclasses.replace(amb_2, gap=None, force_capacity=None),
        ),
        notes={"tsai_wu": "ply strength needs a lamina shaft material"},
    )
    verdict = evaluate(ev, Requirements())  # no spin-up limit by default
    # (no loops: the loop checks are not listed; no torsional modes: not evaluated)
    assert [c.status for c in verdict.checks] == ["not evaluated"] * 10
    assert verdict.passed and len(verdict.not_evaluated) == 10  # nothing failed, nothing passed
    notes = {c.key: c.note for c in verdict.checks}
    assert notes["tsai_wu"] == "ply strength needs a lamina shaft material"
    assert notes["actuator_orbit"] == "no gap given on the active bearings (amb_1, amb_2)"
    assert notes["actuator_force"] == "no force_capacity given on the active bearings (amb_1, amb_2)"
    assert notes["spinup_deflection"] == "no limit given ([requirements] max_spinup_deflection)"
    assert notes["temperature"] == "no shaft thermal result"
    assert notes["torsional_separation"] == "no torsional modes"
    assert all(c.value is None and c.margin is None for c in verdict.checks)
    assert "10 not evaluated" in verdict.summary


def test_a_gap_on_one_actuator_only_is_evaluated_there() -> None:
    amb_1, amb_2 = passing_evidence().actuators
    ev = dataclasses.replace(passing_evidence(), actuators=(amb_1, dataclasses.replace(amb_2, gap=None)))
    check = evaluate(ev, REQUIREMENTS).check("actuator_orbit")
    assert check.status == "pass" and check.location["actuator"] == "amb_1"
    assert "not evaluated for amb_2 (no gap given)" in check.note


def test_no_active_bearings_and_separation_off() -> None:
    ev = dataclasses.replace(passing_evidence(), actuators=())
    verdict = evaluate(ev, Requirements(separation="off", max_spinup_deflection=5e-3))
    assert verdict.check("actuator_orbit").note == "the design has no active bearings"
    assert verdict.check("separation").status == "not evaluated"
    assert "off" in verdict.check("separation").note


def test_whirl_onset_without_onset_is_a_lower_bound_or_not_evaluated() -> None:
    check = whirl_onset_check(None, 1.5 * OP, OP, 0.15)
    assert check.status == "pass" and check.lower_bound
    assert check.value == pytest.approx(1.5 * OP) and check.margin == pytest.approx(0.35 * OP)
    short = whirl_onset_check(None, 1.1 * OP, OP, 0.15)  # analysed only to 110 % < 115 %
    assert short.status == "not evaluated" and "analyse to a higher speed" in short.note
    none = whirl_onset_check(None, None, OP, 0.15, note="no whirl stability analysis")
    assert none.status == "not evaluated" and none.note == "no whirl stability analysis"


# ------------------------------------------------------------------------------------------------
# The [requirements] table and the active-bearing limits


def test_baseline_requirements_and_bearing_limits() -> None:
    design = baseline_design()
    req = design.requirements
    assert (req.min_safety_factor, req.min_buckling_safety_factor, req.min_onset_margin) == (1.5, 2.0, 0.15)
    assert (req.min_log_decrement, req.min_damping_ratio, req.separation) == (0.1, None, "api684")
    assert req.max_spinup_deflection == 0.005
    amb_1 = design.bearing("amb_1")
    assert (amb_1.gap, amb_1.force_capacity) == (0.25e-3, 1500.0)
    # defaults when the table is absent
    assert Requirements().required_log_decrement == 0.1
    assert Requirements().max_spinup_deflection is None
    assert log_decrement_from_damping_ratio(0.0) == 0.0


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        (
            "min_safety_factor = 1.5 ",
            "min_safety_factor = -1.5 ",
            "requirements.min_safety_factor: must be > 0 (got -1.5)",
        ),
        (
            "min_onset_margin = 0.15 ",
            "min_onset_margin = nan ",
            "requirements.min_onset_margin: must be a finite number",
        ),
        ('separation = "api684"', 'separation = "api610"', 'requirements.separation: unknown value (got "api610"'),
        (
            "min_log_decrement = 0.1 ",
            "min_log_decrement = 0.1\nmin_damping_ratio = 0.02 ",
            "requirements.min_damping_ratio: give at most one of min_log_decrement and min_damping_ratio",
        ),
        ("min_log_decrement = 0.1 ", "min_log_decrement = 0.1\ncolour = 1 ", "requirements.colour: unknown key"),
        ("gap = 0.25e-3 ", "gap = -0.25e-3 ", "bearings[1].gap: must be > 0 (got -0.00025)"),
        ("force_capacity = 1500.0 ", 'force_capacity = "big" ', "bearings[1].force_capacity: must be a number"),
        (
            "fixed too: thesis eq. 2.29 (assumed)",
            "fixed too: thesis eq. 2.29 (assumed)\ngap = 1e-3",
            "bearings[3].gap: unknown key",
        ),
    ],
)
def test_bad_requirements_are_refused_naming_the_field(old: str, new: str, message: str) -> None:
    text = baseline_text()
    assert old in text
    with pytest.raises(DesignError) as info:
        loads_design(text.replace(old, new, 1))
    assert message in str(info.value), str(info.value)


# ------------------------------------------------------------------------------------------------
# The adapter on a real run


def test_adapter_on_a_run_reports_what_it_cannot_evaluate() -> None:
    """An isotropic tube on rigid supports: no plies, no thermal model, no actuators, no limit.
    At the screening resolution (CPU budget, issue 23): the adapter reads the same fields of the
    run whatever its grids (the report's extra detail is not evidence), and the statuses are
    those of the report resolution."""
    from test_separation import TUBE

    from flexshaft.resolution import SCREENING
    from flexshaft.verdict.assess import assess

    design = loads_design(TUBE)
    res = assess(design, SCREENING)
    verdict = res.verdict
    status = {c.key: c.status for c in verdict.checks}
    # the tube's fixed-frame ("thesis") internal damping cannot destabilise whirl: onset passes;
    # a metal shaft gets the metal strength check (not evaluated: its material gives no strengths)
    # and the isotropic shell's buckling (no torque: T_cr/T infinite)
    assert status == {
        "tsai_wu": "not evaluated",
        "metal_strength": "not evaluated",
        "buckling": "pass",
        "whirl_onset": "pass",
        "whirl_damping": "fail",
        "separation": "pass",
        "actuator_orbit": "not evaluated",
        "actuator_force": "not evaluated",
        "temperature": "not evaluated",
        "spinup_deflection": "not evaluated",
        # its first torsional mode (388 Hz, free twist against the held end) is far from 1/rev
        "torsional_separation": "pass",
    }
    # the adapter passes the run's numbers through unchanged
    onset = verdict.check("whirl_onset")
    assert res.stability.onset_speed is None  # stable over the analysed speeds: the lower bound is their top
    assert onset.value == res.stability.speeds[-1] and onset.findings[0].lower_bound
    assert onset.limit == pytest.approx(1.15 * design.operating.speed_rad_s)
    separation = verdict.check("separation")
    (critical,) = separation.findings
    assert critical.location["station"] == pytest.approx(1.0)
    assert critical.value == pytest.approx(1 - critical.location["speed"] / design.operating.speed_rad_s)
    assert verdict.check("tsai_wu").note == "ply strength needs a lamina shaft material"
    assert verdict.check("actuator_orbit").note == "the design has no active bearings"


def test_static_actuator_force_of_an_integrating_bearing_is_its_reaction():
    """Was: a PID bearing (C(0) infinite) entered the force check with a static force of 0 (the
    collocated law times the offset was not finite and was dropped). Now the static force is the
    run's static bearing reaction (the integrator's constraint force); for a PD bearing that
    reaction equals the law C(0) − k_s times the static offset at the magnet (another path).
    On the smallest grids a resolution accepts (3 spin-up and 3 whirl speeds, 4 modes) and a
    coarse mesh, 10 shaft and 6 boom elements (CPU budget, issue 23): the static solution and
    the reactions do not depend on the speed grids or the modes kept, the dynamic peak only
    adds to the static force, and both equalities hold on any mesh (each side is computed on
    the same model)."""
    import numpy as np

    from flexshaft.design import tuned_design, with_overrides
    from flexshaft.verdict.assess import assess

    coarse = {"mesh.shaft_elements": 10, "mesh.boom_elements": 6}
    # the nominal point: the envelope adds nothing here
    tuned = with_overrides(tuned_design(), {"envelope": None, **coarse})
    pd = assess(tuned, SMALLEST)
    for a, ev in zip(pd.model.actuators, pd.evidence.actuators):
        offset = float(np.hypot(*np.real(a.lateral_rows @ pd.static_displacement)))
        assert ev.static_force == pytest.approx(abs(a.law(0j)) * offset, rel=1e-9)
    pid = with_overrides(tuned, {"bearings[1].integral_gain": 2.0e6, "bearings[2].integral_gain": 2.0e6})
    res = assess(pid, SMALLEST)
    evidence = res.evidence.actuators
    for ev in evidence:
        reaction = res.bearing_reactions[ev.name].static_lateral
        assert reaction > 10.0 and ev.static_force == reaction  # 3.5 g on the shaft: tens of newtons at least
    check = res.verdict.check("actuator_force")
    assert check.value >= max(ev.static_force for ev in evidence)
