"""The design file's ply: default transverse shear moduli, the G_23 bound, units; the layup pairs.

* Transversely isotropic ply (isotropic in the 2-3 plane across the fibres): G_13 = G_12 = G_LT
  and G_23 = E_T/(2 (1 + ν_23)), with the default ν_23 = 0.5 giving E_T/3 (docstring of
  :class:`flexshaft.design.materials.Lamina`).
* Positive definiteness of its compliance (the determinant condition 1 − ν_12ν_21 − ν_23ν_32 −
  ν_31ν_13 − 2ν_21ν_32ν_13 > 0 of Jones, *Mechanics of Composite Materials*, 2nd ed., 1999,
  restrictions on the elastic constants) with ν_13 = ν_12, ν_32 = ν_23 factors as
  (1 + ν_23)(1 − ν_23 − 2ν_LTν_TL) > 0, ν_TL = ν_LT E_T/E_L (reciprocity), i.e.
  G_23 > E_T/(4 (1 − ν_LT ν_TL)): a G_23 0.1 % below the bound is refused, 0.1 % above accepted.
* The design writes temperatures in °C and angles in degrees; the SI properties are K and rad.
* '-/+θ', '-+θ' and '∓θ' are the pair −θ/+θ ('±θ' is +θ/−θ, tests/test_laminate.py).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.design.layup import parse_layup
from flexshaft.design.materials import Lamina

E_L, E_T, G_LT, NU_LT = 120.0e9, 8.0e9, 4.0e9, 0.3
PLY = {
    "kind": "lamina",
    "density": 1600.0,
    "E_L": E_L,
    "E_T": E_T,
    "G_LT": G_LT,
    "nu_LT": NU_LT,
    "X_t": 2.0e9,
    "X_c": 1.0e9,
    "Y_t": 40.0e6,
    "Y_c": 140.0e6,
    "S": 60.0e6,
}


def test_default_transverse_shear_moduli_of_a_transversely_isotropic_ply():
    """(G_13, G_23) = (G_LT, E_T/(2 · 1.5)); given values are kept."""
    assert Lamina(**PLY).transverse_shear_moduli == pytest.approx((G_LT, E_T / 3.0), rel=1e-15)
    given = Lamina(**PLY, G_13=3.0e9, G_23=2.5e9)
    assert given.transverse_shear_moduli == (3.0e9, 2.5e9)


def test_g23_must_keep_the_ply_compliance_positive_definite():
    """Bound E_T/(4 (1 − ν_LT² E_T/E_L)) = 2.0121 GPa here."""
    bound = E_T / (4.0 * (1.0 - NU_LT * NU_LT * E_T / E_L))
    assert Lamina(**PLY).nu_TL == pytest.approx(NU_LT * E_T / E_L, rel=1e-15)
    Lamina(**PLY, G_23=1.001 * bound)
    with pytest.raises(ValueError, match="G_23"):
        Lamina(**PLY, G_23=0.999 * bound)


def test_stress_free_temperature_in_kelvin_and_misalignment_in_radians():
    """100 °C = 373.15 K; 2° = π/90 rad (the defaults) and a given 3°."""
    ply = Lamina(**PLY)
    assert ply.stress_free_temperature == pytest.approx(373.15, rel=1e-15)
    assert ply.fibre_misalignment == pytest.approx(math.pi / 90.0, rel=1e-15)
    assert Lamina(**PLY, fibre_misalignment_deg=3.0).fibre_misalignment == pytest.approx(math.pi / 60.0, rel=1e-15)


@pytest.mark.parametrize("text", ["-/+45", "-+45", "∓45"])
def test_a_minus_plus_pair_starts_with_the_negative_angle(text):
    assert parse_layup(text) == (-45.0, 45.0)
    assert parse_layup(f"({text})s") == (-45.0, 45.0, 45.0, -45.0)
