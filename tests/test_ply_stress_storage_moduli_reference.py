"""Ply stresses of an orthotropic ply with unequal loss factors come from the storage moduli alone.

Reference: the strength check takes the ply stresses from the storage (real) moduli (laminate.py,
thesis eq. 2.47; docs/model.md, forced response and strength). In the ply axes the plane-stress
reduced stiffness of the storage moduli is (Jones 1999, eq. 2.61)

    Q11 = E_L/Δ,  Q22 = E_T/Δ,  Q12 = ν_LT E_T/Δ,  Q66 = G_LT,   Δ = 1 − ν_LT² E_T/E_L,

so σ1 = Q11 ε1 + Q12 ε2, σ2 = Q12 ε1 + Q22 ε2, τ12 = G_LT γ12. The strains of a [0/90] stack
are written by hand: the 0° ply has (ε1, ε2, γ12) = (ε_x, ε_y, γ_xy), the 90° ply
(ε_y, ε_x, −γ_xy) (Jones eq. 2.87 with cos θ = 0, sin θ = 1: the engineering shear strain
changes sign).

The ply's loss factors are far apart (η_L = 0.01, η_T = 0.3, η_G = 0.1): the real part of Q
built from the complex moduli is not Q of the storage moduli, because Δ of complex moduli is
complex (Re[E_T*/Δ*] differs from E_T/Δ by about ν_LT ν_TL η_T² ≈ 5e-4 relative here), so taking
Re Q(E*) in place of Q(Re E*) is seen at the tolerance below.

Tolerance 1e-12 of the largest stress. Basis: a few products of decimal inputs; the 90° ply
carries cos(π/2) ≈ 6e-17 in its transformation, which moves its stresses by less than 1e-15
of the largest.
"""

from __future__ import annotations

import numpy as np

from flexshaft.laminate import Lamina, Laminate, ply_stresses

E_L, E_T, G_LT, NU = 120e9, 8e9, 4e9, 0.3
EPS_X, EPS_Y, GAMMA = 1e-3, -2e-4, 5e-4


def _expected(e1, e2, g12):
    delta = 1.0 - NU**2 * E_T / E_L
    q11, q22, q12 = E_L / delta, E_T / delta, NU * E_T / delta
    return np.array([q11 * e1 + q12 * e2, q12 * e1 + q22 * e2, G_LT * g12])


def test_cross_ply_stresses_use_the_storage_moduli_of_a_lossy_orthotropic_ply():
    lamina = Lamina.from_loss_factors(E_L, E_T, G_LT, NU, 1500.0, 0.01, 0.3, 0.1)
    laminate = Laminate(np.radians([0.0, 90.0]), np.array([0.001, 0.001]), lamina)
    stresses = ply_stresses(laminate, EPS_X, EPS_Y, GAMMA)
    expected = np.array([_expected(EPS_X, EPS_Y, GAMMA), _expected(EPS_Y, EPS_X, -GAMMA)])
    assert stresses.shape == (2, 3)
    assert np.all(np.abs(stresses - expected) <= 1e-12 * np.abs(expected).max())
