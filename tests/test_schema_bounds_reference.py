"""The design schema's physical bounds and derived quantities, derived by hand.

Ply (:class:`flexshaft.design.materials.Lamina`):

* **Major Poisson ratio.** Positive definiteness of the in-plane compliance needs
  1 − ν_LT ν_TL > 0 with ν_TL = ν_LT E_T/E_L (reciprocity; Jones, *Mechanics of Composite
  Materials*, 2nd ed., 1999, restrictions on the elastic constants), i.e. ν_LT < √(E_L/E_T). With
  E_L/E_T = 16 the bound is 4: ν_LT = 0.45 (any carbon ply) is accepted; the minor ratio's bound
  √(E_T/E_L) = 0.25 would refuse it. With E_T = 4 E_L (the schema allows it) the bound is ½:
  ν_LT = 0.6 is refused (the inverted bound, 2, would accept it).
* **G_23 bound** E_T/(4 (1 − ν_LT ν_TL)) (tests/test_lamina_and_layup_reference.py derives it);
  here with a strongly coupled ply (ν_LT = 0.9, E_L = E_T: ν_LT ν_TL = 0.81) the bound is
  E_T/0.76, 5.3x the uncoupled E_T/4: a G_23 = E_T/2 (between them) must be refused.
* **Tsai-Wu closure** |F12| < √(F11 F22), F11 = 1/(X_t X_c), F22 = 1/(Y_t Y_c) (Tsai & Wu 1971:
  F11 F22 − F12² > 0 for a closed ellipsoid): F12 = ±0.9 √(F11 F22) is accepted (both signs
  close the envelope), ±1.1 √(F11 F22) refused; 0.9 exceeds the default's ½.
* **Expansion coefficients** within ±1e-3 1/K: −2e-3 1/K (a negative value off by a unit
  factor) is refused like +2e-3.

Metal (:class:`flexshaft.design.materials.Isotropic`): ν = E/(2G) − 1 must stay below 0.5 (the
shell formulas divide by 1 − 2ν): E = 3e9, G = 1e9 gives ν = 0.5 exactly (both in binary),
refused; G = 1.01e9 accepted. A yield or fatigue strength above the ultimate strength is refused
(the fatigue strength of a part at its design life is at most its static ultimate strength);
equal is accepted.

Active bearing (:class:`flexshaft.design.bearings`):

* **Filtered PID** C(s) = k_p + K_I/s + k_d s/(1 + s/ω_d), ω_d = 2π f_d (docstring of
  ActiveBearing): over s (1 + s/ω_d) the numerator is (k_d + k_p/ω_d) s² + (k_p + K_I/ω_d) s
  + K_I, expanded here by hand; checked by evaluating the returned fraction at a few s.
* **Properness.** A controller (b_0 s² + b_1 s + b_2)/(s + a) with b_0 = 0 has degree 1 (its
  leading zero dropped) and is accepted over a degree-1 denominator (biproper: a lead filter);
  (1, 2, 3)/(1, 1) (degree 2 over 1) is refused.
* **Magnet geometry.** ``coil_turns`` alone asks for the geometry, which then lacks
  ``bias_current``, ``air_gap``, ``pole_area``: refused (not silently the ideal magnet).

Contact bearing and mount (docstrings of the bearing classes): a direction omitted from
``stiffness`` or ``damping`` is free (0); the damping of a direction is the ``damping`` table's,
not its stiffness; the boom station is ``x_boom`` when given, else ``x``.

Written for the h26a-materials-* and h26a-bearings-* mutations of scripts/mutations.toml. Only
schema objects, no model: a few ms. Comparisons of a few operations on numbers of order 1 to 1e7:
relative 1e-12.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.design.bearings import ActiveBearing, ContactBearing, Controller
from flexshaft.design.materials import Isotropic, Lamina

X_T, X_C, Y_T, Y_C = 2.0e9, 1.0e9, 40.0e6, 140.0e6
PLY = {
    "kind": "lamina",
    "density": 1600.0,
    "E_L": 128.0e9,
    "E_T": 8.0e9,
    "G_LT": 4.0e9,
    "nu_LT": 0.3,
    "X_t": X_T,
    "X_c": X_C,
    "Y_t": Y_T,
    "Y_c": Y_C,
    "S": 60.0e6,
}


def test_major_poisson_ratio_is_bounded_by_the_root_of_the_moduli_ratio():
    Lamina(**{**PLY, "nu_LT": 0.45})  # sqrt(E_L/E_T) = 4
    stiff_across = {**PLY, "E_L": 8.0e9, "E_T": 32.0e9}  # sqrt(E_L/E_T) = 1/2
    Lamina(**{**stiff_across, "nu_LT": 0.49})
    with pytest.raises(ValueError, match="nu_LT"):
        Lamina(**{**stiff_across, "nu_LT": 0.6})


def test_g23_bound_carries_the_in_plane_poisson_coupling():
    e_t = 8.0e9
    coupled = {**PLY, "E_L": e_t, "E_T": e_t, "nu_LT": 0.9}  # nu_LT nu_TL = 0.81
    bound = e_t / (4.0 * (1.0 - 0.81))  # E_T / 0.76
    Lamina(**coupled, G_23=1.001 * bound)
    with pytest.raises(ValueError, match="G_23"):
        Lamina(**coupled, G_23=e_t / 2.0)  # above E_T/4, below E_T/0.76


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_tsai_wu_interaction_closes_the_envelope_either_sign(sign):
    root = math.sqrt(1.0 / (X_T * X_C) * 1.0 / (Y_T * Y_C))  # sqrt(F11 F22)
    Lamina(**PLY, F12=sign * 0.9 * root)
    with pytest.raises(ValueError, match="F12"):
        Lamina(**PLY, F12=sign * 1.1 * root)


@pytest.mark.parametrize("name", ["alpha_L", "alpha_T"])
@pytest.mark.parametrize("value", [2.0e-3, -2.0e-3])
def test_expansion_coefficients_outside_a_thousandth_per_kelvin_are_refused(name, value):
    Lamina(**{**PLY, name: 0.9e-3 if value > 0 else -0.9e-3})
    with pytest.raises(ValueError, match=name):
        Lamina(**{**PLY, name: value})


def test_incompressible_metal_is_refused():
    assert Isotropic(kind="isotropic", E=3.0e9, G=1.01e9, density=7800.0).poisson_ratio == pytest.approx(
        3.0 / 2.02 - 1.0, rel=1e-12
    )
    with pytest.raises(ValueError, match="Poisson"):
        Isotropic(kind="isotropic", E=3.0e9, G=1.0e9, density=7800.0)  # nu = 0.5 exactly


def _value(coefficients, s):
    return sum(c * s ** (len(coefficients) - 1 - k) for k, c in enumerate(coefficients))


def test_filtered_pid_keys_give_the_law_over_one_denominator():
    kp, kd, ki, fd = 2.0e6, 900.0, 3.0e7, 400.0
    bearing = ActiveBearing(kind="active", name="amb", x=0.5, kp=kp, kd=kd, integral_gain=ki, derivative_cutoff=fd)
    num, den = bearing.transfer_function()
    wd = 2.0 * math.pi * fd
    assert num == pytest.approx((kd + kp / wd, kp + ki / wd, ki), rel=1e-12)  # expanded by hand
    for s in (1j * 50.0, 1j * wd, -30.0 + 400.0j, 1j * 1.0e5):
        assert _value(num, s) / _value(den, s) == pytest.approx(kp + ki / s + kd * s / (1.0 + s / wd), rel=1e-12)


def test_a_biproper_controller_with_a_leading_zero_is_proper():
    lead = Controller(numerator=(0.0, 2.0, 3.0), denominator=(1.0, 5.0))
    assert lead.numerator_degree == 1
    assert Controller(numerator=(4.0,), denominator=(1.0,)).numerator_degree == 0
    with pytest.raises(ValueError, match="proper"):
        Controller(numerator=(1.0, 2.0, 3.0), denominator=(1.0, 1.0))


def test_coil_turns_alone_asks_for_the_rest_of_the_magnet():
    with pytest.raises(ValueError, match="bias_current"):
        ActiveBearing(kind="active", name="amb", x=0.5, kp=1.0e5, coil_turns=100.0)


@pytest.mark.parametrize("name", ["yield_strength", "fatigue_strength"])
def test_metal_strengths_above_the_ultimate_are_refused(name):
    metal = {"kind": "isotropic", "E": 200.0e9, "G": 80.0e9, "density": 7800.0, "ultimate_strength": 500.0e6}
    Isotropic(**metal, **{name: 500.0e6})
    with pytest.raises(ValueError, match=name):
        Isotropic(**metal, **{name: 600.0e6})


def test_contact_bearing_directions_and_boom_station():
    bearing = ContactBearing(
        kind="contact", name="hanger", x=0.5, stiffness={"v": 1.0e8, "w": 2.0e8}, damping={"v": 300.0}
    )
    assert [bearing.stiffness_of(d) for d in ("u", "v", "w")] == [0.0, 1.0e8, 2.0e8]
    assert [bearing.damping_of(d) for d in ("u", "v", "w")] == [0.0, 300.0, 0.0]
    assert bearing.boom_x == 0.5
    mounted = ContactBearing(kind="contact", name="hanger", x=0.5, x_boom=0.7, stiffness={"v": 1.0e8})
    assert mounted.boom_x == 0.7
    assert mounted.damping_of("v") == 0.0
