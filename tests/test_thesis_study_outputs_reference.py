"""The thesis studies' per-point outputs against their definitions and exact properties.

Each study point is computed on the baseline design at a coarse mesh (18 shaft and 12 boom
elements: the properties below hold at any mesh), and checked against

* its definition built from the lower layers directly (the imbalance response at the operating
  speed Ω_op, the Tsai-Wu check of :func:`~flexshaft.analyses.shaft_strength.shaft_safety_factor`,
  each actuator's relative displacement rows): study 3's and 4's "safety factor with the
  imbalance" is the worst (smallest) over the imbalance load cases at Ω_op (thesis §3.2, figure
  3.4: "studied both with and without the imbalance loading"), study 4's actuator displacement
  the largest relative orbit over both actuators at Ω_op (thesis figure 3.6: "the maximum shaft
  displacement at the actuator locations");
* exact properties: the worst case is at most every case and at most the static factor; the
  thesis's own load set (no centrifugal hoop stress) does not change when the spin doubles at
  the same torque (P and Ω both doubled, T = P/Ω), while flexshaft's added hoop stress (∝ Ω²) does;
* a closed form: study 3's forced response (thesis figure 3.5) of a shaft without actuators on
  the Jeffcott rotor of tests/rotors.py (20 kg disk at mid-span of a near-massless pinned-pinned
  tube, k = 48EI/L³, an external dashpot c_e at the disk, no internal loss): the disk's forward
  circle of radius e m Ω² / |k − mΩ² + iΩc_e| (m the rotating mass, the disk and the tube).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import DI, DO, K_SHAFT, M_DISK, WN, L, jeffcott_text

from flexshaft.analyses.response import imbalance_response, orbit_amplitude, static_response
from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly.loads import external_static_load, imbalance_loads, torque_load
from flexshaft.design import baseline_design, loads_design, with_overrides
from flexshaft.sweep.study import Point
from flexshaft.thesis.gain import _actuator_outputs
from flexshaft.thesis.ply_angle import critical_ply_outputs
from flexshaft.thesis.strength import strength_outputs
from flexshaft.thesis.wall import _wall_outputs, forced_response

COARSE = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}


@pytest.fixture(scope="module")
def worst_point():
    """The baseline, coarse, at the 1.7 mm wall (the operating speed near a natural frequency,
    thesis figure 3.5: the imbalance matters) with the 'worst' placement: four imbalance cases
    (in/anti-phase bays) whose safety factors differ."""
    design = with_overrides(
        baseline_design(), {**COARSE, "shaft.wall_thickness": 0.0017, "loads.imbalance_placement": "worst"}
    )
    return Point(0, {}, {}, design)


def _imbalance_at_operating_speed(model):
    return imbalance_response(model, [model.speed], imbalance_loads(model))[:, :, 0]


def test_strength_with_imbalance_is_the_worst_case_at_the_operating_speed(worst_point):
    """safety_factor = min over the cases of Tsai-Wu(static + case at Ω_op) to 1e-12 (the same
    solves in another order); strictly below the static factor and at most every case."""
    model = worst_point.model
    out = strength_outputs(worst_point)
    q_static = static_response(model, external_static_load(model) + torque_load(model))
    q = _imbalance_at_operating_speed(model)
    cases = np.array([shaft_safety_factor(model, q_static, q[:, c]).safety_factor for c in range(q.shape[1])])
    static = shaft_safety_factor(model, q_static).safety_factor
    assert cases.size == 4 and np.ptp(cases) > 1e-3 * cases.min()  # the cases differ: min ≠ max
    assert out["safety_factor_static"] == pytest.approx(static, rel=1e-12)
    assert out["safety_factor"] == pytest.approx(cases.min(), rel=1e-12)
    assert out["safety_factor"] < static


def test_gain_study_displacement_is_the_larger_actuator_orbit_at_the_operating_speed(worst_point):
    """Thesis figure 3.6's actuator displacement: the largest relative orbit (major semi-axis of
    shaft − attachment at the magnet) over both actuators and every case at Ω_op, to 1e-12; the
    two actuators' orbits differ (by 3 % here: their stations do), so the larger one is the
    one named."""
    model = worst_point.model
    out = _actuator_outputs(worst_point)
    q = _imbalance_at_operating_speed(model)
    per_actuator = np.array([orbit_amplitude(*(a.lateral_rows @ q)).max() for a in model.actuators])
    assert per_actuator.size == 2 and per_actuator.min() < 0.99 * per_actuator.max()
    assert out["actuator_displacement"] == pytest.approx(per_actuator.max(), rel=1e-12)


def test_the_thesis_load_set_does_not_spin():
    """``added_loads=False`` (the thesis's loads: external loads and torque, no hoop stress, no
    thermal residual): doubling both the speed and the power keeps the torque and the external
    loads, and so the safety factor (to 1e-12, the same solve); with flexshaft's added loads
    the centrifugal hoop stress (∝ Ω²) changes it (by 14 % on this design)."""
    design = with_overrides(baseline_design(), {**COARSE, "loads.eccentricity": 0.0})
    faster = with_overrides(
        design, {"operating.speed_rpm": 2 * design.operating.speed_rpm, "operating.power": 2 * design.operating.power}
    )
    thesis = [critical_ply_outputs(Point(0, {}, {}, d), added_loads=False)["safety_factor"] for d in (design, faster)]
    added = [critical_ply_outputs(Point(0, {}, {}, d))["safety_factor"] for d in (design, faster)]
    assert thesis[1] == pytest.approx(thesis[0], rel=1e-12)
    assert abs(added[1] / added[0] - 1) > 0.05


def test_wall_study_without_imbalance_is_the_static_factor(worst_point):
    """Study 3's "without imbalance" factor is the static one (external loads and torque only),
    computed directly to 1e-12; the imbalance at Ω_op lowers the factor with it (0.2 % at the
    1.7 mm wall). Twelve spin-up speeds: the spin-up peak is not this test's subject."""
    point = Point(0, {}, {"n_speeds": 12}, worst_point.design)
    model = point.model
    out = _wall_outputs(point)
    q_static = static_response(model, external_static_load(model) + torque_load(model))
    static = shaft_safety_factor(model, q_static).safety_factor
    assert out["safety_factor_no_imbalance"] == pytest.approx(static, rel=1e-12)
    assert out["safety_factor"] < (1 - 1e-3) * out["safety_factor_no_imbalance"]


def test_forced_response_without_actuators_is_the_jeffcott_circle():
    """Seven speeds from 2 % to 130 % of Ω_op = ω_n (the resonance inside), 10 % of critical
    damping at the disk; the largest orbit over the nodes (the disk's) against the closed form
    to 1e-4 (it leaves out the tube's 7e-6 of the disk's mass and its shear flexibility;
    measured 8e-6)."""
    c_e = 2 * 0.05 * M_DISK * WN
    text = jeffcott_text(0.0, c_e).replace("speed_rpm = 0.0", f"speed_rpm = {float(WN * 30 / np.pi)!r}")
    design = loads_design(text + "[loads]\neccentricity = 1e-5\n")
    out = forced_response(design, [(DO - DI) / 2], 7)
    speeds = np.asarray(out["speed"].values)
    assert speeds[0] < 0.1 * WN < WN < speeds[-1]
    m_rot = M_DISK + 0.1 * np.pi / 4 * (DO**2 - DI**2) * L  # disk + tube (density 0.1 kg/m³)
    closed = 1e-5 * m_rot * speeds**2 / np.abs(K_SHAFT - M_DISK * speeds**2 + 1j * speeds * c_e)
    np.testing.assert_allclose(np.asarray(out["shaft_peak"].values)[0], closed, rtol=1e-4)


def test_critical_ply_stresses_fail_at_the_reported_factor_by_table_3_2():
    """Study 1's critical ply (thesis Table 3.3): its (σ1, σ2, τ12) scaled by the reported R lie
    on the Tsai-Wu surface of the thesis's Table 3.2 strengths (X_t 2185, X_c 2000, Y_t 5.1,
    Y_c 5.5, S 20 MPa; F12 = −½√(F11 F22), Tsai & Hahn): a R² + b R = 1 with
    a = F11σ1² + F22σ2² + F66τ12² + 2F12σ1σ2, b = F1σ1 + F2σ2 (thesis eq. 2.48). The thesis's
    load set (no residual stress, which would not scale with R); at 30° the three stresses
    differ (a column read for another shows). 1e-9: a quadratic's roots, well conditioned here."""
    design = with_overrides(baseline_design(), {**COARSE, "loads.eccentricity": 0.0, "shaft.layup": "(30/-30/-30/30)"})
    out = critical_ply_outputs(Point(0, {}, {}, design), added_loads=False)
    xt, xc, yt, yc, s = 2185e6, 2000e6, 5.1e6, 5.5e6, 20e6
    f1, f2, f11, f22, f66 = 1 / xt - 1 / xc, 1 / yt - 1 / yc, 1 / (xt * xc), 1 / (yt * yc), 1 / s**2
    f12 = -0.5 * np.sqrt(f11 * f22)
    s1, s2, t12 = out["sigma1"], out["sigma2"], out["tau12"]
    a = f11 * s1**2 + f22 * s2**2 + f66 * t12**2 + 2 * f12 * s1 * s2
    b = f1 * s1 + f2 * s2
    r = out["safety_factor"]
    assert abs(abs(t12) - abs(s2)) > 0.1 * max(abs(t12), abs(s2))
    assert a * r**2 + b * r == pytest.approx(1.0, rel=1e-9)
