"""The metal segments' safety factor along the shaft is the one that governs: min(n_f, n_y).

A pinned aluminium tube (S_y = 276 MPa, S_ut = 310 MPa, S_e = 100 MPa) under a static axial
compression F_x = −5 kN at its free end, no imbalance response: a uniform mean stress
σ_m = |F_x|/A on every fibre, A = π(D_o² − D_i²)/4, no alternating stress, beside the mean hoop
stress σ_θ = ρ Ω² r_m² of a thin ring (r_m = (D_o − t)/2). With no alternation, the DE-Goodman
and first-cycle yield forms of Shigley (Budynas & Nisbett, 10th ed., 2015) eqs. 7-7 and 7-16, as
the module's docstring and tests/test_metal_strength_reference.py state them, give the same von Mises stress
σ' = √(σ_m² + σ_m σ_θ + σ_θ²) (a compression beside a tensile hoop stress) for both checks:
n_f = S_ut/σ' (DE-Goodman with σ_a' = 0) and n_y = S_y/σ' (first-cycle yield). Since
S_y < S_ut, yield governs: the factor drawn along the shaft is n_y = S_y/σ' at every element
end, and n_f/n_y = S_ut/S_y. The Hermite beam element is exact for a uniform axial force, so
the tolerance is round-off, 1e-9. CPU: a few milliseconds after the model's build.
"""

from __future__ import annotations

import math

import numpy as np

from flexshaft.analyses.metal_strength import metal_strength
from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import design_from_dict

S_Y, S_UT, S_E, RHO = 276e6, 310e6, 100e6, 2700.0
L, D_O, WALL, RPM = 2.0, 0.05, 0.002, 3000.0


def test_the_factor_along_the_shaft_is_the_smaller_first_cycle_yield_factor():
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
    model = build_model(design_from_dict(data))
    static = static_response(model, point_load(model, "shaft", (-5000.0, 0.0, 0.0), x=L))
    result = metal_strength(model, static, buckling=False)
    sigma = 5000.0 / (math.pi * (D_O**2 - (D_O - 2 * WALL) ** 2) / 4)
    hoop = RHO * (RPM * 2 * math.pi / 60) ** 2 * ((D_O - WALL) / 2) ** 2
    von_mises = math.sqrt(sigma**2 + sigma * hoop + hoop**2)
    x, along = result.along_shaft()
    np.testing.assert_allclose(x, result.x.reshape(-1), rtol=0, atol=0)
    np.testing.assert_allclose(along, S_Y / von_mises, rtol=1e-9)
    np.testing.assert_allclose(result.fatigue_safety_factor, S_UT / von_mises, rtol=1e-9)
