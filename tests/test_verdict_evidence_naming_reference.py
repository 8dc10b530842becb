"""What the verdict judges and what its findings name, from hand-built evidence (derived here).

Each test feeds a few numbers, chosen by hand, to one check of :mod:`flexshaft.verdict.checks`,
to one reader of :mod:`flexshaft.verdict.gather` (stand-in analyses), to the envelope's
combination or to a data file's attributes, and compares with the value the requirement's
definition (docs/requirements.md) gives by hand arithmetic:

* whirl onset: the limit is (1 + m) Ω_op; with m = 0.2 and Ω_op = 100 rad/s an onset at
  110 rad/s fails by 110 − 120 = −10 rad/s; a scan stable to its top speed gives that speed as
  a lower bound of the onset, and the check names the unstable mode;
* separation: each finding names the critical speed it judges; no resonance peak passes;
* actuators: the excursion finding is at the speed of the excursion peak, the force finding at
  that of the force peak;
* couplings: the angle held is static + whirl: 0.01 + 0.02 = 0.03 rad > 0.025 rad fails;
* loops: a limit shown without a crossover is still in radians (the check's unit);
* which checks apply: ply strength and temperature to a laminated shaft only, the coupling
  angle to a driveline with couplings only;
* gather: mode numbers from 1 (T1 for the first torsional mode, ply 1 the inner ply),
  frequencies in rad/s (2π × Hz), the highest speed analysed is the scan's last, stations where
  the maximum occurs, the buckling sense of the smaller critical torque;
* envelope: the worst finding names its point, each finding its own; a tie goes to the first point;
* the strength data file: the smallest safety factor, the ply angle in degrees.

Every comparison is exact arithmetic on a handful of floats (relative 1e-12 where a product of
floats is formed, else equality).
"""

from __future__ import annotations

import math
from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.analyses.criticals import LateralCritical
from flexshaft.analyses.datasets import strength_dataset
from flexshaft.design.requirements import Requirements
from flexshaft.design.segments import Coupling
from flexshaft.units import format_quantity
from flexshaft.verdict import checks, gather
from flexshaft.verdict.envelope import PointAssessment, envelope_verdict, governing_point
from flexshaft.verdict.evidence import ActuatorEvidence, CouplingEvidence, Evidence, LoopEvidence
from flexshaft.verdict.result import Check, Finding, Verdict

REQ = Requirements(min_onset_margin=0.2)
OMEGA = 100.0  # operating speed [rad/s]


# ------------------------------------------------------------------------------------------------
# checks


def test_an_onset_is_held_against_one_plus_margin_times_operating():
    c = checks.whirl_onset(
        Evidence(OMEGA, onset_speed=110.0, stability_max_speed=200.0, onset_location={"mode": "2 (forward)"}), REQ
    )
    assert c.status == "fail" and c.limit == pytest.approx(120.0, rel=1e-12)
    assert c.margin == pytest.approx(-10.0, rel=1e-12)
    assert c.location["mode"] == "2 (forward)"


def test_stable_to_the_top_speed_is_a_lower_bound():
    c = checks.whirl_onset(Evidence(OMEGA, stability_max_speed=200.0), REQ)
    assert c.status == "pass" and c.value == 200.0 and c.lower_bound


def test_separation_names_the_critical_and_no_peak_passes():
    ev = Evidence(OMEGA, critical_speeds=(LateralCritical(50.0, 2.0, {"station": 1.0}),))
    c = checks.separation(ev, REQ)
    assert c.location["speed"] == 50.0 and c.location["station"] == 1.0
    assert checks.separation(Evidence(OMEGA, critical_speeds=()), REQ).status == "pass"


def test_actuator_findings_at_their_own_peaks():
    a = ActuatorEvidence("A", 1e-4, 10.0, 50.0, 20.0, gap=3e-4, force_capacity=100.0)
    ev = Evidence(OMEGA, actuators=(a,))
    assert checks.actuator_orbit(ev, REQ).location["speed"] == 10.0
    assert checks.actuator_force(ev, REQ).location["speed"] == 20.0


def test_coupling_angle_is_static_plus_whirl():
    c = checks.coupling_angle(Evidence(OMEGA, coupling_angles=(CouplingEvidence("c", 1.0, 0.01, 0.02, 0.025),)), REQ)
    assert c.value == pytest.approx(0.03, rel=1e-12) and c.status == "fail"


def test_phase_limit_without_crossover_is_in_radians():
    loop = LoopEvidence("A", "y", OMEGA, 2.0, 300.0)
    c = checks.loop_phase_margin(Evidence(OMEGA, loops=(loop,)), REQ)
    assert c.status == "pass" and c.limit == pytest.approx(math.radians(REQ.min_phase_margin_deg), rel=1e-12)
    # SI inside (docs/requirements.md: the results in SI units, a unit per check), degrees shown
    assert c.to_dict()["unit"] == "rad" and format_quantity("angle", c.limit) == f"{REQ.min_phase_margin_deg:g}°"


def test_which_checks_apply():
    """Tsai-Wu and the temperature apply to a laminated shaft, whatever its couplings; the
    coupling angle to a driveline with couplings, whatever its shaft (all four combinations, so
    that neither condition can stand in for the other)."""
    rules = {r.key: r for r in checks.CHECKS}
    for laminated in (False, True):
        for coupled in (False, True):
            model = NS(shaft=NS(laminate=object() if laminated else None), couplings=(object(),) if coupled else ())
            assert rules["tsai_wu"].applies(model) is laminated
            assert rules["temperature"].applies(model) is laminated
            assert rules["coupling_angle"].applies(model) is coupled


# ------------------------------------------------------------------------------------------------
# gather (stand-in analyses)


def _modes():
    s = np.array([-1.0 + 30.0j, -2.0 + 80.0j, -0.5 + 120.0j])  # the torsional mode above the whirl modes
    return NS(
        eigenvalues=s,
        kind=np.array(["lateral", "lateral", "torsional"]),
        shaft_fractions=np.array([0.9, 0.8, 1.0]),
        whirl=np.array(["backward", "forward", "-"]),
        component=np.array(["shaft", "shaft", "shaft"]),
        log_decrements=np.array([0.2, 0.3, 0.1]),
    )


def test_gather_whirl_numbers_modes_from_one_and_reads_the_top_speed():
    speeds = np.array([0.0, 100.0, 200.0, 300.0])
    st = NS(
        speeds=speeds,
        onset_speed=280.0,  # nearest analysed speed 300 (StabilityResult.at_speed's rule), no tie
        at_speed=lambda s: int(np.argmin(np.abs(speeds - s))),
        unstable_mode=1,
        onset_kind="whirl",
        whirl=np.array([["backward", "forward"]] * 4),
        onset_whirl="forward",  # mode 2's label at every speed
        eigenvalues=np.array([[-1 + 30j, -1 + 80j]] * 3 + [[-1 + 30j, 2 + 90j]]),
        damping_model="viscous",
        divergence=None,
    )
    p = NS(stability=st, roots=NS(onset_speed=None), modes_at_speed=_modes(), model=NS(design=None, speed=OMEGA))
    out = gather._whirl(p)
    assert out["stability_max_speed"] == 300.0
    assert out["onset_location"]["mode"] == "2 (forward)" and out["onset_location"]["frequency"] == 90.0
    labels = [m.label for m in out["modes_at_operating"]]
    assert labels == ["1 (backward, shaft)", "2 (forward, shaft)"]
    assert out["whirl_modes_top"] == 80.0  # the highest lateral whirl mode, not the torsional one


def _actuator_point(saturation=None):
    a = NS(name="A", lateral_rows=np.eye(2), saturation_force=saturation)
    model = NS(actuators=[a], speed=OMEGA, design=NS(bearing=lambda n: NS(gap=3e-4, force_capacity=100.0)))
    spinup = NS(
        up_to=lambda s: np.arange(3),
        actuator_displacement={"A": np.array([1e-5, 3e-5, 2e-5])},
        actuator_force={"A": np.array([5.0, 1.0, 2.0])},
        speeds=np.array([10.0, 20.0, 30.0]),
    )
    return NS(
        model=model,
        spinup=spinup,
        static_displacement=np.array([3e-6, 4e-6]),
        bearing_reactions={"A": NS(static_lateral=7.0)},
        operating_speed=OMEGA,
        design=NS(operating=NS(speed_range=None)),
    )


def test_gather_actuator_peaks_at_their_speeds_and_the_designs_capacity():
    (a,) = gather._actuators(_actuator_point(saturation=500.0))
    assert (a.peak_orbit, a.orbit_speed, a.peak_force, a.force_speed) == (3e-5, 20.0, 5.0, 10.0)
    assert a.static_offset == pytest.approx(5e-6, rel=1e-12)  # |(3, 4)| µm
    assert a.force_capacity == 100.0  # the design's, not the magnet's 500 N


def test_gather_temperature_names_the_hottest_station():
    th = NS(
        self_heating=None,
        shaft_temperature=NS(temperature=np.array([300.0, 320.0, 310.0]), x=np.array([0.0, 1.0, 2.0])),
        loss_model="m",
    )
    out = gather._temperature(NS(thermal=th, conditions=None), {})
    assert out["max_temperature"] == 320.0 and out["temperature_location"]["station"] == 1.0


def test_gather_spinup_peak_station_and_a_smaller_refined_peak():
    """The largest sampled orbit up to the operating speed, at its station and speed (the shaft's
    peak per speed is the envelope's largest node, as SpinupResponse computes it); a critical
    speed's refined peak replaces it only when larger and at or below the operating speed."""
    envelope = np.array([[1.0, 1.0, 0.0, 9.0], [3.0, 4.0, 0.0, 0.0], [0.0, 2.0, 2.0, 0.0]])  # (node, speed)
    speeds = np.array([10.0, 20.0, 30.0, 40.0])
    spinup = NS(
        up_to=lambda s: np.flatnonzero(speeds <= s), shaft_peak=envelope.max(axis=0), envelope=envelope, speeds=speeds
    )
    p = NS(
        spinup=spinup,
        operating_speed=30.0,
        model=NS(dofs=NS(shaft_x=np.array([0.0, 0.5, 1.0]))),
        design=NS(operating=NS(speed_range=None)),  # one operating speed: the spin-up ends at it
    )
    smaller = NS(speed=15.0, location={"peak_orbit": 2.5, "station": 0.0})
    above = NS(speed=35.0, location={"peak_orbit": 50.0, "station": 1.0})  # beyond the operating speed
    out = gather._spinup_peak(p, [smaller, above])
    assert out["spinup_peak"] == 4.0  # the 9.0 at 40 rad/s lies above the operating speed
    assert out["spinup_location"] == {"station": 0.5, "speed": 20.0}
    larger = NS(speed=25.0, location={"peak_orbit": 5.0, "station": 1.0})
    out = gather._spinup_peak(p, [smaller, larger, above])
    assert out["spinup_peak"] == 5.0
    assert out["spinup_location"] == {
        "station": 1.0,
        "speed": 25.0,
        "detail": "peak refined between the sampled speeds",
    }


def test_gather_torsional_in_rad_s_from_t1():
    s = NS(mode=0, natural_frequency=10.0, margin=0.3, excitation="1/rev", band=(5.0, 7.0))
    (t,) = gather._torsional(NS(torsional_separation=[s]), {})["torsional_modes"]
    assert t.label == "T1" and t.frequency == pytest.approx(20.0 * np.pi, rel=1e-12)
    assert t.band == pytest.approx((10.0 * np.pi, 14.0 * np.pi), rel=1e-12)


def test_gather_loop_margins_units_and_directions():
    m = NS(
        peak_sensitivity=2.0,
        peak_frequency=50.0,
        gain_margin_upper_db=8.0,
        gain_margin_lower_db=-12.0,
        phase_margin_deg=40.0,
        phase_margin_frequency=30.0,
    )
    (lp,) = gather._loops(NS(bearing_loops=[NS(actuator="A", axis="y", speed=OMEGA, margins=m)]))["loops"]
    assert (lp.gain_margin_upper, lp.gain_margin_lower) == (8.0, -12.0)
    assert lp.phase_margin == pytest.approx(math.radians(40.0), rel=1e-12)
    assert lp.phase_margin_frequency == pytest.approx(60.0 * np.pi, rel=1e-12)


def test_gather_buckling_names_the_weaker_sense():
    r = NS(torque_positive=5000.0, torque_negative=3000.0, n_positive=3, n_negative=4, theory="Donnell")
    p = NS(buckling=NS(result=r, safety_factor=3.0, torque=1000.0), torque_factor=1.0)
    assert gather._buckling(p, {})["buckling_location"]["case"] == "negative torque, n = 4"


def test_gather_strength_case_and_ply_from_one():
    total = NS(safety_factor=2.0, x=0.5, ply=2, ply_angle_deg=45.0, phase_deg=90.0, dominant_stress="σ2")
    p = NS(
        strength_static=NS(safety_factor=3.0),
        strength_total=total,
        compressive_strength=None,
        torque_factor=1.0,
        residual_temperature=None,
    )
    loc = gather._strength(p, {})["safety_factor_location"]
    assert loc["case"] == "static + imbalance" and loc["ply"] == "3 (+45°)" and loc["station"] == 0.5


# ------------------------------------------------------------------------------------------------
# envelope


def _point(name, margin):
    f = Finding(10.0 + margin, 10.0, margin, {"station": 1.0})
    c = Check("k", "t", "ratio", "at least", "pass", f.value, f.limit, f.margin, f.location, "", (f,))
    return PointAssessment(name=name, analyses=None, evidence=None, verdict=Verdict((c,)))  # type: ignore[arg-type]


def test_envelope_names_points_and_a_tie_goes_to_the_first():
    (c,) = envelope_verdict([_point("hover", 2.0), _point("cruise", 1.0)]).checks
    assert c.location == {"point": "cruise", "station": 1.0}
    assert [f.location["point"] for f in c.findings] == ["hover", "cruise"]
    assert governing_point([_point("a", 1.0), _point("b", 1.0)]) == "a"


# ------------------------------------------------------------------------------------------------
# inputs and data files


def test_a_coupling_rated_for_two_degrees_is_accepted():
    c = Coupling(
        name="c", x=1.0, angular_stiffness=1e3, axial_stiffness=1e6, torsional_stiffness=1e5, allowable_angle_deg=2.0
    )
    assert c.allowable_angle_deg == 2.0
    # docs/design-reference.md: (0, 90) deg, open at both ends (a bound in radians refused 2 deg)
    for refused in (0.0, 90.0):
        with pytest.raises(ValueError, match="allowable_angle_deg"):
            Coupling(
                name="c",
                x=1.0,
                angular_stiffness=1e3,
                axial_stiffness=1e6,
                torsional_stiffness=1e5,
                allowable_angle_deg=refused,
            )
    assert (
        Coupling(
            name="c",
            x=1.0,
            angular_stiffness=1e3,
            axial_stiffness=1e6,
            torsional_stiffness=1e5,
            allowable_angle_deg=89.9,
        ).allowable_angle_deg
        == 89.9
    )


def test_strength_file_has_the_smallest_factor_and_the_angle_in_degrees():
    s = NS(
        along_shaft=np.array([3.0, 2.0, 5.0]),
        x_along=np.array([0.0, 0.5, 1.0]),
        safety_factor=2.0,
        x=0.5,
        ply=1,
        ply_angle_deg=45.0,
        phase_deg=0.0,
        dominant_stress="σ1",
        load_shares=None,
    )
    attrs = strength_dataset(s).attrs
    assert attrs["safety_factor"] == 2.0 and attrs["critical_ply_angle_deg"] == 45.0
