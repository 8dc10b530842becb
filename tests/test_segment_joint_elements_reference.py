"""Two-segment shafts in torsion: every element takes the tube of its own segment.

A shaft of two tubes in series, a (0 to 1 m, the thicker) and b (1 to 2 m), held in twist at
x = 0. The joint is a mesh node, so the first element of b starts exactly at b's x_start.

* **Statics.** A torque T at the aft end: every section carries T (free-body equilibrium), so the
  outer-fibre shear stress in segment k is τ = T r_k / J_k (r_k = D_k/2, J_k = π(D_k⁴ − d_k⁴)/32),
  the elastic torsion of a tube (derived). The metal strength check must report τ_m = T r_k/J_k
  at both ends of every element of segment k, and that element's segment name.
* **Torsional forced response.** A massless shaft (density 1e-2) with the tail rotor of
  tests/test_torsional.py: the shaft is a series spring k_s = 1/(L_a/(G J_a) + L_b/(G J_b)) and
  carries the same torque in every element; the rotor sees 1/k* = 1/k_s + 1/k_in and the shaft
  torque at ω is a T |k*/(k* − Jω² + icω)| (the single-DOF closed form derived there). The
  element torques are G J_k Δθ/L of each element with its own segment's J_k; the shaft's inertia
  perturbs them by ~J_s ω²/k ≈ 1e-9: tolerance 1e-7, as in tests/test_torsional.py.

Eight elements (0.25 m) on each model: statics and the massless spring are exact on any mesh.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.metal_strength import metal_strength
from flexshaft.analyses.response import static_response
from flexshaft.analyses.torsional import torsional_forced_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import design_from_dict

G_MOD = 26.0e9
TUBES = {"a": (0.06, 0.003), "b": (0.04, 0.002)}  # (outer diameter, wall) [m]
JOINT, LENGTH = 1.0, 2.0


def _polar(name: str) -> float:
    d_o, wall = TUBES[name]
    return np.pi * (d_o**4 - (d_o - 2 * wall) ** 4) / 32


def _design(density: float, extra: dict) -> dict:
    (d_a, t_a), (d_b, t_b) = TUBES["a"], TUBES["b"]
    data = {
        "name": "two tubes in series",
        "materials": {
            "al": {
                "kind": "isotropic",
                "E": 70.0e9,
                "G": G_MOD,
                "density": density,
                "loss_factor": 0.0,
                "yield_strength": 276e6,
                "ultimate_strength": 310e6,
                "fatigue_strength": 100e6,
            }
        },
        "shaft": {
            "x_start": 0.0,
            "x_end": LENGTH,
            "outer_diameter": d_a,
            "wall_thickness": t_a,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
            "segments": [
                {"name": "a", "x_start": 0.0, "x_end": JOINT},
                {"name": "b", "x_start": JOINT, "x_end": LENGTH, "outer_diameter": d_b, "wall_thickness": t_b},
            ],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": LENGTH, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 100.0e3},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 8},
    }
    data.update(extra)
    return data


def test_metal_check_takes_each_elements_own_tube_at_the_joint():
    torque = 500.0
    model = build_model(design_from_dict(_design(2700.0, {"operating": {"speed_rpm": 3000.0, "power": 0.0}})))
    q = static_response(model, point_load(model, "shaft", (0.0, 0.0, 0.0), (torque, 0.0, 0.0), x=LENGTH))
    result = metal_strength(model, q, buckling=False)
    mid = result.x.mean(axis=1)
    assert result.x.shape == (8, 2) and np.any(result.x[:, 0] == JOINT)  # an element starts at the joint
    for row, x_mid in enumerate(mid):
        name = "a" if x_mid < JOINT else "b"
        expected = torque * (TUBES[name][0] / 2) / _polar(name)
        assert result.segment[row] == name
        assert result.tau_mean[row] == pytest.approx(np.full(2, expected), rel=1e-9)


def test_torsional_response_of_a_massless_two_tube_shaft_is_the_series_spring():
    J_tr, n, k_in, c_tr, blades = 12.0, 3.4, 4.0e4, 30.0, 4
    rotor = {
        "blades": blades,
        "polar_inertia": J_tr,
        "gearbox_ratio": n,
        "input_stiffness": k_in,
        "aerodynamic_damping": c_tr,
        "torque_oscillation_1p": 0.05,
        "torque_oscillation_np": 0.1,
    }
    model = build_model(design_from_dict(_design(1e-2, {"tail_rotor": rotor})))
    response = torsional_forced_response(model)
    speed = model.speed
    T = 100.0e3 / speed
    k_s = 1.0 / (JOINT / (G_MOD * _polar("a")) + (LENGTH - JOINT) / (G_MOD * _polar("b")))
    k_star = 1.0 / (1.0 / k_s + 1.0 / k_in)
    J, c = J_tr / n**2, c_tr / n**2
    for harmonic, order, a in zip(response.harmonics, (1, blades), (0.05, 0.1)):
        w = order * speed / n
        expected = a * T * abs(k_star / (k_star - J * w * w + 1j * c * w))
        assert harmonic.torque == pytest.approx(expected, rel=1e-7)
    assert response.steady_shear_stress == pytest.approx(T * (TUBES["b"][0] / 2) / _polar("b"), rel=1e-12)
