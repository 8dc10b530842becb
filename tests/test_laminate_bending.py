"""Bending stiffness D and coupling B of classical lamination theory against closed forms.

References (derived here):

* an isotropic plate of thickness t: A11 = E t/(1 − ν²), D11 = E t³/(12(1 − ν²)), D12 = ν D11,
  D66 = G t³/12 (Kirchhoff plate), B = 0;
* a symmetric cross-ply [0/90]s of four plies of thickness h (z = −2h … 2h): the outer 0° plies
  carry Q11 over ∫z² dz = 2((2h)³ − h³)/3 = 14h³/3 and the inner 90° plies Q22 over 2h³/3, so
  D11 = (14 Q11 + 2 Q22) h³/3 and D22 = (14 Q22 + 2 Q11) h³/3, while A11 = A22 = 2h(Q11 + Q22);
* an unsymmetric [0/90] pair of plies of thickness h: B11 = (Q22 − Q11) h²/2 (the 0° ply below
  the mid-plane, ∫z dz = −h²/2, the 90° ply above, +h²/2), B22 = −B11.

Q11, Q22 are the ply's reduced stiffnesses (Jones eq. 2.61, checked in tests/test_laminate.py);
the z-weights are the integrals above. Equalities to round-off (1e-12).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.laminate import Lamina, Laminate, abd_matrices, reduced_stiffness

E, G = 70e9, 26e9
NU = E / (2 * G) - 1


def test_isotropic_plate_bending_stiffness():
    t = 3e-3
    lam = Laminate.from_layup("(0/45/-45/90)s", t, Lamina.isotropic(E, G, 2700.0))
    A, B, D = (m.real for m in abd_matrices(lam))
    D11 = E * t**3 / (12 * (1 - NU**2))
    assert A[0, 0] == pytest.approx(E * t / (1 - NU**2), rel=1e-12)
    assert D[0, 0] == pytest.approx(D11, rel=1e-12)
    assert D[1, 1] == pytest.approx(D11, rel=1e-12)
    assert D[0, 1] == pytest.approx(NU * D11, rel=1e-12)
    assert D[2, 2] == pytest.approx(G * t**3 / 12, rel=1e-12)
    assert np.abs(B).max() <= 1e-12 * np.abs(A).max() * t


def test_cross_ply_bending_stiffness_weights_the_outer_plies():
    lamina = Lamina(E_L=140e9, E_T=10e9, G_LT=5e9, nu_LT=0.3, density=1600.0)
    h = 0.25e-3
    lam = Laminate(np.radians([0.0, 90.0, 90.0, 0.0]), np.full(4, h), lamina)
    Q = reduced_stiffness(lamina).real
    A, B, D = (m.real for m in abd_matrices(lam))
    assert D[0, 0] == pytest.approx((14 * Q[0, 0] + 2 * Q[1, 1]) * h**3 / 3, rel=1e-12)
    assert D[1, 1] == pytest.approx((14 * Q[1, 1] + 2 * Q[0, 0]) * h**3 / 3, rel=1e-12)
    assert A[0, 0] == pytest.approx(2 * h * (Q[0, 0] + Q[1, 1]), rel=1e-12)
    assert A[1, 1] == pytest.approx(A[0, 0], rel=1e-12)
    assert np.abs(B).max() <= 1e-12 * np.abs(D).max() / h


def test_unsymmetric_pair_has_the_closed_form_coupling():
    lamina = Lamina(E_L=140e9, E_T=10e9, G_LT=5e9, nu_LT=0.3, density=1600.0)
    h = 0.5e-3
    lam = Laminate(np.radians([0.0, 90.0]), np.full(2, h), lamina)  # inner 0°, outer 90°
    Q = reduced_stiffness(lamina).real
    _, B, _ = (m.real for m in abd_matrices(lam))
    assert B[0, 0] == pytest.approx((Q[1, 1] - Q[0, 0]) * h**2 / 2, rel=1e-12)
    assert B[1, 1] == pytest.approx(-B[0, 0], rel=1e-12)
