"""Thesis reproduction (docs/thesis-reproduction.md): each finding the thesis states in words
against flexshaft's number on the embedded designs, at reduced resolution.

Every row of the doc's table is computed here by one function of this module; the tests assert
the rows marked "reproduced" within the tolerance the table states, and, for the rows that are
not reproduced, the mechanism the doc gives for the disagreement. Print the table from the same
computations with::

    OMP_NUM_THREADS=1 .venv/bin/python tests/test_reproduction.py

The inputs are the embedded ``baseline`` (thesis Table 3.1: K_p 1e7 N/m, K_d 0) and ``tuned``
as the thesis tuned it (:func:`flexshaft.thesis.designs.thesis_tuned_design`: (55/-55/0/0)s,
3 mm, K_p 5e5, K_d 560; the packaged ``tuned`` was re-tuned for the verdict's envelope, and only
its verdict row is of the packaged file). Unless a row says otherwise it uses the designs' internal-damping model
("rotating"); the thesis's own numbers came from its fixed-frame complex stiffness
(``internal_damping = "thesis"``), and rows whose number that choice changes show both.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
import pytest

from flexshaft.analyses import imbalance_response, modes, static_response
from flexshaft.analyses.response import orbit_amplitude
from flexshaft.analyses.spinup import actuator_receptance, spinup_curves, spinup_map
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load, imbalance_loads, torque_load
from flexshaft.design import baseline_design, embedded_text, tuned_design, with_overrides
from flexshaft.thesis.designs import THESIS_TUNED_CHANGES, thesis_tuned_design

RPM = 60.0 / (2.0 * math.pi)
THESIS_DAMPING = {"analysis.internal_damping": "thesis"}


def chapter3_studies():
    """The thesis chapter-3 study functions (ply_angle_study, two_angle_study, ...)."""
    from flexshaft import thesis

    return thesis


# ------------------------------------------------------------------------------------------------
# Helpers


def actuator_paths(design) -> list[int]:
    """Indices of the design's active bearings (the same gains go to each)."""
    return [i for i, b in enumerate(design.bearings) if b.kind == "active"]


def with_gains(design, kp: float, kd: float):
    """``design`` with the PD gains (kp [N/m], kd [N s/m]) on every active bearing."""
    overrides = {}
    for i in actuator_paths(design):
        overrides[f"bearings[{i}].kp"] = float(kp)
        overrides[f"bearings[{i}].kd"] = float(kd)
    return with_overrides(design, overrides)


def spin_speeds(model, n_speeds: int) -> np.ndarray:
    """The coarse spin-up grid [rad/s]: ``n_speeds`` speeds over 2-100 % of the operating speed."""
    return np.linspace(0.02, 1.0, n_speeds) * model.speed


_RECEPTANCES: dict = {}


def coarse_receptance(design, n_speeds: int):
    """(model, actuator receptance on :func:`spin_speeds`) of ``design``: independent of the gains,
    computed once for every gain pair and row that scans the same driveline (CPU budget, issue 23)."""
    key = (design.model_dump_json(), n_speeds)
    if key not in _RECEPTANCES:
        model = build_model(design)
        _RECEPTANCES[key] = model, actuator_receptance(model, spin_speeds(model, n_speeds))
    return _RECEPTANCES[key]


def spinup_peak(
    model, kp: float, kd: float, n_speeds: int = 400, rounds: int = 3, receptance=None
) -> tuple[float, float]:
    """Peak shaft orbit [m] over 2-100 % of the operating speed and its speed [rad/s].

    The lightly damped peaks are far narrower than the coarse grid: the three largest local
    maxima are zoomed into (41 points between their neighbours, ``rounds`` times), so the
    value converges to the true peak (within 0.1 % after three rounds). ``receptance``: the
    model's actuator receptance on :func:`spin_speeds` (``n_speeds``) when already computed.
    """
    speeds = spin_speeds(model, n_speeds)
    if receptance is None:
        receptance = actuator_receptance(model, speeds)
    curve = spinup_curves(receptance, (kp, kd)).shaft_peak
    inner = np.flatnonzero((curve[1:-1] >= curve[:-2]) & (curve[1:-1] >= curve[2:])) + 1
    best = (float(curve.max()), float(speeds[np.argmax(curve)]))
    for k in inner[np.argsort(curve[inner])[::-1][:3]]:
        low, high = speeds[k - 1], speeds[k + 1]
        for _ in range(rounds):
            fine = np.linspace(low, high, 41)
            values = spinup_curves(actuator_receptance(model, fine), (kp, kd)).shaft_peak
            j = int(np.argmax(values))
            low, high = fine[max(j - 1, 0)], fine[min(j + 1, fine.size - 1)]
        if values[j] > best[0]:
            best = (float(values[j]), float(fine[j]))
    return best


def static_actuator_offsets(design, kps) -> np.ndarray:
    """Static relative displacement [m] at each actuator under the static loads, (n_kp, n_act).

    One static solve of the driveline without actuator stiffness for the loads and for unit
    actuator forces; each K_p then adds K_p BᵀB, a rank-2-per-actuator update solved exactly
    (Woodbury): d = (I + K_p S)⁻¹ g with S = B K₀⁻¹ Bᵀ, g = B K₀⁻¹ Q.
    """
    model = build_model(with_gains(design, 0.0, 0.0))
    B = np.vstack([a.lateral_rows.toarray() for a in model.actuators])  # (2 n_act, ndof)
    loads = np.column_stack([external_static_load(model) + torque_load(model), B.T])
    q = static_response(model, loads)
    g, S = B @ q[:, 0], B @ q[:, 1:]
    out = []
    for kp in kps:
        d = np.linalg.solve(np.eye(B.shape[0]) + kp * S, g)
        out.append(np.hypot(d[0::2], d[1::2]))
    return np.array(out)


@dataclass(frozen=True)
class Tuning:
    """The thesis's gain tuning on the spin-up map: smallest peak with the actuator within its gap."""

    kp: float  # N/m
    kd: float  # N s/m
    peak: float  # m, refined
    speed: float  # rad/s of the peak
    excursion: float  # m, static offset + spin-up orbit at the worst actuator


TUNING_KP = np.logspace(5.0, 7.5, 26)
TUNING_KD = np.concatenate([[0.0], np.logspace(1.5, 4.0, 21)])


def tune_gains(design, gap: float, candidates: int = 4) -> Tuning:
    """Gains of the smallest spin-up peak with static offset + orbit within ``gap`` [m].

    The map's peaks are sampled at 400 speeds; the ``candidates`` best admissible pairs are
    refined (:func:`spinup_peak`) and the smallest refined peak wins.
    """
    model, receptance = coarse_receptance(design, 400)
    smap = spinup_map(model, TUNING_KP, TUNING_KD, receptance=receptance)
    excursion = (smap.actuator_displacement_peak + static_actuator_offsets(design, TUNING_KP)[:, None, :]).max(axis=-1)
    admissible = excursion <= gap
    order = np.argsort(np.where(admissible, smap.shaft_peak, np.inf), axis=None)[:candidates]
    best = None
    for flat in order:
        i, j = np.unravel_index(int(flat), admissible.shape)
        if not admissible[i, j]:
            continue
        peak, speed = spinup_peak(
            model, TUNING_KP[i], TUNING_KD[j], n_speeds=300, rounds=2, receptance=coarse_receptance(design, 300)[1]
        )
        if best is None or peak < best.peak:
            best = Tuning(float(TUNING_KP[i]), float(TUNING_KD[j]), peak, speed, float(excursion[i, j]))
    assert best is not None, f"no gain pair keeps the actuator within {gap} m"
    return best


def lateral_shaft_frequencies(model, n_modes: int = 16) -> np.ndarray:
    """Natural frequencies at rest [Hz] of the lateral modes with most kinetic energy in the shaft."""
    m = modes(model, 0.0, n_modes)
    keep = (np.asarray(m.kind) == "lateral") & (np.asarray(m.shaft_fractions) > 0.5)
    return np.asarray(m.frequencies)[keep]


# ------------------------------------------------------------------------------------------------
# The computations behind each row (cached: the tests and the printed table share them)


@functools.cache
def strength_row() -> dict:
    """Tsai-Wu safety factor of both embedded designs (static loads + imbalance at 4800 rpm)."""
    from flexshaft.analyses.shaft_strength import shaft_safety_factor

    out = {}
    for name, design in (("baseline", baseline_design()), ("tuned", thesis_tuned_design())):
        model = build_model(design)
        q_static = static_response(model, external_static_load(model) + torque_load(model))
        q_imb = imbalance_response(model, [model.speed], imbalance_loads(model))[:, :, 0]
        out[name] = min(
            (shaft_safety_factor(model, q_static, q_imb[:, c]) for c in range(q_imb.shape[1])),
            key=lambda r: r.safety_factor,
        )
    return out


@functools.cache
def ply_angle_row():
    return chapter3_studies().ply_angle_study(np.arange(5.0, 90.0, 2.5), design=baseline_design())


@functools.cache
def two_angle_row():
    angles = np.array([0.0, 15.0, 30.0, 45.0, 55.0, 60.0, 75.0, 90.0])
    return chapter3_studies().two_angle_study(angles, angles, design=baseline_design())


WALLS = np.array([1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0]) * 1e-3


@functools.cache
def wall_frequency_row() -> np.ndarray:
    """First four lateral shaft-mode frequencies at rest [Hz] for each wall of WALLS, Table 3.1."""
    design = baseline_design()
    return np.array(
        [
            lateral_shaft_frequencies(build_model(with_overrides(design, {"shaft.wall_thickness": float(w)})))[:4]
            for w in WALLS
        ]
    )


@functools.cache
def wall_strength_row():
    return chapter3_studies().wall_thickness_study(WALLS, design=baseline_design())


GAIN_KP = np.logspace(5.0, 8.0, 25)


@functools.cache
def gain_row():
    return chapter3_studies().proportional_gain_study(GAIN_KP, design=baseline_design())


@functools.cache
def gain_map_row(damping: str = "thesis"):
    """Spin-up peaks over (K_p, K_d) on the Table 3.1 driveline (thesis figures 3.11, 3.12)."""
    model, receptance = coarse_receptance(
        with_overrides(baseline_design(), {"analysis.internal_damping": damping}), 400
    )
    kp = np.logspace(5.0, 8.0, 13)
    kd = np.concatenate([[0.0], np.logspace(1.0, 4.5, 15)])
    return spinup_map(model, kp, kd, receptance=receptance)


@functools.cache
def table31_peak(damping: str) -> tuple[float, float]:
    """Refined spin-up peak [m] and speed [rad/s] at the Table 3.1 gains (1e7 N/m, 0)."""
    model, receptance = coarse_receptance(
        with_overrides(baseline_design(), {"analysis.internal_damping": damping}), 400
    )
    return spinup_peak(model, 1e7, 0.0, receptance=receptance)


@functools.cache
def tuning_row(damping: str, gap: float) -> Tuning:
    return tune_gains(with_overrides(baseline_design(), {"analysis.internal_damping": damping}), gap)


@functools.cache
def surfaces_row(damping: str = "thesis") -> dict:
    """Thesis figures 3.13 (K_p 2e6) and 3.14 (K_p 3e5), both K_d 1170 N s/m."""
    model, rec = coarse_receptance(with_overrides(baseline_design(), {"analysis.internal_damping": damping}), 400)
    speeds = spin_speeds(model, 400)
    high, low = (spinup_curves(rec, (kp, 1170.0)) for kp in (2e6, 3e5))
    k = int(np.argmax(high.shaft_peak))
    band = np.abs(speeds / speeds[k] - 1.0) <= 0.1
    return {
        "peak_high": float(high.shaft_peak[k]),
        "speed": float(speeds[k]),
        "station": float(rec.shaft_x[np.argmax(high.shaft_orbit[:, k])]),
        "median_high": float(np.median(high.shaft_peak)),
        "band_low": float(low.shaft_peak[band].max()),
        "peak_low": float(low.shaft_peak.max()),
    }


BUCKLING_WALLS = np.array([0.75, 1.0, 1.25]) * 1e-3


@functools.cache
def buckling_row():
    return chapter3_studies().buckling_study(BUCKLING_WALLS, design=baseline_design())


@functools.cache
def thermal_row() -> dict:
    from flexshaft.thermal.study import thermal_summary

    design = thesis_tuned_design()
    model = build_model(design)
    return thermal_summary(design, model)


@functools.cache
def whirl_row(method: str) -> dict:
    """Whirl onset [rad/s] (None: stable to 1.5 x the operating speed) of the thesis's three shafts
    on the Table 3.1 driveline (thesis figures 4.2-4.4)."""
    from flexshaft.thesis.whirl import compare_shafts

    design = baseline_design()
    speeds = np.linspace(0.0, 1.5 * design.operating.speed_rad_s, 31)
    return {label: r.onset_speed for label, r in compare_shafts(design, speeds, method, n_modes=8).items()}


@functools.cache
def verdict_row(name: str):
    """The verdict of ``flexshaft run`` on an embedded design: assessed at the ``VERDICT``
    resolution, the report's grids with only what the checks read (the same check values and
    statuses as ``flexshaft run``, measured bitwise on the baseline, at three quarters of its
    CPU; CPU budget, issue 23)."""
    from flexshaft.resolution import VERDICT
    from flexshaft.verdict.assess import assess

    return assess(baseline_design() if name == "baseline" else tuned_design(), VERDICT)


def shaft_mode_log_decrements(results) -> dict[str, float]:
    """Log decrement at the operating speed of the lateral modes with shaft participation (the
    whirl-damping check's modes: lateral only, at least 10 % of their kinetic energy in the shaft;
    boom-only ones excluded by their label)."""
    return {m.label: m.log_decrement for m in results.evidence.modes_at_operating if "boom)" not in m.label}


# ------------------------------------------------------------------------------------------------
# Tests: rows marked "reproduced" within the stated tolerance


def test_embedded_designs_differ_only_in_the_tuned_actuators() -> None:
    """The thesis's tuned design is Table 3.1 with tuned actuators (and what the thesis did not
    model); the packaged tuned design differs from it in the keys re-tuned for the envelope."""
    packaged = tuned_design().model_dump()
    thesis = thesis_tuned_design().model_dump()
    assert packaged["shaft"]["layup"] != thesis["shaft"]["layup"]
    for key, value in THESIS_TUNED_CHANGES.items():
        table, _, field = key.partition(".")
        if table == "shaft":
            packaged["shaft"][field] = value
        else:
            index = int(table[table.index("[") + 1 : -1])
            packaged["bearings"][index][field] = value
    for data in (packaged, thesis):
        data.pop("name"), data.pop("envelope")
        data["shaft"].pop("ply_angles_deg", None)
    assert packaged == thesis
    base, tuned = baseline_design(), thesis_tuned_design()
    # and in what the thesis did not model: the tail rotor on the shaft's twist, the speed range
    changes = {
        "name": tuned.name,
        "tail_rotor": tuned.tail_rotor,
        "operating.speed_range": tuned.operating.speed_range,
        "envelope": tuned.envelope,
    }
    for i in actuator_paths(base):
        bearing = tuned.bearings[i]
        changes.update(
            {f"bearings[{i}].kp": bearing.kp, f"bearings[{i}].kd": bearing.kd, f"bearings[{i}].gap": bearing.gap}
        )
    assert with_overrides(base, changes) == tuned
    # every tuned value is marked in its comment, every calibrated value names its finding
    for line in embedded_text("baseline").splitlines() + embedded_text("tuned").splitlines():
        if "calibrated" in line.split("#", 1)[-1] and "=" in line.split("#", 1)[0]:
            assert "calibrated:" in line, line


def test_natural_frequencies_fall_with_the_wall_at_fixed_outer_diameter() -> None:
    f = wall_frequency_row()
    # thesis §3.2.2 (eq. 3.3): at fixed D_o the mass grows faster than the stiffness
    assert np.all(np.diff(f, axis=0) < 0.0)
    # eq. 3.3 for a pinned span: f ∝ sqrt(EI/μ) = sqrt(E/ρ · (D_o² + D_i²)/16); the first mode is
    # a bay between near-rigid supports (K_p = 1e7), so its ratio matches within 1 % (the bay's
    # supports and the boom are not ideal pins)
    d_o = baseline_design().shaft.outer_diameter
    d_i = d_o - 2.0 * WALLS
    closed_form = math.sqrt((d_o**2 + d_i[-1] ** 2) / (d_o**2 + d_i[0] ** 2))
    assert f[-1, 0] / f[0, 0] == pytest.approx(closed_form, rel=0.01)


def test_proportional_gain_trends_of_figures_3_6_and_3_9() -> None:
    ds = gain_row()
    sf = ds["safety_factor"].values
    disp = ds["actuator_displacement"].values
    kp = ds["kp"].values
    # raising K_p from low values pulls the shaft onto the boom and loads it (left end of fig. 3.6)
    low = kp <= 1e6
    assert np.all(np.diff(sf[low]) < 0.0)
    # a resonance at the operating speed makes both curves non-monotonic (figs 3.6, 3.9): the
    # critical K_p is within a factor 3 of the thesis's 6.5e5 N/m, and 1e7 is non-critical
    critical = kp[np.argmax(disp)]
    assert 6.5e5 / 3.0 <= critical <= 6.5e5 * 3.0
    assert sf.min() < 0.9 * sf[np.argmin(np.abs(kp - 1e7))]
    assert disp.max() > 30.0 * disp[np.argmin(np.abs(kp - 1e7))]


def test_derivative_gain_damps_only_with_a_low_proportional_gain() -> None:
    smap = gain_map_row("thesis")
    kp = smap.kp

    def reduction(value: float) -> float:
        row = smap.shaft_peak[np.argmin(np.abs(kp - value))]
        return float(row[0] / row.min())

    # fig. 3.11: K_p 1e6 -> K_d reduces the peak several-fold; K_p 5e7 -> hardly at all
    assert reduction(1e6) >= 3.0
    assert reduction(5e7) <= 1.5
    # fig. 3.12: the best peak falls as K_p decreases, with an optimum K_d for each K_p
    best = smap.shaft_peak.min(axis=1)
    assert best[np.argmin(np.abs(kp - 5.6e5))] < best[np.argmin(np.abs(kp - 1e7))] / 10.0
    for i in np.flatnonzero(kp <= 6e6):
        assert 0 < int(np.argmin(smap.shaft_peak[i])) < smap.kd.size - 1, kp[i]


def test_table31_spinup_peak_is_the_calibrated_38_mm() -> None:
    peak, speed = table31_peak("thesis")
    # e_c was calibrated to this (thesis damping model): the calibration holds to ±2 %
    assert peak == pytest.approx(0.038, rel=0.02)
    assert 0.5 < speed / baseline_design().operating.speed_rad_s < 1.0


def test_tuned_gains_cut_the_spinup_peak_as_the_thesis_does() -> None:
    tuning = tuning_row("thesis", baseline_design().bearings[1].gap)
    # the thesis's 38 -> 4 mm; the tuned peak depends on the assumed 0.25 mm gap: a factor 2
    assert 0.002 <= tuning.peak <= 0.008
    assert tuning.excursion <= baseline_design().bearings[1].gap
    assert tuning.kd > 0.0 and tuning.kp < 1e7


def test_shipped_tuned_gains_are_the_map_optimum_within_their_gap() -> None:
    tuned = thesis_tuned_design()  # the thesis's gains (the packaged design raised K_d for its loops)
    gap = tuned.bearings[1].gap
    best = tuning_row("rotating", gap)
    kp, kd = tuned.bearings[1].kp, tuned.bearings[1].kd
    model, receptance = coarse_receptance(tuned, 300)
    peak, _ = spinup_peak(model, kp, kd, n_speeds=300, rounds=2, receptance=receptance)
    # the shipped values are the map's optimum rounded to 2 digits: within 5 % of its peak
    assert kp == pytest.approx(best.kp, rel=0.02) and kd == pytest.approx(best.kd, rel=0.02)
    assert peak <= 1.05 * best.peak


def test_a_lower_proportional_gain_damps_the_resonance_of_figure_3_13() -> None:
    s = surfaces_row("thesis")
    # fig. 3.13 (K_p 2e6): one resonance passed in spin-up stands out of the response
    assert s["peak_high"] >= 20.0 * s["median_high"]
    assert s["speed"] < 502.65
    # fig. 3.14 (K_p 3e5): the same resonance is damped, the response much lower
    assert s["band_low"] <= s["peak_high"] / 3.0


def test_torsional_buckling_is_safe_above_1_mm_wall() -> None:
    ds = buckling_row()
    walls, sf = ds["wall_thickness"].values, ds["buckling_safety_factor"].values
    crossing = float(np.interp(1.0, sf, walls))  # sf rises with the wall
    # fig. 3.10: safe (T_cr/T > 1) when the wall is thicker than 1 mm; ±0.15 mm
    assert crossing == pytest.approx(1.0e-3, abs=0.15e-3)


def test_tailboom_temperatures_hover_and_parked() -> None:
    boom = thermal_row()["tailboom_c"]
    assert boom["parked"] == pytest.approx(89.0, abs=1.0)  # calibrated (solar_area_fraction)
    assert boom["hover"] == pytest.approx(44.0, abs=1.0)  # predicted (Hilpert, thesis eq. 2.57)


def test_zero_degree_plies_improve_whirl_stability() -> None:
    top = 1.5 * baseline_design().operating.speed_rad_s
    for method in ("viscous", "hysteretic"):
        onset = {k: (top if v is None else v) for k, v in whirl_row(method).items()}
        # abstract / figs 4.3-4.4: (45/-45/0/0)s raises the onset of the (45/-45)s shaft (factor >= 2)
        assert onset["(45/-45/0/0)s FMC"] >= 2.0 * onset["(45/-45)s FMC"], method


# Tests: the evidence for the assumed geometry


FORWARD_ENDS = {"twist only": ["theta"], "pinned": ["v", "w", "theta"], "clamped": ["v", "w", "theta", "beta", "gamma"]}


@functools.cache
def forward_end_row(end: str) -> tuple:
    """Lateral critical speeds [rad/s] and AF within 0.8-1.25 x the operating speed at the Table 3.1
    gains (thesis damping), and the shaft orbit [m] at the operating speed, for a forward end."""
    from flexshaft.analyses.criticals import lateral_critical_speeds

    design = with_overrides(baseline_design(), {**THESIS_DAMPING, "shaft.fixed_start": FORWARD_ENDS[end]})
    model = build_model(design)
    near = tuple(
        (c.speed, c.amplification_factor)
        for c in lateral_critical_speeds(model, top=1.25, n_points=300)
        if c.speed >= 0.8 * model.speed
    )
    q = imbalance_response(model, [model.speed], imbalance_loads(model))
    dm = model.dofs
    n = np.arange(dm.n_shaft_nodes)
    return near, float(orbit_amplitude(q[dm.shaft(n, "v")], q[dm.shaft(n, "w")]).max())


def test_only_a_laterally_free_forward_end_keeps_table31_non_critical() -> None:
    op = baseline_design().operating.speed_rad_s
    # thesis fig. 3.9: at K_p = 1e7 the operating condition is non-critical
    free, free_orbit = forward_end_row("twist only")
    assert all(abs(speed / op - 1.0) > 0.15 for speed, _ in free)
    for end in ("pinned", "clamped"):
        near, orbit = forward_end_row(end)
        # a lateral support at x = 0 stiffens the first bay onto the operating speed
        assert any(abs(speed / op - 1.0) < 0.02 and af > 100.0 for speed, af in near), end
        assert orbit > 3.0 * free_orbit, end


def test_no_boom_mode_near_the_tail_drive_speed() -> None:
    design = baseline_design()
    detached = {
        f"bearings[{i}].stiffness": {"u": 0.0, "v": 0.0, "w": 0.0}
        for i, b in enumerate(design.bearings)
        if b.kind == "contact"
    }
    detached.update({f"bearings[{i}].kp": 0.0 for i in actuator_paths(design)})
    m = modes(build_model(with_overrides(design, detached)), 0.0, 30)
    boom = np.asarray(m.frequencies)[np.asarray(m.shaft_fractions) < 0.5]
    drive = design.operating.speed_rad_s / (2.0 * math.pi)  # 80 Hz
    # frequency placement: nothing within API 684's largest margins (16 % below, 26 % above)
    assert not np.any((boom > 0.84 * drive) & (boom < 1.26 * drive)), boom
    # first bending pair between the main rotor's 1/rev and 4/rev (AH-64: 289 rpm)
    rotor = 289.0 / 60.0
    assert np.all((boom[:2] > rotor) & (boom[:2] < 4.0 * rotor)), boom[:2]


# Tests: rows not reproduced, asserting the mechanism the doc states


def test_safety_factor_is_set_by_the_torque_fibre_stress_not_3_5() -> None:
    for result in strength_row().values():
        # R ≈ 36 with sigma1 (fibre compression of a ±55° ply from the 489 N m torque) dominant
        assert 25.0 < result.safety_factor < 50.0
        assert result.dominant_stress == "sigma1" and abs(result.ply_angle_deg) == 55.0


def test_centrifugal_hoop_stress_does_not_explain_3_5() -> None:
    """The free-hoop strength model (N_y = 0, eq. 2.46) omits the spinning tube's own hoop
    resultant N_y = ρ t Ω² r_m²; adding it to the static strains moves R by < 5 %."""
    from flexshaft.analyses.shaft_strength import shaft_strains, shaft_strengths
    from flexshaft.laminate import abd_matrices, ply_stresses
    from flexshaft.strength import tsai_wu_safety_factor

    design = baseline_design()
    model = build_model(design)
    laminate, strengths = shaft_strengths(model)
    strains = shaft_strains(model, static_response(model, external_static_load(model) + torque_load(model)))
    r = model.shaft.outer_diameter / 2
    t = design.shaft.wall_thickness
    hoop = design.materials[design.shaft.material].density * t * model.speed**2 * (r - t / 2) ** 2  # N/m
    A = abd_matrices(laminate.storage)[0].real
    gamma = r * strains.twist

    def safety_factor(n_y: float) -> float:
        worst = np.inf
        for sign in (1.0, -1.0):
            eps_x = strains.axial + sign * r * np.hypot(strains.curvature_v, strains.curvature_w)
            eps_y = (n_y - A[0, 1] * eps_x - A[1, 2] * gamma) / A[1, 1]  # N_y given instead of 0
            sig = ply_stresses(laminate, eps_x, eps_y, gamma)
            worst = min(worst, float(tsai_wu_safety_factor(sig[..., 0], sig[..., 1], sig[..., 2], strengths).min()))
        return worst

    from flexshaft.analyses.shaft_strength import shaft_safety_factor

    free, spinning = safety_factor(0.0), safety_factor(hoop)
    assert hoop / t == pytest.approx(1.0e6, rel=0.05)  # ρ Ω² r² ≈ 1.0 MPa
    # the hand-built free-hoop check is the package's thesis path (no hoop, no thermal residual)
    thesis_path = shaft_safety_factor(
        model,
        static_response(model, external_static_load(model) + torque_load(model)),
        speed=0.0,
        thermal_residual=False,
    )
    assert free == pytest.approx(thesis_path.safety_factor, rel=1e-6)
    assert abs(spinning / free - 1.0) < 0.05


def test_single_angle_optimum_is_45_degrees_under_imposed_bending() -> None:
    ds = ply_angle_row()
    alpha, sf = ds["alpha"].values, ds["safety_factor"].values
    # a top near 45° where the bending σ2 vanishes (cos 2α ≈ 0); the uniform thermal residual σ2
    # (about 0.7 MPa in every ply) flattens the contrast: measured 16.1 at 47.5° against 10.6 at 55°
    assert 40.0 <= alpha[np.argmax(sf)] <= 50.0
    assert sf.max() > 1.4 * sf[alpha == 55.0][0]


def test_two_angle_optimum_is_not_55_0() -> None:
    ds = two_angle_row()
    sf = ds["safety_factor"]
    best = float(sf.max())
    assert float(sf.sel(alpha=55.0, beta=0.0)) < 0.9 * best


def test_safety_factor_rises_monotonically_with_the_wall() -> None:
    ds = wall_strength_row()
    sf, sf0 = ds["safety_factor"].values, ds["safety_factor_no_imbalance"].values
    assert np.all(np.diff(sf) > 0.0)  # no resonance dip (thesis fig. 3.4: near 1.7 mm)
    assert np.all(np.abs(sf / sf0 - 1.0) < 0.02)  # the imbalance costs little (measured at most 1.04 %, 6 mm)


def test_shaft_self_heating_is_far_below_8_kelvin() -> None:
    th = thermal_row()
    for key in ("shaft_thesis_loss_model", "shaft_rotating_loss_model"):
        assert th[key]["peak_rise_K"] < 0.01  # thesis: about 8 K above ambient


# The verdicts of both embedded designs


def test_tuned_design_passes_every_requirement(embedded_comparison) -> None:
    """``verdict_row("tuned")``, the packaged tuned design assessed as ``flexshaft run`` does
    (all its envelope points, the report's resolution): the same assessment is the first run of
    the comparison of the embedded designs, computed once per session (tests/conftest.py; CPU
    budget, issue 23)."""
    from flexshaft.resolution import REPORT

    res = embedded_comparison.runs[0]
    assert res.design == tuned_design() and res.resolution == REPORT  # what verdict_row("tuned") assesses
    failed = [c.key for c in res.verdict.checks if c.status == "fail"]
    assert all(c.status != "not evaluated" for c in res.verdict.checks)
    # whirl_damping may fail only on boom-only modes (ζ ≈ η_boom/2 = 0.01, δ ≈ 0.063): the lead's
    # change restricts the check to lateral modes with shaft participation
    assert set(failed) <= {"whirl_damping"}
    shaft_modes = shaft_mode_log_decrements(res)
    assert shaft_modes and min(shaft_modes.values()) >= res.model.design.requirements.required_log_decrement


def test_table31_configuration_fails_where_the_thesis_says_it_must_be_tuned() -> None:
    res = verdict_row("baseline")
    failed = {c.key for c in res.verdict.checks if c.status == "fail"}
    # K_d = 0: whirl-unstable below the operating speed, spin-up peak far above the limit
    assert {"whirl_onset", "spinup_deflection"} <= failed
    assert res.verdict.check("whirl_onset").value < res.model.speed


# ------------------------------------------------------------------------------------------------
# The table of docs/thesis-reproduction.md, from the same computations


def _mm(value: float) -> str:
    return f"{value * 1e3:.3g} mm"


def reproduction_table() -> list[tuple[str, str, str]]:
    """(finding, flexshaft's number, status) of each row, numbers formatted for the doc."""
    rows = []
    sf = strength_row()
    rows.append(
        (
            "safety factor ≈ 3.5",
            f"R = {sf['baseline'].safety_factor:.1f} (Table 3.1), "
            f"{sf['tuned'].safety_factor:.1f} (tuned); {sf['tuned'].dominant_stress} of the "
            f"{sf['tuned'].ply_angle_deg:+.0f}° ply at x = {sf['tuned'].x:.2f} m",
            "not reproduced",
        )
    )
    ds = ply_angle_row()
    alpha, r = ds["alpha"].values, ds["safety_factor"].values
    rows.append(
        (
            "±55° best single angle",
            f"{alpha[np.argmax(r)]:.1f}° (R = {r.max():.1f}); ±55°: R = {r[alpha == 55.0][0]:.1f}",
            "not reproduced",
        )
    )
    ds2 = two_angle_row()["safety_factor"]
    i, j = np.unravel_index(int(np.nanargmax(ds2.values)), ds2.shape)
    rows.append(
        (
            "(55/−55/0/0)s best two-angle",
            f"({ds2.alpha.values[i]:.0f}/−{ds2.alpha.values[i]:.0f}/"
            f"{ds2.beta.values[j]:.0f}/−{ds2.beta.values[j]:.0f})s R = {float(ds2.max()):.1f}; (55/−55/0/0)s "
            f"R = {float(ds2.sel(alpha=55.0, beta=0.0)):.1f}",
            "not reproduced",
        )
    )
    f = wall_frequency_row()
    d_o = baseline_design().shaft.outer_diameter
    d_i = d_o - 2.0 * WALLS
    closed = math.sqrt((d_o**2 + d_i[-1] ** 2) / (d_o**2 + d_i[0] ** 2))
    rows.append(
        (
            "frequencies fall with wall at fixed D_o",
            f"first shaft mode {f[0, 0]:.2f} → {f[-1, 0]:.2f} Hz "
            f"(1 → 6 mm), ratio {f[-1, 0] / f[0, 0]:.4f} vs eq. 3.3 {closed:.4f}",
            "reproduced",
        )
    )
    w = wall_strength_row()
    rows.append(
        (
            "SF dip near 1.7 mm, falls above 3 mm",
            f"R rises {w['safety_factor'].values[0]:.1f} → "
            f"{w['safety_factor'].values[-1]:.1f} (1 → 6 mm), imbalance < 1 %",
            "not reproduced",
        )
    )
    g = gain_row()
    kp, disp, gsf = g["kp"].values, g["actuator_displacement"].values, g["safety_factor"].values
    k10 = int(np.argmin(np.abs(kp - 1e7)))
    rows.append(
        (
            "K_p: SF falls from low K_p; resonance at 6.5e5 critical, 1e7 not",
            f"R {gsf[0]:.2f} → "
            f"{gsf[kp <= 1e6][-1]:.2f} (1e5 → 1e6); critical K_p {kp[np.argmax(disp)]:.3g} N/m (R {gsf.min():.1f}, "
            f"actuator {_mm(disp.max())}); at 1e7 {disp[k10] * 1e6:.1f} µm",
            "reproduced (K_p ×2.7)",
        )
    )
    smap = gain_map_row("thesis")

    def reduction(value):
        row = smap.shaft_peak[np.argmin(np.abs(smap.kp - value))]
        return row[0] / row.min()

    best = smap.shaft_peak.min(axis=1)
    rows.append(
        (
            "K_d damps at low K_p only; optimum K_d per K_p",
            f"best K_d cuts the peak ×{reduction(1e6):.1f} at "
            f"1e6, ×{reduction(5e7):.2f} at 5e7; best peak {_mm(best[np.argmin(np.abs(smap.kp - 1e7))])} (1e7) → "
            f"{_mm(best.min())} ({smap.kp[np.argmin(best)]:.2g})",
            "reproduced",
        )
    )
    for damping in ("thesis", "rotating"):
        peak, speed = table31_peak(damping)
        rows.append(
            (
                f"spin-up peak 38 mm at Table 3.1 gains [{damping}]",
                f"{_mm(peak)} at {speed * RPM:.0f} rpm",
                "calibrated" if damping == "thesis" else "model difference",
            )
        )
    gap = baseline_design().bearings[1].gap
    for damping in ("thesis", "rotating"):
        t = tuning_row(damping, gap)
        rows.append(
            (
                f"tuned gains: 38 → 4 mm [{damping}]",
                f"{_mm(t.peak)} at K_p {t.kp:.3g}, K_d {t.kd:.3g} (gap {gap * 1e3:g} mm, excursion {_mm(t.excursion)})",
                "reproduced (×2)" if 0.002 <= t.peak <= 0.008 else "not reproduced",
            )
        )
    tuned_gap = tuned_design().bearings[1].gap
    t = tuning_row("rotating", tuned_gap)
    rows.append(
        (
            "tuned design's gains [rotating]",
            f"{_mm(t.peak)} at K_p {t.kp:.3g}, K_d {t.kd:.3g} (gap "
            f"{tuned_gap * 1e3:g} mm, excursion {_mm(t.excursion)})",
            "design",
        )
    )
    s = surfaces_row("thesis")
    rows.append(
        (
            "Fig. 3.13/3.14: resonance excited at 2e6, damped at 3e5",
            f"{_mm(s['peak_high'])} at "
            f"{s['speed'] * RPM:.0f} rpm, x = {s['station']:.2f} m ({s['peak_high'] / s['median_high']:.0f}× the "
            f"median); 3e5: {_mm(s['band_low'])} (×{s['peak_high'] / s['band_low']:.1f} lower)",
            "reproduced",
        )
    )
    b = buckling_row()
    bw, bsf = b["wall_thickness"].values, b["buckling_safety_factor"].values
    rows.append(
        (
            "buckling safe above 1 mm wall",
            ", ".join(f"{x * 1e3:g} mm: {v:.2f}" for x, v in zip(bw, bsf))
            + f"; crossing {float(np.interp(1.0, bsf, bw)) * 1e3:.2f} mm",
            "reproduced",
        )
    )
    th = thermal_row()
    rows.append(
        (
            "boom 44 °C hover / 89 °C parked",
            f"{th['tailboom_c']['hover']:.1f} / {th['tailboom_c']['parked']:.1f} °C",
            "reproduced (parked calibrated)",
        )
    )
    rows.append(
        (
            "shaft ≈ 8 °C above ambient",
            f"+{th['shaft_thesis_loss_model']['peak_rise_K']:.2g} K (thesis loss) / "
            f"+{th['shaft_rotating_loss_model']['peak_rise_K']:.2g} K (rotating) above the 44.1 °C boom air",
            "not reproduced",
        )
    )
    for method in ("viscous", "hysteretic"):
        onset = whirl_row(method)
        text = ", ".join(
            f"{k.replace(' FMC', '')}: " + ("stable" if v is None else f"{v * RPM:.0f} rpm") for k, v in onset.items()
        )
        rows.append((f"0° plies improve whirl stability [{method}]", text, "reproduced"))
    for name in ("baseline", "tuned"):
        res = verdict_row(name)
        failed = [c.key for c in res.verdict.checks if c.status == "fail"]
        logdec = min(shaft_mode_log_decrements(res).values())
        rows.append(
            (f"verdict of {name}", f"fails: {', '.join(failed) or 'none'}; shaft-mode log dec {logdec:.3f}", "-")
        )
    return rows


if __name__ == "__main__":
    for finding, value, status in reproduction_table():
        print(f"| {finding} | {value} | {status} |")
