"""Walls of unequal plies (ABD sums, transverse shear) and the ply's definiteness condition.

Unequal plies, derived here by hand from the definitions in :mod:`flexshaft.laminate`: a 0° ply of
t1 = 1 mm inside a 90° ply of t2 = 3 mm (total t = 4 mm) has its interfaces at
z = (-2, -1, +2) mm from the mid-surface, so (the sums as abd_matrices' docstring states them, derived here)

* A = Q0 t1 + Q90 t2,
* B = 1/2 [Q0 ((-1)^2 - (-2)^2) + Q90 (2^2 - (-1)^2)] mm^2 = 3/2 (Q90 - Q0) mm^2,
* D = 1/3 [Q0 ((-1)^3 - (-2)^3) + Q90 (2^3 - (-1)^3)] mm^3 = (7 Q0 + 9 Q90)/3 mm^3,

with Q0 = [[Q11, Q12, 0], [Q12, Q22, 0], [0, 0, G_LT]] (Q11 = E_L/(1 - nu_LT nu_TL),
Q22 = E_T/(1 - nu_LT nu_TL), Q12 = nu_LT E_T/(1 - nu_LT nu_TL), nu_TL = nu_LT E_T/E_L; Jones eq.
2.61) and Q90 the same with 1 and 2 swapped. The transverse shear stiffness A_ij = k sum Q_ij,k h_k
(Reddy 2004, eq. 3.3.9): the 0° ply has Q55 = G_13, Q44 = G_23, the 90° ply Q55 = G_23, Q44 = G_13,
so A55 = k (G_13 t1 + G_23 t2), A44 = k (G_23 t1 + G_13 t2), A45 = 0. Equal plies would put the
interface at z = 0 and weigh both plies by 2 mm; every number above differs from that.

Definiteness, derived here: the in-plane normal compliance block [[1/E_L, -nu_LT/E_L],
[-nu_LT/E_L, 1/E_T]] is positive definite iff its determinant 1/(E_L E_T) - nu_LT^2/E_L^2 > 0,
i.e. nu_LT^2 < E_L/E_T, i.e. nu_LT nu_TL < 1 (the denominator of Q), the bound the
:class:`flexshaft.laminate.Lamina` message states, |nu_LT| < sqrt(E_L/E_T). A ply with E_T = 4 E_L
has the bound 0.5, well inside the |nu_LT| < 1 of an isotropic-looking check.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.laminate import Lamina, Laminate, abd_matrices, reduced_stiffness, transverse_shear_stiffness

E_L, E_T, G_LT, NU_LT, G_13, G_23, K_SHEAR = 140.0e9, 9.0e9, 5.0e9, 0.3, 5.0e9, 3.0e9, 5.0 / 6.0
T1, T2 = 1.0e-3, 3.0e-3
MM = 1.0e-3

# Sums of two or three products of O(1e9) numbers: rounding a few ulp; 1e-12 relative leaves
# three orders of margin and is far below the tens-of-percent changes of a misplaced ply.
RTOL = 1e-12


def _lamina() -> Lamina:
    return Lamina(E_L, E_T, G_LT, NU_LT, 1500.0, G_13=G_13, G_23=G_23, shear_correction=K_SHEAR)


def _wall() -> Laminate:
    return Laminate(np.radians([0.0, 90.0]), np.array([T1, T2]), _lamina())


def _q0_q90() -> tuple[np.ndarray, np.ndarray]:
    nu_TL = NU_LT * E_T / E_L
    den = 1.0 - NU_LT * nu_TL
    Q11, Q22, Q12 = E_L / den, E_T / den, NU_LT * E_T / den
    Q0 = np.array([[Q11, Q12, 0.0], [Q12, Q22, 0.0], [0.0, 0.0, G_LT]])
    Q90 = np.array([[Q22, Q12, 0.0], [Q12, Q11, 0.0], [0.0, 0.0, G_LT]])
    return Q0, Q90


def test_interfaces_of_unequal_plies_sit_at_their_own_thicknesses():
    """z = (-2, -1, +2) mm for a 1 mm ply inside a 3 mm ply (exact binary fractions of t)."""
    np.testing.assert_allclose(_wall().z_interfaces, np.array([-2.0, -1.0, 2.0]) * MM, rtol=0.0, atol=1e-15)


def test_abd_of_unequal_plies_matches_the_hand_sums():
    """A = Q0 t1 + Q90 t2, B = 3/2 (Q90 - Q0) mm^2, D = (7 Q0 + 9 Q90)/3 mm^3 (module docstring).

    Entries that are zero by symmetry (the 16, 26 terms, up to cos 90° = 6e-17) are compared
    with an absolute tolerance 1e-12 of the largest entry.
    """
    Q0, Q90 = _q0_q90()
    A, B, D = (m.real for m in abd_matrices(_wall()))
    for got, expected in (
        (A, Q0 * T1 + Q90 * T2),
        (B, 1.5 * (Q90 - Q0) * MM**2),
        (D, (7.0 * Q0 + 9.0 * Q90) / 3.0 * MM**3),
    ):
        np.testing.assert_allclose(got, expected, rtol=RTOL, atol=RTOL * np.abs(expected).max())


def test_transverse_shear_stiffness_of_unequal_plies_weighs_each_by_its_thickness():
    """A55 = k (G_13 t1 + G_23 t2), A44 = k (G_23 t1 + G_13 t2), A45 = 0 (module docstring)."""
    As = transverse_shear_stiffness(_wall()).real
    A55, A44 = K_SHEAR * (G_13 * T1 + G_23 * T2), K_SHEAR * (G_23 * T1 + G_13 * T2)
    scale = max(A55, A44)
    np.testing.assert_allclose(As, [[A55, 0.0], [0.0, A44]], rtol=RTOL, atol=RTOL * scale)


@pytest.mark.parametrize("nu_LT", [0.501, 0.6, 0.9])
def test_a_ply_beyond_nu_squared_below_EL_over_ET_is_refused(nu_LT):
    """E_T = 4 E_L: the bound is |nu_LT| < 0.5; 0.501 (nu_LT nu_TL = 1.004) already indefinite."""
    with pytest.raises(ValueError, match="indefinite"):
        Lamina(10.0e9, 40.0e9, 4.0e9, nu_LT, 1500.0)


def test_a_ply_inside_the_bound_is_accepted_with_a_positive_definite_Q():
    """E_T = 4 E_L, nu_LT = 0.499: nu_LT nu_TL = 0.996 < 1, so Q is positive definite.

    Q11 = 2.5e12, Q22 = 1e13, Q12 = 4.995e12 Pa: the normal block's smaller eigenvalue is about
    det/trace = 1e23/1.25e13 = 8e9 Pa and Q66 = G_LT = 4e9 Pa, far above the rounding of a
    1e13 Pa matrix (about 1e-3 Pa), so the sign is certain.
    """
    Q = reduced_stiffness(Lamina(10.0e9, 40.0e9, 4.0e9, 0.499, 1500.0)).real
    assert np.linalg.eigvalsh(Q).min() > 0.0
