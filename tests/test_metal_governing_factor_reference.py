"""The metal segments' safety factor along the shaft is the one that governs: min(n_f, n_y).

A pinned aluminium tube (S_y = 276 MPa, S_ut = 310 MPa, S_e = 100 MPa; D_o = 50 mm, 2 mm
wall, L = 2 m, 3000 rpm, four elements, ends at x = 0, L/4, L/2, 3L/4, L) beside the mean hoop
stress σ_θ = ρ Ω² r_m² of a thin ring (r_m = (D_o − t)/2). The stresses are combined by
plane-stress von Mises, σ'² = σ_x² − σ_xσ_θ + σ_θ² + 3τ² (derived here; no shear in these
load cases), and the safety factors by the DE-Goodman and first-cycle yield forms as the
module quotes them (Shigley, Budynas & Nisbett, 10th ed., 2015, eqs. 7-7, 7-16; not read
here): 1/n_f = σ_a'/S_e + σ_m'/S_ut, n_y = S_y/σ'_max. Two load cases, one for each side of
the min:

* a static axial compression F_x = −5 kN at the free end, no imbalance response: a uniform
  mean stress σ_x = −F/A on every fibre, A = π(D_o² − D_i²)/4, no alternating stress, so
  σ' = √(σ_m² + σ_m σ_θ + σ_θ²) (σ_x < 0 beside σ_θ > 0) in both checks: n_f = S_ut/σ',
  n_y = S_y/σ', and since S_y < S_ut yield governs at every element end;
* a transverse point load P = 500 N at midspan: the static bending moment M = P x/2
  (x ≤ L/2, statics of the simply supported beam, mirrored beyond) is seen by the rotating
  tube as fully reversed, σ_a = M (D_o/2)/I, I = π(D_o⁴ − D_i⁴)/64, no mean axial stress:
  n_f = 1/(σ_a/S_e + σ_θ/S_ut), n_y = S_y/√(σ_a² + σ_a σ_θ + σ_θ²) (the compressed fibre,
  σ_x = −σ_a, is the worse). With S_e < S_y fatigue governs wherever σ_a ≫ σ_θ (σ_a = 36 MPa
  at L/4, σ_θ = 0.15 MPa), yield at the pinned ends where M = 0 (n_y = S_y/σ_θ < S_ut/σ_θ).

Tolerance: the linear axial element is exact for a uniform axial force, and the beam
element's interpolation (exact for a Timoshenko element, as :mod:`flexshaft.elements.shape`
states: with no load between its nodes the moment is linear there) for a point load on a
node, so only round-off remains: rtol 1e-9 (measured 1e-12 at the pinned ends, where σ_a is
the round-off of a zero moment beside σ_θ). CPU: a few milliseconds after the model's build.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.metal_strength import metal_strength
from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import design_from_dict

S_Y, S_UT, S_E, RHO = 276e6, 310e6, 100e6, 2700.0
L, D_O, WALL, RPM = 2.0, 0.05, 0.002, 3000.0
D_I = D_O - 2 * WALL
HOOP = RHO * (RPM * 2 * math.pi / 60) ** 2 * ((D_O - WALL) / 2) ** 2
ENDS = np.repeat(np.linspace(0.0, L, 5), 2)[1:-1]  # the four elements' ends, flattened


@pytest.fixture(scope="module")
def model():
    data = {
        "name": "metal tube",
        "materials": {
            "al": {
                "kind": "isotropic",
                "E": 70.0e9,
                "G": 26.0e9,
                "density": RHO,
                "yield_strength": S_Y,
                "ultimate_strength": S_UT,
                "fatigue_strength": S_E,
            }
        },
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
        "operating": {"speed_rpm": RPM, "power": 12e3},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 4},
    }
    return build_model(design_from_dict(data))


def test_the_factor_along_the_shaft_is_the_smaller_first_cycle_yield_factor(model):
    static = static_response(model, point_load(model, "shaft", (-5000.0, 0.0, 0.0), x=L))
    result = metal_strength(model, static, buckling=False)
    sigma = 5000.0 / (math.pi * (D_O**2 - D_I**2) / 4)
    von_mises = math.sqrt(sigma**2 + sigma * HOOP + HOOP**2)
    x, along = result.along_shaft()
    np.testing.assert_allclose(x, ENDS, rtol=0, atol=1e-12 * L)  # stations: round-off of the mesh
    np.testing.assert_allclose(along, S_Y / von_mises, rtol=1e-9)
    np.testing.assert_allclose(result.fatigue_safety_factor, S_UT / von_mises, rtol=1e-9)


def test_fatigue_governs_under_the_reversed_bending_and_yield_at_the_pinned_ends(model):
    P = 500.0
    static = static_response(model, point_load(model, "shaft", (0.0, P, 0.0), x=L / 2))
    result = metal_strength(model, static, buckling=False)
    inertia = math.pi * (D_O**4 - D_I**4) / 64
    sigma_a = P * np.minimum(ENDS, L - ENDS) / 2 * (D_O / 2) / inertia
    n_f = 1.0 / (sigma_a / S_E + HOOP / S_UT)
    n_y = S_Y / np.sqrt(sigma_a**2 + sigma_a * HOOP + HOOP**2)
    governs_fatigue = n_f < n_y
    assert governs_fatigue.tolist() == [False] + [True] * 6 + [False]  # both sides of the min
    x, along = result.along_shaft()
    np.testing.assert_allclose(x, ENDS, rtol=0, atol=1e-12 * L)
    np.testing.assert_allclose(result.fatigue_safety_factor.reshape(-1), n_f, rtol=1e-9)
    np.testing.assert_allclose(result.yield_safety_factor.reshape(-1), n_y, rtol=1e-9)
    np.testing.assert_allclose(along, np.where(governs_fatigue, n_f, n_y), rtol=1e-9)
