"""Tsai-Wu with the Tsai-Hahn interaction term reduces to von Mises for an isotropic ply.

Reference (derived here): with equal strengths in tension and compression along and across the
fibres (X_t = X_c = Y_t = Y_c = σ_y) the linear terms vanish, F11 = F22 = 1/σ_y², and the default
interaction F12 = −½√(F11 F22) = −1/(2σ_y²) (Tsai & Hahn). With S = σ_y/√3 (F66 = 3/σ_y²) the
Tsai-Wu index becomes (σ1² − σ1σ2 + σ2² + 3τ12²)/σ_y², the plane-stress von Mises criterion, so
the safety factor is R = σ_y/σ_vm for any plane stress state. A factor on F12, F66 or in the
root of the quadratic breaks the equality for a general state; 1e-12 relative is asserted
(closed-form arithmetic). With unequal tension and compression strengths, a uniaxial stress
reaches R = 1 exactly at its own strength (the linear terms), in either sign.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.strength import Strengths, tsai_wu_index, tsai_wu_safety_factor

SY = 250e6


def von_mises(s1, s2, t12):
    return np.sqrt(s1**2 - s1 * s2 + s2**2 + 3 * t12**2)


def test_isotropic_tsai_wu_is_von_mises():
    strengths = Strengths(SY, SY, SY, SY, SY / np.sqrt(3.0))
    rng = np.random.default_rng(7)
    s1, s2, t12 = rng.normal(scale=100e6, size=(3, 200))
    R = tsai_wu_safety_factor(s1, s2, t12, strengths)
    assert R == pytest.approx(SY / von_mises(s1, s2, t12), rel=1e-12)
    assert tsai_wu_index(s1, s2, t12, strengths) == pytest.approx(von_mises(s1, s2, t12) ** 2 / SY**2, rel=1e-12)
    # equal biaxial tension: σ_vm = σ, so R = σ_y/σ (the interaction term cancels half of a + b)
    assert float(tsai_wu_safety_factor(100e6, 100e6, 0.0, strengths)) == pytest.approx(2.5, rel=1e-12)
    # pure shear at the shear strength fails exactly
    assert float(tsai_wu_safety_factor(0.0, 0.0, SY / np.sqrt(3.0), strengths)) == pytest.approx(1.0, rel=1e-12)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_uniaxial_stress_at_each_strength_fails_exactly(sign):
    s = Strengths(X_t=2000e6, X_c=1200e6, Y_t=50e6, Y_c=150e6, S=70e6)
    X = s.X_t if sign > 0 else s.X_c
    Y = s.Y_t if sign > 0 else s.Y_c
    assert float(tsai_wu_safety_factor(sign * X, 0.0, 0.0, s)) == pytest.approx(1.0, rel=1e-12)
    assert float(tsai_wu_safety_factor(0.0, sign * Y, 0.0, s)) == pytest.approx(1.0, rel=1e-12)
    # half the strength is not a safety factor of 2 when X_t ≠ X_c (the linear term), but the
    # failure load is still found: R σ reaches the envelope
    R = float(tsai_wu_safety_factor(sign * X / 2, 0.0, 0.0, s))
    assert float(tsai_wu_index(sign * X / 2 * R, 0.0, 0.0, s)) == pytest.approx(1.0, rel=1e-12)
