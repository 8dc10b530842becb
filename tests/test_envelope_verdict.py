"""The verdict over the operating envelope (flexshaft.verdict.envelope, assess) and designs with a
known governing failure.

* Combining the points, on hand-made evidence: a check fails when it fails at some point, its
  value and location are the worst point's (the location names the point), its findings are
  every point's; not evaluated only where no point could evaluate it; the governing point is
  the point of the tightest check.
* A design without an ``[envelope]`` is judged at its own operating point (as before the
  envelope existed): one point, no point in the locations, the point's verdict unchanged.
* Designs whose governing failure is known by construction, each flagged by the right check at
  the right point: fibre kinking (a fibre misalignment of 6° lowers the Budiansky-Fleck kink
  band G_LT/(1 + φ/γ_y): the Tsai-Wu factor that passed with the file's X_c fails with it, on
  the hot day where G_LT is lowest at full power), a torsional resonance (a lighter tail rotor,
  12 kg m², puts the first torsional mode at 9.46 Hz inside the main rotor's 2/rev band
  9.15-10.1 Hz: margin 0), a hot-soak start (an allowable of 85 °C below the 88.8 °C parked
  boom: only the hot-soak point fails the temperature) and a poor magnetic-bearing loop
  (K_d 250 N s/m: a sensitivity peak above ISO 14839-3's zone B).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.analyses.shaft_strength import shaft_safety_factor, static_load_parts
from flexshaft.design import DesignError, baseline_design, design_from_dict, tuned_design, with_overrides
from flexshaft.resolution import REPORT, SCREENING
from flexshaft.verdict.assess import assess
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.envelope import PointAssessment, envelope_verdict, governing_point
from flexshaft.verdict.evidence import Evidence, ModeDamping

OP = 500.0  # rad/s


def _point(name: str, **values) -> PointAssessment:
    ev = Evidence(
        operating_speed=OP, stability_max_speed=1.5 * OP, modes_at_operating=(ModeDamping("1", 300.0, 0.2),), **values
    )
    return PointAssessment(name=name, analyses=None, evidence=ev, verdict=evaluate(ev))


def test_each_check_takes_its_worst_point_with_the_points_name():
    """Tsai-Wu 3.0, 1.2 and 2.0 at three points: fails (1.2 < 1.5) at "hot"; buckling passes at
    two points and is not evaluated at the third; the temperature is not evaluated anywhere."""
    points = [
        _point("cold", safety_factor=3.0, safety_factor_location={"station": 1.0}, buckling_safety_factor=5.0),
        _point("hot", safety_factor=1.2, safety_factor_location={"station": 2.0}, buckling_safety_factor=2.5),
        _point("standard", safety_factor=2.0, safety_factor_location={"station": 3.0}),
    ]
    verdict = envelope_verdict(points)
    tsai = verdict.check("tsai_wu")
    assert tsai.status == "fail" and tsai.value == 1.2 and tsai.margin == pytest.approx(-0.3)
    assert tsai.location == {"point": "hot", "station": 2.0}
    assert sorted((f.location["point"], f.value) for f in tsai.findings) == [
        ("cold", 3.0),
        ("hot", 1.2),
        ("standard", 2.0),
    ]
    buckling = verdict.check("buckling")
    assert buckling.status == "pass" and buckling.value == 2.5 and buckling.location["point"] == "hot"
    assert "not evaluated at standard" in buckling.note
    temperature = verdict.check("temperature")
    assert temperature.status == "not evaluated" and "at every point" in temperature.note
    assert [c.key for c in verdict.checks] == [c.key for c in points[0].verdict.checks]
    assert governing_point(points) == "hot"


def test_a_check_failing_at_one_point_fails_even_where_another_has_a_smaller_margin():
    """The worst point is a failing one first: a runaway fails at "hot" although its margin is
    positive, while "cold" passes with a smaller one."""
    cold = _point("cold", max_temperature=372.0, allowable_temperature=373.15)
    hot = _point("hot", max_temperature=300.0, allowable_temperature=373.15, thermal_runaway=True)
    check = envelope_verdict([cold, hot]).check("temperature")
    assert check.status == "fail" and check.location["point"] == "hot"


@pytest.fixture(scope="module")
def tuned_run(embedded_comparison):
    """The embedded tuned design over its four envelope points, as ``flexshaft run`` judges it
    (:func:`~flexshaft.comparison.compare`'s first run, ``assess(tuned_design(), REPORT)``: computed
    once per session, tests/conftest.py; read only). What these tests check (the points, their
    verdicts and the governing point, the report's and the terminal's envelope) holds at any
    resolution; this one the session computes anyway (CPU budget, issue 23)."""
    run = embedded_comparison.runs[0]
    assert run.design == tuned_design() and run.resolution == REPORT
    return run


@pytest.fixture(scope="module")
def nominal_screening(tuned_nominal_screening):
    """The tuned design without its ``[envelope]``, at the screening resolution (shared with
    tests/test_verdict.py for the session, tests/conftest.py: read only)."""
    return tuned_nominal_screening


def test_a_design_without_an_envelope_is_judged_at_its_own_point(tuned_run, nominal_screening):
    a = nominal_screening
    design = a.design
    assert design.envelope is None and [p.name for p in a.points] == ["operating point"]
    assert a.governing_point == "operating point" and a.conditions is None
    assert a.verdict == a.points[0].verdict
    assert all("point" not in c.location for c in a.verdict.checks)
    # the envelope's points are the design at each point: the one above is none of them
    assert [p.name for p in tuned_run.points] == ["cold_day", "standard_day", "hot_day", "hot_soak_start"]


def test_the_tuned_design_passes_at_every_point_and_says_where_each_check_governs(tuned_run):
    a = tuned_run
    assert a.verdict.passed and not a.verdict.not_evaluated, a.verdict.summary
    names = {p.name for p in a.points}
    for check in a.verdict.checks:
        if check.status != "not evaluated" and check.value is not None:
            assert check.location["point"] in names
            evaluated = [p.verdict.check(check.key) for p in a.points]
            same = [c for c in evaluated if c.margin is not None]
            if same:  # the value is the worst point's
                worst = min(same, key=lambda c: c.margin / abs(c.limit) if c.limit else c.margin)
                assert check.margin == pytest.approx(worst.margin)
    assert a.governing_point in names and a.point(a.governing_point).analyses is not None


def test_the_report_json_and_terminal_say_each_points_verdict_and_which_governs(tuned_run, nominal_screening):
    """results.json's ``envelope`` holds each point's conditions and own verdict, the report's
    table one row per point, the terminal's line the governing point: all read the same
    assessment, whose governing point has the tightest check of any point."""
    from flexshaft.report.results_json import results_json
    from flexshaft.verdict.envelope import tightest_check
    from flexshaft.verdict.envelope_text import envelope_line, envelope_rows
    from flexshaft.verdict.result import normalised_margin

    a = tuned_run
    data = results_json(a)["envelope"]
    assert data["governing_point"] == a.governing_point
    assert [p["name"] for p in data["points"]] == [p.name for p in a.points]
    for entry, point in zip(data["points"], a.points):
        assert entry["material_temperature_c"] == pytest.approx(point.analyses.conditions.material_temperature_c)
        assert entry["passed"] == point.verdict.passed
        for c in point.verdict.checks:
            assert entry["checks"][c.key]["status"] == c.status and entry["checks"][c.key]["value"] == c.value
    # the governing point's tightest check is the tightest of all points' (relative margin)
    tightest = {p.name: normalised_margin(tightest_check(p.verdict)) for p in a.points}
    assert tightest[a.governing_point] == min(tightest.values())
    assert data["points"][[p.name for p in a.points].index(a.governing_point)]["tightest_check"] == (
        tightest_check(a.point(a.governing_point).verdict).key
    )
    rows = envelope_rows(a)
    assert [r[0] for r in rows if r[0].endswith("(governs)")] == [f"{a.governing_point} (governs)"]
    assert f"governed by {a.governing_point} (" in envelope_line(a)
    nominal = nominal_screening
    assert results_json(nominal)["envelope"] is None and envelope_rows(nominal) == [] and envelope_line(nominal) == ""


#: A coarse mesh for the designs with a known failure (CPU budget, issue 23): the values their
#: tests check move by less than 2e-5 of themselves from the tuned design's own mesh (36 shaft,
#: 24 boom elements) at the points they use (measured: the Tsai-Wu factors of the misaligned ply,
#: 3e-4 at the cold day, which no test uses; the torsional frequencies T1, 4e-8; the shaft's
#: temperatures, 1e-6; the loop's sensitivity peak stays 6.45).
COARSE = {"mesh.shaft_elements": 12, "mesh.boom_elements": 8}


def _at_points(design, *names):
    """``design`` on :data:`COARSE` over the named points of its envelope only (CPU budget,
    issue 23: each point is a whole assessment)."""
    data = with_overrides(design, COARSE).model_dump()
    data["envelope"]["points"] = [p for p in data["envelope"]["points"] if p["name"] in names]
    assert [p["name"] for p in data["envelope"]["points"]] == list(names)
    return design_from_dict(data)


def _failed(design, key):
    a = assess(design, SCREENING)
    assert [c.key for c in a.verdict.failed] == [key], a.verdict.summary
    return a, a.verdict.check(key)


def test_fibre_kinking_governs_a_misaligned_soft_matrix_ply():
    """φ = 6°: γ_y = S/G_LT, so the kink band G_LT/(1 + φ G_LT/S) falls to ~38 MPa on the hot
    day (G_LT 55 MPa at 44 °C); with the file's X_c (2000 MPa) the same point passes by far. At
    the hot day and the hot-soak start: the soak's shaft is the hottest (88.8 °C, the lowest
    G_LT) but carries less power, and the kink band must not move the failure there (its Tsai-Wu
    factor 2.15, measured; the cold and the standard day pass with 3.15 and 1.74 and are left
    out, CPU budget, issue 23)."""
    design = _at_points(
        with_overrides(tuned_design(), {"materials.t700_adiprene.fibre_misalignment_deg": 6.0}),
        "hot_day",
        "hot_soak_start",
    )
    a, check = _failed(design, "tsai_wu")
    assert check.location["point"] == "hot_day" and "kink-band" in check.note
    hot = a.point("hot_day").analyses
    strength = hot.compressive_strength
    assert strength.governs == "kink_band"
    G, phi, S = strength.shear_modulus, math.radians(6.0), hot.design.materials["t700_adiprene"].S
    assert strength.kink_band == pytest.approx(G / (1 + phi * G / S), rel=1e-12)
    parts = static_load_parts(hot.model)
    datasheet = shaft_safety_factor(
        hot.model, parts, hot.imbalance_at_speed[:, 0], temperature=hot.residual_temperature
    )
    assert datasheet.safety_factor > 10 * check.value


def test_a_torsional_resonance_is_flagged_by_the_torsional_separation():
    """At the standard day alone: T1 barely moves with the point's temperature (9.45 to 9.50 Hz
    at the four points, each inside the band, measured), and what is checked is the torsional
    check at a point, not the envelope's combining (CPU budget, issue 23)."""
    design = _at_points(with_overrides(tuned_design(), {"tail_rotor.polar_inertia": 12.0}), "standard_day")
    _, check = _failed(design, "torsional_separation")
    assert check.value == 0.0 and check.location["mode"] == "T1" and check.location["case"] == "main rotor 2/rev"
    assert 9.15 < check.location["frequency"] / (2 * math.pi) < 10.12


def test_a_hot_soak_start_fails_only_at_the_hot_soak_point():
    """Against the hot day, the hottest of the other points (self-heating equilibrium 44.1 °C;
    the cold and the standard day reach -22.5 °C and 33.2 °C, measured, and are left out: CPU
    budget, issue 23): the parked shaft's 88.8 °C fails the 85 °C allowable, the running one's
    passes."""
    design = _at_points(
        with_overrides(tuned_design(), {"thermal.allowable_temperature_c": 85.0}), "hot_day", "hot_soak_start"
    )
    a, check = _failed(design, "temperature")
    assert check.location["point"] == "hot_soak_start"
    failing = [p.name for p in a.points if p.verdict.check("temperature").status == "fail"]
    assert failing == ["hot_soak_start"]
    assert check.value == pytest.approx(a.point("hot_soak_start").analyses.conditions.material_temperature)


def test_a_poor_loop_is_flagged_by_its_sensitivity_peak():
    """At the cold day alone (CPU budget, issue 23: each point is a whole assessment): the
    loop's sensitivity barely depends on the point (peaks of 6.44 to 6.45 at the four, measured),
    and what is checked here is the check and its Nyquist bound, not the envelope's combining."""
    design = with_overrides(tuned_design(), {"bearings[1].kd": 250.0, "bearings[2].kd": 250.0})
    a = assess(_at_points(design, "cold_day"), SCREENING)
    check = a.verdict.check("loop_sensitivity")
    assert check.status == "fail" and check.value > 4.0 and check.limit == 4.0
    assert check.location["actuator"].startswith("amb_")
    # the peak bounds the phase margin (Nyquist geometry): 2 sin(PM/2) >= 1/|S|max in each loop
    assert a.verdict.check("loop_phase_margin").status == "fail"
    for loop in a.point(check.location["point"]).evidence.loops:
        assert 2 * math.sin(loop.phase_margin / 2) >= (1 - 1e-6) / loop.peak_sensitivity


def test_a_divergent_magnet_fails_the_onset_at_rest_with_its_root():
    """Was: a divergent stability onset crashed the whirl evidence (``m + 1`` on None). amb_1's
    negative stiffness 2e7 N/m against its control stiffness k_i K_p = 1e7 N/m: the net bearing
    stiffness is negative, so the rotor diverges at rest (a real root s > 0). On a coarse mesh
    (12 shaft, 8 boom elements; CPU budget, issue 23): the divergence is the bearing's, s = 2958
    1/s there against 3002 1/s on the design's own mesh (measured)."""
    data = baseline_design().model_dump()
    data["bearings"][1]["ks"] = 2.0e7
    data["envelope"] = None
    data["mesh"] = {"shaft_elements": 12, "boom_elements": 8}
    a = assess(design_from_dict(data), SCREENING)
    onset = a.verdict.check("whirl_onset")
    assert onset.status == "fail" and onset.value == 0.0
    assert onset.location["mode"].startswith("divergence")
    assert a.stability.onset_kind == "divergence" and a.roots.worst_at(0.0).kind == "divergence"


def test_a_design_at_rest_gets_a_verdict_or_a_clean_refusal(monkeypatch):
    """Was: a design at rest crashed the actuator evidence (argmax of an empty spin-up). At rest
    the actuators carry their static offset and force alone; nothing sweeps the criticals or the
    torsional modes. With the tuned envelope, whose hot-soak point (the last) sets a power of
    75 kW, the point's design is refused (a power without speed) naming the point, before any
    point is analysed (errors at the edge: it was refused after the three points before it had
    been analysed, about 1.2 s of CPU)."""
    import flexshaft.verdict.assess as module

    data = with_overrides(tuned_design(), {"operating.speed_rpm": 0.0, "operating.power": 0.0}).model_dump()
    data["envelope"] = None
    a = assess(design_from_dict(data), SCREENING)
    statuses = {c.key: c.status for c in a.verdict.checks}
    assert statuses["actuator_orbit"] == "pass" and statuses["torsional_separation"] == "not evaluated"
    (ev, *_) = a.evidence.actuators
    assert ev.peak_orbit == 0.0 and ev.static_offset > 0.0

    def no_analysis(*args, **kwargs):
        raise AssertionError("a point was analysed before the envelope's designs were checked")

    monkeypatch.setattr(module, "analyse_point", no_analysis)
    at_rest = with_overrides(tuned_design(), {"operating.speed_rpm": 0.0, "operating.power": 0.0})
    assert [p.name for p in at_rest.envelope.points][-1] == "hot_soak_start"
    with pytest.raises(DesignError, match=r"envelope\.points\[3\] \(hot_soak_start\): operating\.power: must be 0"):
        assess(at_rest, SCREENING)


def test_the_log_decrement_counts_the_lateral_vibration_modes_only():
    """Was: the check took the lowest ``resolution.modes`` modes at the operating speed, among them
    the torsional mode T1 (7 Hz) and the real roots of the controllers' states (integrator,
    derivative filter, amplifier: zero frequency, ζ ≈ 1), and missed the worst shaft mode of the
    thesis's tuned design on the realistic magnet (docs/magnetic-bearings.md): a forward mode near
    54.5 Hz with δ ≈ 0.08. Reference: 40 modes at the operating speed, filtered by hand (lateral,
    ζ < 0.99, the lowest ``resolution.modes`` of those, ≥ 10 % of their kinetic energy in the
    shaft), on the same model. On a coarse mesh (12 shaft, 8 boom elements; CPU budget, issue 23):
    the reference holds at any mesh, and the mode is the same (54.54 Hz, δ 0.0818 against 54.52 Hz
    and 0.0818 on the design's own mesh, measured)."""
    import numpy as np

    from flexshaft.analyses.modal import modes
    from flexshaft.thesis.designs import thesis_tuned_design

    keys = {"ks": 8.47e5, "ki": 177.0, "kp": 7610.0, "kd": 3.16, "integral_gain": 4.8e4}
    keys.update(derivative_cutoff=500.0, amplifier_bandwidth=1000.0)
    design = with_overrides(thesis_tuned_design(), {f"bearings[{i}].{k}": v for i in (1, 2) for k, v in keys.items()})
    a = assess(
        with_overrides(design, {"envelope": None, "mesh.shaft_elements": 12, "mesh.boom_elements": 8}), SCREENING
    )
    check = a.verdict.check("whirl_damping")
    m = modes(a.model, a.model.speed, 40)
    s = m.eigenvalues
    zeta = -s.real / np.abs(s)
    assert "torsional" in m.kind[:12]  # it would take a whirl mode's place
    # the controllers' real roots (ζ ≈ 1) would too; the mode lists now put them after every
    # vibration mode (analyses.eigen.lowest_modes), and the check must not depend on that
    assert not np.any(zeta[: SCREENING.modes] > 0.995)
    lateral = np.flatnonzero((m.kind == "lateral") & (zeta < 0.99))[: SCREENING.modes]
    shaft = [k for k in lateral if m.shaft_fractions[k] >= 0.1]
    worst = min(shaft, key=lambda k: m.log_decrements[k])
    assert check.status == "fail"
    # (the modal solver's basis grows with the modes asked for: 40 modes move δ by 3e-4)
    assert check.value == pytest.approx(m.log_decrements[worst], rel=1e-3)
    assert check.location["frequency"] == pytest.approx(abs(s[worst].imag), rel=1e-4)
    assert 54.0 < abs(s[worst].imag) / (2 * np.pi) < 55.0 and m.whirl[worst] == "forward"


def test_the_governing_point_compares_margins_relative_to_their_limits():
    """Checks of different units compare by their normalised margins (the margins figure's
    measure): Tsai-Wu 1.55 against 1.5 at "a" (margin 0.05, a thirtieth of the limit) and 372 K
    against 373.15 K at "b" (margin 1.15 K, 1.15/85 of the allowable's rise above 15 °C): "b"
    governs, although its margin's number is larger (kelvin are not safety factors)."""
    a = _point("a", safety_factor=1.55, safety_factor_location={"station": 1.0})
    b = _point("b", max_temperature=372.0, allowable_temperature=373.15)
    assert governing_point([a, b]) == "b" and governing_point([b, a]) == "b"
