"""The wiring of the verdict, on hand-built inputs whose right answer is known by construction.

Every analysis can be right while the verdict is wrong: the evidence read from the worst load
case or the best, a peak searched beyond the operating speed, a frequency handed over in Hz
where rad/s is expected, the every-root check at the wrong speed, the assessment showing the
first point instead of the governing one, an envelope point's loads half scaled, a Monte-Carlo
sample drawing another sample's stream. These tests feed the wiring (the evidence gatherers of
:mod:`flexshaft.verdict.gather`, :mod:`flexshaft.verdict.point_tasks`,
:func:`flexshaft.verdict.assess.combine_points`, :func:`flexshaft.design.points.design_at_point`,
the Monte-Carlo sampler, ...) small stand-ins for the analyses' results (``SimpleNamespace``
with the attributes the code reads), built so that the expected number is written down by
hand: the smaller of two safety factors, the orbit peak below the operating speed, 2π × a
frequency in Hz, T_cr/(k T), (1 + margin) Ω, a load scaled by the point's factor. No analysis
runs (each test takes milliseconds); exact comparisons unless a tolerance says why. They were
written for the wiring mutations of scripts/mutations.toml that the suite did not catch.
"""

from __future__ import annotations

import math
from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.design import DesignError, design_from_dict, tuned_design
from flexshaft.design.requirements import Requirements
from flexshaft.verdict import gather
from flexshaft.verdict.checks import whirl_onset_check
from flexshaft.verdict.evidence import Evidence, ModeDamping
from flexshaft.verdict.operating_point import PointAnalyses
from flexshaft.verdict.point_tasks import campbell_ceiling, root_speeds

SPEEDS = np.array([0.0, 100.0, 200.0, 300.0, 400.0])  # a spin-up scan [rad/s], the operating speed 300


def _spinup(**arrays) -> NS:
    """A spin-up scan over :data:`SPEEDS` with SpinupResponse's ``up_to`` (speeds <= Ω)."""
    return NS(speeds=SPEEDS, up_to=lambda speed: np.flatnonzero(SPEEDS <= speed * (1 + 1e-9)), **arrays)


# ------------------------------------------------------------------------ the evidence of a point


def _ply(safety_factor: float, x: float) -> NS:
    return NS(safety_factor=safety_factor, x=x, ply=0, ply_angle_deg=45.0, phase_deg=0.0, dominant_stress="σ2")


@pytest.mark.parametrize(
    ("static", "total", "value", "case"), [(3.0, 2.0, 2.0, "static + imbalance"), (1.5, 2.0, 1.5, "static")]
)
def test_the_ply_check_reads_the_worst_load_case(static, total, value, case):
    """The static and the static + imbalance cases at stations 1 and 2 m: the evidence is the
    smaller factor, at its station, named by its case."""
    p = NS(
        strength_static=_ply(static, 1.0),
        strength_total=_ply(total, 2.0),
        compressive_strength=None,
        torque_factor=1.0,
        residual_temperature=None,
    )
    out = gather._strength(p, {})
    assert out["safety_factor"] == value and out["safety_factor_location"]["case"] == case
    assert out["safety_factor_location"]["station"] == (1.0 if case == "static" else 2.0)


def test_buckling_is_judged_at_the_peak_torque():
    """T_cr = 1000 N m (positive sense, the lower), steady torque 250 N m, the torsional response's
    peak 1.6 × it: the factor at the peak torque is T_cr/(1.6 × 250) = 2.5 (not 4)."""
    result = NS(torque_positive=1000.0, torque_negative=1500.0, n_positive=3, n_negative=4, theory="Donnell")
    p = NS(buckling=NS(result=result, safety_factor=1000.0 / 250.0, torque=250.0), torque_factor=1.6)
    out = gather._buckling(p, {})
    assert out["buckling_safety_factor"] == pytest.approx(1000.0 / (1.6 * 250.0), rel=1e-15)
    assert out["buckling_location"]["case"] == "positive torque, n = 3"


def _stability(onset: float) -> NS:
    """Tracked modes unstable from ``onset`` on (mode 1, forward) on a scan to 900 rad/s."""
    speeds = np.array([0.0, 300.0, 600.0, 900.0])
    return NS(
        speeds=speeds,
        onset_speed=onset,
        at_speed=lambda s: int(np.searchsorted(speeds, s)),
        unstable_mode=0,
        onset_kind="whirl",
        divergence=None,
        whirl=np.full((4, 1), "forward"),
        onset_whirl="forward",
        eigenvalues=np.full((4, 1), 0.1 + 250.0j),
        damping_model="rotating",
    )


def _roots(onset: float, speeds=(0.0, 300.0)) -> NS:
    """The every-root check solved stable at ``speeds`` and unstable at ``onset``."""
    worst = NS(kind="whirl", refined=True, frequency=240.0, root=0.5 + 240.0j, damping_ratio=-0.002)
    return NS(
        onset_speed=onset, worst_at=lambda s: worst, unstable=(NS(speed=onset),), speeds=np.array([*speeds, onset])
    )


def _modes() -> NS:
    """Two lateral modes at the operating speed: 50 % and 5 % of their kinetic energy in the shaft."""
    return NS(
        eigenvalues=np.array([-1.0 + 100.0j, -1.0 + 200.0j]),
        kind=np.array(["lateral", "lateral"]),
        shaft_fractions=np.array([0.5, 0.05]),
        log_decrements=np.array([0.063, 0.031]),
        whirl=["forward", "forward"],
        component=["shaft", "boom"],
    )


@pytest.mark.parametrize(("tracked", "every_root", "onset"), [(600.0, 550.0, 300.0), (600.0, 650.0, 600.0)])
def test_the_onset_is_the_lowest_unstable_speed_of_both_checks(tracked, every_root, onset):
    """The onset is the lowest speed with an unstable root: the tracked modes' (600 rad/s) or the
    every-root check's, whichever is lower; the every-root check's lies above the last speed it
    solved stable (300 rad/s) and at or below its first unstable one, and is held to that lower
    end. The whirl damping counts the mode with a 50 % shaft share, not the one with 5 % (below
    the 10 % of WHIRL_DAMPING_SHAFT_SHARE)."""
    # the model's speed and design set the scope's frequency (no design: the onset margin is 0)
    model = NS(design=None, speed=300.0)
    p = NS(stability=_stability(tracked), roots=_roots(every_root), modes_at_speed=_modes(), model=model)
    out = gather._whirl(p)
    assert out["onset_speed"] == onset
    assert ("root" in out["onset_location"]["mode"]) == (every_root < tracked)
    assert out["modes_at_operating"] == (ModeDamping("1 (forward, shaft)", 100.0, 0.063),)
    assert out["whirl_scope"] == 300.0


def test_an_unstable_root_at_the_required_speed_fails_the_onset_check():
    """docs/requirements.md: no whirl onset below (1 + min_onset_margin) × Ω_op, and the
    every-root check's onset lies at or below the lowest speed with an unstable root. Solved
    stable at rest and at Ω_op = 300 rad/s, unstable at the required 1.15 × 300 = 345 rad/s itself:
    the onset lies in (300, 345] rad/s, below the requirement (until the twenty-fifth session it
    was read as 345 rad/s, a margin of exactly 0, and passed)."""
    model = NS(design=None, speed=300.0)
    p = NS(stability=_stability(None), roots=_roots(345.0), modes_at_speed=_modes(), model=model)
    out = gather._whirl(p)
    assert out["onset_speed"] == 300.0
    assert "between 2865 and 3295 rpm" in out["onset_location"]["detail"]
    check = whirl_onset_check(out["onset_speed"], 345.0, 300.0, 0.15, out["onset_location"])
    assert check.status == "fail" and check.margin == pytest.approx(300.0 - 345.0, rel=1e-12)


#: One operating speed, and a speed range to 400 rad/s (its highest speed 4/3 × 300).
ONE_SPEED, RANGE_TO_400 = NS(speed_range=None), NS(speed_range=(0.9, 4.0 / 3.0), speed_limits=(270.0, 400.0))


@pytest.mark.parametrize(
    ("operating", "expected"), [(ONE_SPEED, (3e-5, 200.0, 50.0, 100.0)), (RANGE_TO_400, (9e-5, 400.0, 90.0, 400.0))]
)
def test_actuator_peaks_are_up_to_the_highest_operating_speed_each_at_its_own_speed(operating, expected):
    """Orbit [0, 1, 3, 2, 9] × 1e-5 m and force [0, 50, 20, 10, 90] N over 0-400 rad/s, operating at
    300: the orbit peak 3e-5 m at 200 rad/s, the force peak 50 N at 100 rad/s (the overspeed
    point at 400 rad/s is not part of the spin-up to the operating speed). With a speed range to
    400 rad/s (the maximum continuous speed) the shaft runs there too: 9e-5 m and 90 N at 400."""
    actuator = NS(name="amb", lateral_rows=np.array([[3.0, 0.0], [0.0, 4.0]]), saturation_force=None)
    bearing = NS(gap=1e-3, force_capacity=500.0)
    spinup = _spinup(
        actuator_displacement={"amb": [0.0, 1e-5, 3e-5, 2e-5, 9e-5]},
        actuator_force={"amb": [0.0, 50.0, 20.0, 10.0, 90.0]},
    )
    p = NS(
        model=NS(actuators=[actuator], design=NS(bearing=lambda name: bearing), speed=300.0),
        spinup=spinup,
        static_displacement=np.array([1e-6, 1e-6]),
        bearing_reactions={"amb": NS(static_lateral=7.0)},
        operating_speed=300.0,
        design=NS(operating=operating),
    )
    (ev,) = gather._actuators(p)
    assert (ev.peak_orbit, ev.orbit_speed, ev.peak_force, ev.force_speed) == expected
    assert ev.static_offset == pytest.approx(5e-6, rel=1e-15)  # |(3, 4)| × 1e-6 m
    assert (ev.static_force, ev.gap, ev.force_capacity) == (7.0, 1e-3, 500.0)


def test_the_spinup_peak_counts_refined_criticals_below_the_highest_operating_speed_only():
    """Sampled peaks [0, 1, 2, 1.5, 5] × 1e-4 m; a refined critical at 150 rad/s (2.5e-4 m, between
    the samples) raises the peak below the operating speed 300; one at 350 rad/s (9e-4 m) lies
    above it and does not count, unless the speed range reaches 400 rad/s: then it does, and
    so does the sample at 400 (5e-4 m) without it."""
    spinup = _spinup(shaft_peak=np.array([0.0, 1e-4, 2e-4, 1.5e-4, 5e-4]), envelope=np.eye(3, 5))
    model = NS(dofs=NS(shaft_x=np.array([0.0, 1.0, 2.0])))
    p = NS(spinup=spinup, operating_speed=300.0, model=model, design=NS(operating=ONE_SPEED))
    criticals = [
        NS(speed=350.0, location={"peak_orbit": 9e-4, "station": 1.5}),
        NS(speed=150.0, location={"peak_orbit": 2.5e-4, "station": 0.5}),
    ]
    out = gather._spinup_peak(p, criticals)
    assert out["spinup_peak"] == 2.5e-4 and out["spinup_location"]["speed"] == 150.0
    sampled = gather._spinup_peak(p, criticals[:1])
    assert sampled["spinup_peak"] == 2e-4 and sampled["spinup_location"] == {"station": 2.0, "speed": 200.0}
    ranged = NS(spinup=spinup, operating_speed=300.0, model=model, design=NS(operating=RANGE_TO_400))
    out = gather._spinup_peak(ranged, criticals)
    assert out["spinup_peak"] == 9e-4 and (out["spinup_location"]["station"], out["spinup_location"]["speed"]) == (
        1.5,
        350.0,
    )
    sampled = gather._spinup_peak(ranged, [])
    # (the envelope's column at 400 rad/s is zero at every node: its first station, 0.0)
    assert sampled["spinup_peak"] == 5e-4 and sampled["spinup_location"] == {"station": 0.0, "speed": 400.0}


@pytest.mark.parametrize(("material", "peak", "detail"), [(362.0, 362.0, "material"), (280.0, 320.0, "equilibrium")])
def test_a_hot_soaked_start_governs_the_temperature_when_hotter(material, peak, detail):
    """Self-heating equilibrium 300/320/310 K along the shaft; a point whose material starts at
    362 K (hot-soaked) peaks at 362 K, one starting at 280 K at the equilibrium's 320 K."""
    temperature = NS(temperature=np.array([300.0, 320.0, 310.0]), x=np.array([0.0, 1.0, 2.0]))
    thermal = NS(self_heating=NS(status="converged"), shaft_temperature=temperature, loss_model="rotating")
    conditions = NS(material_temperature=material, point=NS(material_temperature="parked"))
    out = gather._temperature(NS(thermal=thermal, conditions=conditions), {})
    assert out["max_temperature"] == peak and not out["thermal_runaway"]
    assert ("station" in out["temperature_location"]) == (detail == "equilibrium")


def test_torsional_modes_and_loops_are_handed_over_in_radians():
    """A torsional mode at 9.46 Hz in a band of 9.15-10.1 Hz, a loop whose sensitivity peaks at
    10 Hz with a 45° phase margin at 20 Hz: 2π × each frequency [rad/s], π/4 [rad]; an infinite
    gain margin (no crossover) is None."""
    separation = NS(mode=0, natural_frequency=9.46, margin=0.0, excitation="main rotor 2/rev", band=(9.15, 10.1))
    (mode,) = gather._torsional(NS(torsional_separation=[separation]), {})["torsional_modes"]
    assert mode.label == "T1" and mode.frequency == pytest.approx(2 * math.pi * 9.46, rel=1e-15)
    assert mode.band == pytest.approx((2 * math.pi * 9.15, 2 * math.pi * 10.1), rel=1e-15)
    margins = NS(
        peak_sensitivity=2.0,
        peak_frequency=10.0,
        gain_margin_upper_db=8.0,
        gain_margin_lower_db=-math.inf,
        phase_margin_deg=45.0,
        phase_margin_frequency=20.0,
    )
    loop = NS(actuator="amb", axis="y", speed=300.0, margins=margins)
    (ev,) = gather._loops(NS(bearing_loops=[loop]))["loops"]
    assert ev.peak_frequency == pytest.approx(2 * math.pi * 10.0, rel=1e-15)
    assert ev.phase_margin == pytest.approx(math.pi / 4, rel=1e-15)
    assert ev.phase_margin_frequency == pytest.approx(2 * math.pi * 20.0, rel=1e-15)
    assert (ev.gain_margin_upper, ev.gain_margin_lower) == (8.0, None)


# ------------------------------------------------------------------------ the analyses of a point


def test_every_root_is_checked_at_rest_the_operating_speed_and_the_required_onset():
    """min_onset_margin 0.25 at 400 rad/s: the every-root check at 0, 400 and 1.25 × 400 = 500."""
    model = NS(speed=400.0, design=NS(requirements=NS(min_onset_margin=0.25)))
    assert root_speeds(model).tolist() == [0.0, 400.0, 500.0]


def test_the_campbell_ceiling_is_the_top_speed_times_the_highest_excitation_order():
    """Shaft 1/rev; a 4-bladed tail rotor through a 0.5 gearbox ratio (the rotor turns twice as
    fast: 2/rev, 8/rev); a 5-bladed main rotor at 300 rpm against the shaft's 6000 rpm (k/20 per
    rev): the highest order is 8, the ceiling 8 × Ω without a Campbell scan."""
    speed = 6000.0 * math.pi / 30.0
    operating = NS(main_rotor_speed_rpm=300.0, main_rotor_blades=5, speed_rad_s=speed)
    design = NS(tail_rotor=NS(gearbox_ratio=0.5, blades=4), operating=operating)
    ceiling = campbell_ceiling(NS(speed=speed, design=design), NS(campbell_speeds=0))
    assert ceiling == pytest.approx(8.0 * speed, rel=1e-15)


# ------------------------------------------------------------------------ judging the points


def _blank_analyses() -> PointAnalyses:
    """A point's analyses that no step of the combining reads (each field None)."""
    from dataclasses import MISSING, fields

    return PointAnalyses(**{f.name: None for f in fields(PointAnalyses) if f.default is MISSING})


def test_the_assessment_shows_the_governing_point_of_the_design_assessed():
    """The tuned design's four points with Tsai-Wu factors 3.0, 1.8, 2.5 and 4.0 (limit 1.5): the
    standard day (index 1) governs, and the assessment's evidence is its evidence, its design
    the design assessed (not a point's), its verdict the worst of each check."""
    from flexshaft.resolution import SCREENING
    from flexshaft.verdict.assess import combine_points
    from flexshaft.verdict.checks import evaluate
    from flexshaft.verdict.envelope import PointAssessment

    design = tuned_design()
    names = [p.name for p in design.envelope.points]
    assert names == ["cold_day", "standard_day", "hot_day", "hot_soak_start"]
    judged = []
    for name, factor in zip(names, (3.0, 1.8, 2.5, 4.0)):
        evidence = Evidence(operating_speed=500.0, safety_factor=factor, safety_factor_location={"station": 1.0})
        verdict = evaluate(evidence, design.requirements)
        judged.append(PointAssessment(name=name, analyses=_blank_analyses(), evidence=evidence, verdict=verdict))
    a = combine_points(design, judged, SCREENING)
    assert a.governing_point == "standard_day" and a.evidence is judged[1].evidence
    assert a.design is design and [p.name for p in a.points] == names
    check = a.verdict.check("tsai_wu")
    assert check.value == 1.8 and check.location["point"] == "standard_day"


def test_each_point_is_judged_against_the_designs_requirements(monkeypatch):
    """A design requiring a Tsai-Wu factor of 2.5 (the default is 1.5): a point at 2.0 fails."""
    import flexshaft.verdict.assess as module

    evidence = Evidence(operating_speed=500.0, safety_factor=2.0, safety_factor_location={"station": 1.0})
    monkeypatch.setattr(module, "gather_evidence", lambda analyses: evidence)
    strict = Requirements(min_safety_factor=2.5)
    judged = module._judged("hot_day", NS(design=NS(requirements=strict)))
    check = judged.verdict.check("tsai_wu")
    assert check.limit == 2.5 and check.status == "fail"


# ------------------------------------------------------------------------ the design at a point


def _loaded_design(speed: float):
    """The tuned design at ``speed`` [rad/s] (given in rad/s) with a point load (force and moment)
    and a line load on the shaft."""
    data = tuned_design().model_dump()
    data["operating"].update(speed_rpm=None, speed=speed)
    data["loads"]["point"] = [{"name": "p", "on": "shaft", "x": 2.0, "force": (0.0, -10.0, 0.0), "moment": (0, 0, 5.0)}]
    data["loads"]["line"] = [
        {"name": "l", "on": "shaft", "x_start": 1.0, "x_end": 3.0, "force_per_length": (0.0, -2.0, 1.0)}
    ]
    data["envelope"] = None
    return design_from_dict(data)


def test_a_points_speed_and_load_scale_reach_every_load_and_the_geared_main_rotor():
    """A design at 500 rad/s (4774.6 rev/min, given in rad/s), a point at 5000 rev/min with loads
    × 2.5: the main rotor scales by 5000/(500 × 30/π), every force, moment and line load and the
    load factor (-3.5 g in tuned.toml) by 2.5."""
    from flexshaft.design.envelope import EnvelopePoint
    from flexshaft.design.points import design_at_point

    design = _loaded_design(500.0)
    point = EnvelopePoint(name="fast", speed_rpm=5000.0, load_scale=2.5)
    at = design_at_point(design, point, NS(thermal={}, materials={}))
    ratio = 5000.0 / (500.0 * 30.0 / math.pi)
    base = design.operating.main_rotor_speed_rpm
    assert at.operating.main_rotor_speed_rpm == pytest.approx(base * ratio, rel=1e-14)
    (load,) = at.loads.point
    assert load.force == (0.0, -25.0, 0.0) and load.moment == (0.0, 0.0, 12.5)
    assert at.loads.line[0].force_per_length == (0.0, -5.0, 2.5)
    assert design.loads.load_factor == (0.0, -3.5, 0.0) and at.loads.load_factor == (0.0, -8.75, 0.0)


def test_the_main_rotors_excitation_frequencies_are_in_hertz():
    """The tuned design's main rotor, 289 rev/min and 4 blades (tuned.toml): 1/rev = 289/60 Hz,
    4/rev = 4 × 289/60 Hz."""
    operating = tuned_design().operating
    assert (operating.main_rotor_speed_rpm, operating.main_rotor_blades) == (289.0, 4)
    assert operating.main_rotor_frequencies() == {"1/rev": 289.0 / 60.0, "4/rev": 4 * 289.0 / 60.0}


# ------------------------------------------------------------------------ the model's refusals


def _shaft_and_design(bearing) -> tuple[NS, NS]:
    """A steel tube 0.1/0.09 m, 3 m long on 12 elements (h = 0.25 m), with ``bearing``."""
    shaft = NS(youngs_modulus=2.0e11, outer_diameter=0.1, inner_diameter=0.09)
    design = NS(shaft=NS(x_start=0.0, x_end=3.0), mesh=NS(shaft_elements=12), bearings=[bearing])
    return shaft, design


def test_the_element_stiffness_is_the_tubes_bending_and_axial_stiffness():
    """E I/h³, E I/h and E A/h with I = π(D⁴ − d⁴)/64 and A = π(D² − d²)/4, written out."""
    from flexshaft.assembly.checks import element_stiffness

    shaft, design = _shaft_and_design(None)
    E, h = 2.0e11, 0.25
    inertia = math.pi * (0.1**4 - 0.09**4) / 64.0
    area = math.pi * (0.1**2 - 0.09**2) / 4.0
    k = element_stiffness(design, shaft)
    assert k["v"] == k["w"] == pytest.approx(E * inertia / h**3, rel=1e-14)
    assert k["beta"] == pytest.approx(E * inertia / h, rel=1e-14)
    assert k["u"] == pytest.approx(E * area / h, rel=1e-14)


def test_an_actuators_control_stiffness_counts_its_current_gain():
    """K_p = 1e10 A/m with k_i = 1e6 N/A is a support of k_i K_p = 1e16 N/m, above 1e8 × the
    element's E I/h³ (1e8 × 2.16e7 N/m for this tube); K_p alone would pass."""
    from flexshaft.assembly.checks import RIGID_RATIO, check_bearing_stiffness, element_stiffness

    bearing = NS(kind="active", kp=1.0e10, ki=1.0e6, ks=None, controller=None)
    shaft, design = _shaft_and_design(bearing)
    assert 1.0e10 < RIGID_RATIO * element_stiffness(design, shaft)["v"] < 1.0e16
    with pytest.raises(DesignError, match=r"bearings\[0\]\.kp"):
        check_bearing_stiffness(design, shaft)


# ------------------------------------------------------------------------ thermal study


def test_the_temperature_margin_is_allowable_minus_peak():
    """Allowable 373.15 K, self-heating peak 350 K: margin +23.15 K."""
    from flexshaft.thermal.study import ThermalResults

    r = ThermalResults(NS(allowable_temperature=373.15), "rotating", {}, {}, NS(max_temperature=350.0), None)
    assert r.temperature_margin == pytest.approx(23.15, rel=1e-12)


@pytest.mark.parametrize("requested", ["thesis", "rotating"])
def test_the_thermal_results_use_the_requested_loss_model(monkeypatch, requested):
    """A comparison asks for each loss model in turn: the self-heating runs with the one asked
    for, whatever the design's ``[analysis] internal_damping`` (the self-heating itself is
    replaced by a stand-in that records its loss model)."""
    import flexshaft.thermal.study as module

    monkeypatch.setattr(module, "self_heating", lambda model, options, loss_model: NS(loss_model=loss_model))
    design = tuned_design()
    r = module.thermal_results(design, None, loss_model=requested, self_heat=True, detail=False)
    assert r.loss_model == requested and r.self_heating.loss_model == requested
    own = module.thermal_results(design, None, self_heat=True, detail=False)
    assert own.loss_model == design.analysis.internal_damping


# ------------------------------------------------------------------------ Monte-Carlo


def test_each_monte_carlo_sample_draws_its_own_stream(monkeypatch):
    """Sample k of seed s draws its angles from ``default_rng([s, k])`` (module docstring of
    flexshaft.montecarlo.steady; a fixed eccentricity draws nothing before them): samples 0 and
    1 differ, each equals numpy's stream."""
    import flexshaft.montecarlo.steady as module
    from flexshaft.montecarlo.samples import EccentricityDistribution

    monkeypatch.setattr(module, "_unit_responses", lambda *args: NS(n_bays=3))
    monkeypatch.setattr(module, "sample_outputs", lambda *args, **kwargs: {})
    sampler = module.MonteCarloSampler(7, EccentricityDistribution("fixed", 1e-5), placement="mid_bay")
    design = NS(model_dump_json=lambda: "{}")
    angles = []
    for k in (0, 1):
        out = sampler(NS(axes={"sample": k}, model=None, design=design))
        angles.append([out[f"angle_bay{b}"] for b in (1, 2, 3)])
        expected = np.random.default_rng([7, k]).uniform(0.0, 2 * np.pi, 3)
        assert angles[-1] == expected.tolist()
    assert angles[0] != angles[1]


def test_a_balance_grade_is_converted_at_the_highest_operating_speed(monkeypatch):
    """G 6.3 mm/s with speed_range [0.95, 1.05]: e = 6.3e-3/(1.05 Ω) [m] (ISO 21940-11 §5.3, the
    maximum service speed); the sweep itself is not run (its study is captured)."""
    import flexshaft.montecarlo.steady as module
    from flexshaft.design import with_overrides

    design = with_overrides(
        tuned_design(),
        {"operating.speed_range": [0.95, 1.05], "mesh.shaft_elements": 4, "mesh.boom_elements": 2, "envelope": None},
    )
    captured = {}

    def fake_sweep(study, *args, **kwargs):
        captured["sampler"] = study.evaluate
        return NS(attrs={})

    monkeypatch.setattr(module, "run_sweep", fake_sweep)
    module.run_montecarlo(design, 2, grade_mm_s=6.3)
    scale = captured["sampler"].distribution.scale
    assert scale == pytest.approx(6.3e-3 / (1.05 * design.operating.speed_rad_s), rel=1e-14)


def test_the_exceedance_standard_error_is_the_binomial_one():
    """3 exceedances in 200 samples: p = 0.015, standard error √(p(1 − p)/N) with N = 200."""
    from flexshaft.montecarlo.confidence import Exceedance

    assert Exceedance(3, 200).standard_error == pytest.approx(math.sqrt(0.015 * 0.985 / 200), rel=1e-14)


@pytest.mark.parametrize(("given", "refused"), [(-70.0, True), (130.0, True), (110.0, False)])
def test_a_given_material_temperature_is_checked_against_both_ends_of_the_table(given, refused):
    """The tuned lamina's temperature table spans -60 to 120 °C (tuned.toml): a point given
    -70 °C or 130 °C is refused naming its field, 110 °C is accepted."""
    from flexshaft.design import with_overrides

    design = tuned_design()
    table = design.materials["t700_adiprene"].temperature_table
    assert (table.temperature_c[0], table.temperature_c[-1]) == (-60.0, 120.0)
    override = {"envelope.points[0].material_temperature": "given", "envelope.points[0].material_temperature_c": given}
    if refused:
        with pytest.raises(DesignError, match=r"envelope\.points\[0\]\.material_temperature_c: puts the shaft at"):
            with_overrides(design, override)
    else:
        assert with_overrides(design, override).envelope.points[0].material_temperature_c == given
