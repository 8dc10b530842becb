"""Ply stresses of an orthotropic ply with unequal loss factors come from the storage moduli alone.

Reference: the strength check takes the ply stresses from the storage (real) moduli (laminate.py,
thesis eq. 2.47; docs/model.md, forced response and strength). In the ply axes the plane-stress
reduced stiffness of the storage moduli is (Jones 1999, eq. 2.61)

    Q11 = E_L/Δ,  Q22 = E_T/Δ,  Q12 = ν_LT E_T/Δ,  Q66 = G_LT,   Δ = 1 − ν_LT² E_T/E_L,

so σ1 = Q11 ε1 + Q12 ε2, σ2 = Q12 ε1 + Q22 ε2, τ12 = G_LT γ12. The strains of a [0/90] stack
are written by hand: the 0° ply has (ε1, ε2, γ12) = (ε_x, ε_y, γ_xy), the 90° ply
(ε_y, ε_x, −γ_xy) (the strain transformation to ply axes with cos θ = 0, sin θ = 1: the
engineering shear strain changes sign).

The ply's loss factors are far apart (η_L = 0.01, η_T = 0.3, η_G = 0.1): the real part of Q
built from the complex moduli is not Q of the storage moduli, because Δ of complex moduli is
complex (Re[E_T*/Δ*] differs from E_T/Δ by about ν_LT ν_TL η_T² ≈ 5e-4 relative here), so taking
Re Q(E*) in place of Q(Re E*) is seen at the tolerance below.

The same holds for the strains the strength check builds before the stresses: the free hoop
strain (N_y = 0) and the membrane strains under given resultants use A of the storage moduli.
For one hoop ply (θ = 90°: the laminate's x is the ply's transverse direction) the storage
compliance gives by hand (the ply compliance turned by 90°, the ply's axes swapped:
S̄11 = S22 = 1/E_T, S̄12 = S12 = −ν_LT/E_L, S̄66 = S66 = 1/G_LT)

    free hoop strain    ε_y = −ν_TL ε_x,  ν_TL = ν_LT E_T/E_L
    N = (N_x, 0, 0):    (ε_x, ε_y, γ_xy) = (N_x/(t E_T), −ν_LT N_x/(t E_L), 0)

while Re A(E*) moves both by about 5e-4 relative (η_T = 0.3 against η_L = 0.01).

Tolerance 1e-12 of the largest stress (strain). Basis: a few products of decimal inputs; the 90° ply
carries cos(π/2) ≈ 6e-17 in its transformation, which moves its stresses by less than 1e-15
of the largest; the strains are one 3×3 solve of a matrix of condition number ≈ E_L/G_LT = 30.
"""

from __future__ import annotations

import numpy as np

from flexshaft.laminate import Lamina, Laminate, hoop_strain_free, membrane_strains, ply_stresses

E_L, E_T, G_LT, NU = 120e9, 8e9, 4e9, 0.3
EPS_X, EPS_Y, GAMMA = 1e-3, -2e-4, 5e-4


def _expected(e1, e2, g12):
    delta = 1.0 - NU**2 * E_T / E_L
    q11, q22, q12 = E_L / delta, E_T / delta, NU * E_T / delta
    return np.array([q11 * e1 + q12 * e2, q12 * e1 + q22 * e2, G_LT * g12])


def _lamina():
    return Lamina.from_loss_factors(E_L, E_T, G_LT, NU, 1500.0, 0.01, 0.3, 0.1)


def test_cross_ply_stresses_use_the_storage_moduli_of_a_lossy_orthotropic_ply():
    laminate = Laminate(np.radians([0.0, 90.0]), np.array([0.001, 0.001]), _lamina())
    stresses = ply_stresses(laminate, EPS_X, EPS_Y, GAMMA)
    expected = np.array([_expected(EPS_X, EPS_Y, GAMMA), _expected(EPS_Y, EPS_X, -GAMMA)])
    assert stresses.shape == (2, 3)
    assert np.all(np.abs(stresses - expected) <= 1e-12 * np.abs(expected).max())


def test_free_hoop_strain_of_a_hoop_ply_is_the_storage_minor_poisson_ratio():
    hoop_ply = Laminate(np.radians([90.0]), np.array([0.002]), _lamina())
    nu_tl = NU * E_T / E_L
    assert abs(hoop_strain_free(hoop_ply, EPS_X, 0.0) - (-nu_tl * EPS_X)) <= 1e-12 * nu_tl * EPS_X


def test_membrane_strains_of_a_hoop_ply_use_the_storage_compliance():
    thickness, n_x = 0.002, 1.0e5
    hoop_ply = Laminate(np.radians([90.0]), np.array([thickness]), _lamina())
    strains = membrane_strains(hoop_ply, [n_x, 0.0, 0.0])
    expected = np.array([n_x / (thickness * E_T), -NU * n_x / (thickness * E_L), 0.0])
    assert np.all(np.abs(strains - expected) <= 1e-12 * np.abs(expected).max())
