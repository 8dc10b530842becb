"""What :func:`shaft_safety_factor` reports about its critical ply, by hand.

Tube and fields of tests/test_shaft_strength_fields_reference.py (a lamina with
Y_t = 40, Y_c = 140, S = 60 MPa; a twist θ = k x gives γ_xy = r_o k at every element end).

* **The dominant stress is read at the failure state** (``dominant_stress``: the largest of
  Tsai-Wu's parts H₁, H₂, H₆ at failure, thesis eq. 2.48-2.53). A [0] ply under a twist carries
  τ₁₂ = G_LT r_o k only (one 0° ply: no shear-extension coupling); with a residual σ₂ = 10 MPa
  (a fixed state R does not scale) the failure state is σ₂ = 10 MPa, τ* = Rτ, where
  F₂σ₂ + F₂₂σ₂² + τ*²/S² = 1 with F₂ = 1/Y_t − 1/Y_c, F₂₂ = 1/(Y_t Y_c):
  H₂ = 0.1964 and H₆ = 0.8036, so τ₁₂ dominates, R = S√H₆/τ. At the operating twist
  (τ = 1 MPa) the residual's H₂ would dominate instead: the check is not vacuous.
* **The critical ply's angle is reported in degrees**: a single ply at +30° under a twist.

Tolerance: algebra on an element that is exact for the field: rel 1e-9.

Written for the mutations h43d-strength-dominant-at-operating-loads and
h43d-strength-ply-angle-in-radians of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_shaft_strength_fields_reference import G_LT, R_O, Y_C, Y_T, S, _field, _tube

from flexshaft.analyses.shaft_strength import shaft_safety_factor, shaft_strengths
from flexshaft.strength import dominant_stress


def test_the_dominant_stress_is_that_of_the_failure_state():
    model = _tube("0")
    tau = 1.0e6
    k = tau / (G_LT * R_O)
    sigma2 = 10.0e6
    residual = np.array([[0.0, sigma2, 0.0]])
    result = shaft_safety_factor(model, _field(model, k=k), speed=0.0, residual_stress=residual)
    F2, F22 = 1 / Y_T - 1 / Y_C, 1 / (Y_T * Y_C)
    H2 = F2 * sigma2 + F22 * sigma2**2
    H6 = 1.0 - H2
    assert H6 > H2
    assert result.safety_factor == pytest.approx(S * np.sqrt(H6) / tau, rel=1e-9)
    assert result.dominant_stress == "tau12"
    # at the operating twist the residual's part would be the larger one
    assert str(dominant_stress(0.0, sigma2, tau, shaft_strengths(model)[1])) == "sigma2"


def test_the_critical_plys_angle_is_in_degrees():
    model = _tube("30")
    result = shaft_safety_factor(model, _field(model, k=2.0e-3), speed=0.0, thermal_residual=False)
    assert result.ply_angle_deg == pytest.approx(30.0, rel=1e-12)
    assert "(+30°)" in result.critical_description
