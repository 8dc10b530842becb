"""Metal shaft segments: whirl sense, torsional fatigue and the buckling torque, by hand.

A pinned aluminium tube, loads at midspan (the Hermite beam element is exact at a loaded node,
so the tolerances are round-off, 1e-9):

* a synchronous **forward** circular whirl is frozen in the rotating material: its bend is a
  mean stress M c/I and no alternating stress; a **backward** whirl of the same size is seen
  at 2/rev: alternating M c/I, no mean stress (the standard result that a rotor in synchronous
  forward whirl is not stressed cyclically, e.g. Genta, *Dynamics of Rotating Systems*, 2005).
  The forward rotating force is (F_y, F_z) = F (1, −i) (the convention of
  :mod:`flexshaft.assembly.loads`, W = −iV); each whirl is solved statically, its shape the bend;
* an alternating torque T_a gives τ_a = T_a c/J and the distortion-energy alternating stress
  √3 τ_a (Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., eq. 7-7):
  n_f = 1/(√3 τ_a/S_e + σ_θ/S_ut), σ_θ = ρ Ω² r_m² the mean hoop stress;
* the transmitted torque is P/Ω (P = T Ω, Ω in rad/s) and the buckling safety factor T_cr/T.
  The critical torque is checked for the segment's wiring only (radius, wall, length, moduli):
  against the classical Sanders shell of the tube's mid-surface radius r_m = (D_o − t)/2 on a
  laminate written by hand from the tube (the shell itself is checked against Timoshenko & Gere
  and Batdorf in tests/test_buckling.py; this is not a second physics reference for it).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.metal_strength import metal_strength
from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load, torque_load
from flexshaft.buckling import torsional_buckling_torque
from flexshaft.design import design_from_dict
from flexshaft.laminate import Lamina, Laminate

AL = {
    "kind": "isotropic",
    "E": 70.0e9,
    "G": 26.0e9,
    "density": 2700.0,
    "yield_strength": 276e6,
    "ultimate_strength": 310e6,
    "fatigue_strength": 100e6,
}
L, D_O, WALL, F, RPM, POWER = 2.0, 0.05, 0.002, 150.0, 3000.0, 12e3
INERTIA = math.pi * (D_O**4 - (D_O - 2 * WALL) ** 4) / 64
OMEGA = RPM * 2 * math.pi / 60


@pytest.fixture(scope="module")
def tube():
    """A 2 m aluminium tube on pinned ends, 3000 rpm, 12 kW, built from a design dict."""
    data = {
        "name": "metal tube",
        "materials": {"al": AL},
        "shaft": {
            "x_start": 0.0,
            "x_end": L,
            "outer_diameter": D_O,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": L, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": RPM, "power": POWER},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 10},
    }
    return build_model(design_from_dict(data))


def _whirl(model, sense: complex) -> np.ndarray:
    """Response to the midspan force F (1, sense·i) solved statically (a circular whirl's shape)."""
    lateral_y = static_response(model, point_load(model, "shaft", (0.0, F, 0.0), x=L / 2))
    lateral_z = static_response(model, point_load(model, "shaft", (0.0, 0.0, F), x=L / 2))
    return lateral_y + sense * 1j * lateral_z


@pytest.mark.parametrize(("sense", "mean", "alternating"), [(-1.0, 1.0, 0.0), (1.0, 0.0, 1.0)])
def test_a_forward_whirl_is_a_mean_stress_and_a_backward_one_alternates(tube, sense, mean, alternating):
    """Forward (F(1, −i)): σ_m = M c/I, σ_a = 0; backward (F(1, i)): σ_a = M c/I, σ_m = 0."""
    result = metal_strength(tube, np.zeros(tube.dofs.size), _whirl(tube, sense), buckling=False)
    stress = F * L / 4 * (D_O / 2) / INERTIA
    middle = int(np.argmin(np.abs(result.x - L / 2)))
    e, end = np.unravel_index(middle, result.x.shape)
    assert result.sigma_mean[e, end] == pytest.approx(mean * stress, rel=1e-9, abs=1e-9 * stress)
    assert result.sigma_alternating[e, end] == pytest.approx(alternating * stress, rel=1e-9, abs=1e-9 * stress)


def test_an_alternating_torque_is_the_distortion_energy_fatigue_stress(tube):
    """Torque T_a = 300 N m as the alternating part, nothing static: τ_a = T_a c/J (J = 2I),
    n_f = 1/(√3 τ_a/S_e + σ_θ/S_ut) at every station (uniform torsion)."""
    T_a = 300.0
    dynamic = static_response(tube, torque_load(tube, T_a)).astype(complex)
    result = metal_strength(tube, np.zeros(tube.dofs.size), dynamic, buckling=False)
    tau_a = T_a * (D_O / 2) / (2 * INERTIA)
    hoop = AL["density"] * OMEGA**2 * ((D_O - WALL) / 2) ** 2
    n_f = 1.0 / (math.sqrt(3.0) * tau_a / AL["fatigue_strength"] + hoop / AL["ultimate_strength"])
    np.testing.assert_allclose(result.tau_alternating, tau_a, rtol=1e-9)
    np.testing.assert_allclose(result.fatigue_safety_factor, n_f, rtol=1e-9)


def test_the_segment_buckles_as_its_mid_surface_shell_under_the_torque_p_over_omega(tube):
    """T = P/Ω; T_cr of the classical shell at r_m = (D_o − t)/2, wall t, over the segment's
    length; safety factor T_cr/T."""
    (b,) = metal_strength(tube, np.zeros(tube.dofs.size)).buckling
    lamina = Lamina.isotropic(AL["E"], AL["G"], AL["density"])
    wall = Laminate(angles=np.zeros(1), thicknesses=np.array([WALL]), lamina=lamina)
    reference = torsional_buckling_torque(wall, (D_O - WALL) / 2, L, theory="classical")
    assert b.torque == pytest.approx(POWER / OMEGA, rel=1e-12)
    assert b.critical_torque == pytest.approx(reference.critical_torque, rel=1e-12)
    assert b.safety_factor == pytest.approx(reference.critical_torque / (POWER / OMEGA), rel=1e-12)


def test_a_static_thrust_is_a_mean_stress_f_over_a(tube):
    """A static axial compression F_x = −5 kN at the free end (u held at the start only): a
    uniform axial stress σ_x = F_x/A on every fibre (A = π(D_o² − D_i²)/4), reported as its
    magnitude σ_m = |σ_x|, no alternating stress. Beside the tensile mean hoop stress σ_θ, the
    biaxial von Mises stress is √(σ_x² − σ_x σ_θ + σ_θ²) = √(σ_m² + σ_m σ_θ + σ_θ²) for a
    compression (Shigley eq. 7-16 with no shear and no alternation), so the first-cycle yield
    factor is S_y over it: a compression is the sign for which the module's worst-sign form is
    the plain von Mises stress (a tension would give √(σ_m² − σ_m σ_θ + σ_θ²), less)."""
    thrust = -5000.0
    static = static_response(tube, point_load(tube, "shaft", (thrust, 0.0, 0.0), x=L))
    result = metal_strength(tube, static, buckling=False)
    sigma = abs(thrust) / (math.pi * (D_O**2 - (D_O - 2 * WALL) ** 2) / 4)
    hoop = AL["density"] * OMEGA**2 * ((D_O - WALL) / 2) ** 2
    np.testing.assert_allclose(result.sigma_mean, sigma, rtol=1e-9)
    np.testing.assert_allclose(result.sigma_alternating, 0.0, atol=1e-9 * sigma)
    n_y = AL["yield_strength"] / math.sqrt(sigma**2 + sigma * hoop + hoop**2)
    np.testing.assert_allclose(result.yield_safety_factor, n_y, rtol=1e-9)


def test_an_alternating_axial_force_is_an_alternating_stress_f_over_a(tube):
    """The response's axial part alternates: an axial force of amplitude F_x = 5 kN at the free
    end, solved statically as the response's shape, gives σ_a = F_x/A everywhere, σ_m = 0."""
    thrust = 5000.0
    dynamic = static_response(tube, point_load(tube, "shaft", (thrust, 0.0, 0.0), x=L)).astype(complex)
    result = metal_strength(tube, np.zeros(tube.dofs.size), dynamic, buckling=False)
    sigma = thrust / (math.pi * (D_O**2 - (D_O - 2 * WALL) ** 2) / 4)
    np.testing.assert_allclose(result.sigma_alternating, sigma, rtol=1e-9)
    np.testing.assert_allclose(result.sigma_mean, 0.0, atol=1e-9 * sigma)


def test_the_worst_imbalance_case_is_kept(tube):
    """Two imbalance cases, one at rest (no response) and the backward whirl of the first test:
    at midspan the check keeps the whirl, σ_a = M c/I with M = F L/4, and the smaller n_f."""
    dynamic = np.column_stack([np.zeros(tube.dofs.size, complex), _whirl(tube, 1.0)])
    result = metal_strength(tube, np.zeros(tube.dofs.size), dynamic, buckling=False)
    stress = F * L / 4 * (D_O / 2) / INERTIA
    middle = int(np.argmin(np.abs(result.x - L / 2)))
    e, end = np.unravel_index(middle, result.x.shape)
    assert result.sigma_alternating[e, end] == pytest.approx(stress, rel=1e-9)
    hoop = AL["density"] * OMEGA**2 * ((D_O - WALL) / 2) ** 2
    n_f = 1.0 / (stress / AL["fatigue_strength"] + hoop / AL["ultimate_strength"])
    assert result.fatigue_safety_factor[e, end] == pytest.approx(n_f, rel=1e-9)
