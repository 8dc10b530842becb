"""The thermal part of the critical point is the critical ply's own residual stress (derived here).

A [0/90] tube under a pure bend (v = a x², κ_v = 2a everywhere, the Hermite element exact) with
a prescribed residual stress per ply, ``residual_stress`` (n_ply, 3) [Pa] in material axes, a
fixed initial state the safety factor R does not scale: F(σ_T + R σ) = 1 (docs/model.md,
line 255). The residuals are chosen so that the two plies' rows differ in every component.

References used (none is a number the code produced):

* the reported thermal part ``stress_parts["thermal"]`` is, by the meaning of the input, the
  row of ``residual_stress`` of the reported critical ply, exactly (a copy: tolerance 0);
* the parts add up to the reported ply stress state (``stresses``, σ_T + Σ σ_j at the operating
  loads), round-off 1e-12 of the largest stress;
* at the failure state σ* = σ_T + R Σ σ_j the Tsai-Wu index is 1 by the definition of R, and
  the load shares, which split that index additively (Aumann-Shapley, module docstring "The
  shares sum to 1"), sum to 1; evaluated directly as F(σ*) from the strengths by hand here:
  F(σ*) = F₁σ₁ + F₂σ₂ + F₁₁σ₁² + F₂₂σ₂² + F₆₆τ² + 2F₁₂σ₁σ₂ (the criterion as stated in
  src/flexshaft/strength.py's docstring), with F₁₂ = −½√(F₁₁F₂₂). Tolerance 1e-9: the
  quadratic's root is well conditioned (the failure state is not near a tangency), round-off
  only.

The critical ply is the 90° ply (index 1): its transverse strength Y_t = 40 MPa, loaded by the
bend's axial strain at E_T, governs long before the 0° ply's fibres (X_c = 1000 MPa at E_L);
the test asserts it, since only a ply other than the first tells whose residual is used.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict

X1, D, WALL = 1.6, 0.1, 0.003
X_T, X_C, Y_T, Y_C, S = 2000.0e6, 1000.0e6, 40.0e6, 140.0e6, 60.0e6
RESIDUAL = np.array([[-12.0e6, 3.0e6, 1.5e6], [6.0e6, 9.0e6, -2.0e6]])  # rows: 0° ply, 90° ply


def _tsai_wu_index(s1, s2, t12):
    f1, f2 = 1 / X_T - 1 / X_C, 1 / Y_T - 1 / Y_C
    f11, f22, f66 = 1 / (X_T * X_C), 1 / (Y_T * Y_C), 1 / S**2
    f12 = -0.5 * np.sqrt(f11 * f22)
    return f1 * s1 + f2 * s2 + f11 * s1**2 + f22 * s2**2 + f66 * t12**2 + 2 * f12 * s1 * s2


@pytest.fixture(scope="module")
def cross_ply():
    ply = {"kind": "lamina", "density": 1600.0, "E_L": 120.0e9, "E_T": 8.0e9, "G_LT": 4.0e9, "nu_LT": 0.3}
    data = {
        "name": "[0/90] tube",
        "materials": {"ply": {**ply, "X_t": X_T, "X_c": X_C, "Y_t": Y_T, "Y_c": Y_C, "S": S}},
        "shaft": {
            "x_start": 0.0,
            "x_end": X1,
            "outer_diameter": D,
            "wall_thickness": WALL,
            "material": "ply",
            "layup": "0/90",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "stop", "kind": "contact", "x": X1, "stiffness": {}}],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 4},
    }
    return build_model(design_from_dict(data))


def _bend(model, a: float) -> np.ndarray:
    """q of v = a x² (γ = v' = 2 a x): κ_v = 2a at every element end."""
    x = np.asarray(model.dofs.shaft_x, dtype=float)
    q = np.zeros(model.dofs.size)
    for node, xn in enumerate(x):
        q[model.dofs.shaft(node, "v")] = a * xn**2
        q[model.dofs.shaft(node, "gamma")] = 2 * a * xn
    return q


def test_the_thermal_part_is_the_critical_plys_residual_and_the_shares_sum_to_one(cross_ply):
    result = shaft_safety_factor(cross_ply, {"bend": _bend(cross_ply, 1.0e-3)}, speed=0.0, residual_stress=RESIDUAL)
    assert result.ply == 1  # the 90° ply (module docstring)
    assert np.isfinite(result.safety_factor) and result.safety_factor > 0
    np.testing.assert_array_equal(result.stress_parts["thermal"], RESIDUAL[result.ply])
    total = np.sum([result.stress_parts[name] for name in result.stress_parts], axis=0)
    np.testing.assert_allclose(total, result.stresses, rtol=0, atol=1e-12 * np.max(np.abs(result.stresses)))
    failure = RESIDUAL[result.ply] + result.safety_factor * (np.array(result.stresses) - RESIDUAL[result.ply])
    assert _tsai_wu_index(*failure) == pytest.approx(1.0, rel=1e-9)
    assert sum(result.load_shares.values()) == pytest.approx(1.0, rel=1e-9)
    assert set(result.load_shares) == {"bend", "thermal"}
