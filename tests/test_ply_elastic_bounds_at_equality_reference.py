"""The design file's ply refused exactly on its positive-definiteness bounds, not only beyond them.

Restrictions on the elastic constants of an orthotropic material (as quoted from Jones,
*Mechanics of Composite Materials*, 2nd ed., 1999, in tests/test_lamina_and_layup_reference.py;
Δ is the determinant of the normal compliance times E_1 E_2 E_3, derived): the compliance is
positive definite only when

* in the plane, 1 − ν_12 ν_21 > 0, i.e. |ν_12| < sqrt(E_1/E_2) (with ν_21 = ν_12 E_2/E_1);
* in three dimensions, Δ = 1 − ν_12ν_21 − ν_23ν_32 − ν_31ν_13 − 2ν_21ν_32ν_13 > 0.

The inequalities are strict: on the bound the compliance is singular (Δ = 0), a ply with a
zero-energy strain, so a design at the bound must be refused like one beyond it. The numbers
are chosen so that every quantity, and every intermediate of the module's bound arithmetic, is
a binary floating-point number, so "at the bound" is exactly at it; the bounds are derived
here in exact rational arithmetic (:class:`fractions.Fraction`), Δ = 0 is checked there, and
the float given to the ply is asserted equal to the exact value:

* ν_23 bound of a transversely isotropic ply (ν_13 = ν_12 = ν_LT, ν_32 = ν_23): E_T = 255·2²⁵
  Pa, E_L = 16 E_T, ν_LT = 1/4 give ν_TL = ν_LT E_T/E_L = 1/64 and Δ = (1 + ν_23)(1 − ν_23 −
  2 ν_LT ν_TL) = 0 at ν_23 = 1 − 1/128 = 127/128, i.e. G_23 = E_T/(2 (1 + ν_23)) =
  E_T/(4 (1 − ν_LT ν_TL)) = 64 E_T/255 = 2³¹ Pa;
* ν_LT bound: E_L = 8 GPa, E_T = 32 GPa give sqrt(E_L/E_T) = 1/2, and ν_LT = 1/2 gives
  ν_TL = 2, 1 − ν_LT ν_TL = 0.

A value a relative 1e-9 inside each bound is accepted (the check is not wider than the bound).
CPU: well under 10 ms.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from flexshaft.design.materials import Lamina

STRENGTHS = {"X_t": 2.0e9, "X_c": 1.0e9, "Y_t": 40.0e6, "Y_c": 140.0e6, "S": 60.0e6}


def _ply(E_L: float, E_T: float, nu_LT: float, **extra) -> Lamina:
    return Lamina(kind="lamina", density=1600.0, E_L=E_L, E_T=E_T, G_LT=4.0e9, nu_LT=nu_LT, **STRENGTHS, **extra)


def _jones_determinant(nu_12: Fraction, nu_21: Fraction, nu_23: Fraction) -> Fraction:
    """Δ of Jones (1999) for a transversely isotropic ply: ν_13 = ν_12, ν_31 = ν_21, ν_32 = ν_23."""
    nu_13, nu_31, nu_32 = nu_12, nu_21, nu_23
    return 1 - nu_12 * nu_21 - nu_23 * nu_32 - nu_31 * nu_13 - 2 * nu_21 * nu_32 * nu_13


def test_g23_exactly_on_the_positive_definite_bound_is_refused():
    E_T = Fraction(255 * 2**25)  # Pa
    E_L, nu_LT = 16 * E_T, Fraction(1, 4)
    nu_TL = nu_LT * E_T / E_L
    assert nu_TL == Fraction(1, 64)
    nu_23 = 1 - 2 * nu_LT * nu_TL
    assert _jones_determinant(nu_LT, nu_TL, nu_23) == 0  # singular compliance
    G_23 = E_T / (2 * (1 + nu_23))
    assert G_23 == E_T / (4 * (1 - nu_LT * nu_TL)) == 2**31
    assert Fraction(float(G_23)) == G_23 and Fraction(float(E_T)) == E_T  # exact in binary
    with pytest.raises(ValueError, match="G_23"):
        _ply(float(E_L), float(E_T), float(nu_LT), G_23=float(G_23))
    inside = float(G_23) * (1.0 + 1e-9)
    assert _ply(float(E_L), float(E_T), float(nu_LT), G_23=inside).G_23 == inside


def test_nu_lt_exactly_sqrt_el_over_et_is_refused():
    E_L, E_T = 8.0e9, 32.0e9
    nu_LT = Fraction(1, 2)
    assert 1 - nu_LT * (nu_LT * Fraction(32, 8)) == 0  # 1 - nu_LT nu_TL: singular in the plane
    with pytest.raises(ValueError, match="nu_LT"):
        _ply(E_L, E_T, float(nu_LT))
    assert _ply(E_L, E_T, 0.5 * (1.0 - 1e-9)).nu_LT == 0.5 * (1.0 - 1e-9)
