"""Which sense of a laminated tube governs its torsional buckling, and the half-wave count of a
helix, against closed forms derived here (mutation hunt 19c).

* Shear crimping of a tube of +45° plies only. The short-wave limit (derived in
  tests/test_buckling.py's ``crimping_closed_form``: a wave much shorter than R and than the
  bending wavelength stores only transverse shear energy) is T± = 2πR² (√(A44 A55) ∓ A45), the
  upper sign for the positive torque. The ply's transverse shear moduli rotate as a vector,
  Q55 = G13 c² + G23 s², Q44 = G13 s² + G23 c², Q45 = (G13 − G23) c s; at 45° (c = s = 1/√2)
  A44 = A55 = k t (G13 + G23)/2 and A45 = k t (G13 − G23)/2, so

      T+ = 2πR² k t G23,    T− = 2πR² k t G13,

  with k = 5/6 (the lamina's default shear correction). The tube buckles in the sense of the
  smaller critical torque: that sense's mode is the tube's ``governing`` mode and its wave
  number the ``critical_n``. Two FMC walls (E_L 115 GPa, E_T 0.10 GPa, G_LT 0.035 GPa) of the
  baseline size: G13 = 40 MPa, G23 = 3 MPa crimps at T+ (115 N m) while the negative sense
  needs a global helix (its crimping limit T− is 1527 N m); G13 = 10 MPa, G23 = 3 MPa crimps
  in the negative sense at T− = 382 N m, and the positive sense buckles in a global helix
  below that (weaker than the +45 plies' transverse shear alone would allow). The crimping
  torques are exact in the package (a closed form of A): 1e-12 relative.
* Half-waves of a long isotropic tube's helix (classical shell, Donnell). Donnell's equation for
  a helix w = cos(kx + nθ) gives τ t = [D s² + E t k⁴/(R² s²)]/(2 k n/R), s = k² + (n/R)²
  (Batdorf 1947; the same relation as tests/test_buckling.py). Over a simply supported span L
  the helix's sine series Σ W_m sin(mπx/L) peaks at m = kL/π, the minimising k of that relation
  at the tube's n. Chosen where kL/π lies within 0.05 of an integer (R/t = 50, L/R = 40 and 80:
  3.02 and 6.05), so the largest term is that integer unless the finite tube's helix wavenumber
  were more than 15 % off the infinite tube's (the ends' effect on a tube 40 radii long is
  far smaller), and the count m of ``sin(mπx/L)`` counts from 1.

CPU: six buckling solves of at most 72 axial terms, about 0.1 s.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
import scipy.optimize

from flexshaft.buckling import torsional_buckling_torque
from flexshaft.laminate import Lamina, Laminate

FMC = Lamina.from_loss_factors(115e9, 0.10e9, 0.035e9, 0.35, 1650.0, 0.003, 0.12, 0.12)
RADIUS, LENGTH, WALL = (0.1016 - 3e-3) / 2, 7.26, 3e-3  # baseline shaft: mid-surface radius, span [m]
SHEAR_CORRECTION = 5.0 / 6.0


def _plus_45_tube(g13: float, g23: float):
    lamina = replace(FMC, G_13=g13, G_23=g23)
    return torsional_buckling_torque(Laminate.from_layup("(45/45/45/45)s", WALL, lamina), RADIUS, LENGTH)


def _crimping(g: float) -> float:
    return 2 * np.pi * RADIUS**2 * SHEAR_CORRECTION * WALL * g


def test_the_positive_sense_crimps_and_governs():
    result = _plus_45_tube(40e6, 3e6)
    assert result.torque_positive == pytest.approx(_crimping(3e6), rel=1e-12)
    assert result.crimping_torque_negative == pytest.approx(_crimping(40e6), rel=1e-12)
    assert result.torque_negative > result.torque_positive  # the negative sense is the stronger
    assert result.critical_torque == pytest.approx(_crimping(3e6), rel=1e-12)
    assert result.governing == "shear crimping"
    assert result.critical_n is None


def test_the_positive_helix_governs_when_the_negative_sense_crimps():
    result = _plus_45_tube(10e6, 3e6)
    assert result.governing_negative == "shear crimping"
    assert result.torque_negative == pytest.approx(_crimping(10e6), rel=1e-12)
    assert result.torque_positive < _crimping(10e6)  # the positive sense is the weaker
    assert result.critical_torque == result.torque_positive
    assert result.governing == "global helical"
    assert result.critical_n is not None and result.critical_n == result.n_positive


@pytest.mark.parametrize("length_over_radius", [40.0, 80.0])
def test_half_waves_of_a_long_tube_are_its_helix_wavenumber_times_the_span_over_pi(length_over_radius):
    E, nu, radius_over_thickness = 70e9, 0.3, 50.0
    t, radius = 1.0 / radius_over_thickness, 1.0
    span = length_over_radius * radius
    tube = Laminate([0.0], [t], Lamina.isotropic(E, E / (2 * (1 + nu)), 2700.0))
    result = torsional_buckling_torque(tube, radius, span, theory="classical", kinematics="donnell")
    D = E * t**3 / (12 * (1 - nu**2))

    def tau(log_k: float, n: int) -> float:
        k, eta = np.exp(log_k), n / radius
        s = k**2 + eta**2
        return (D * s**2 + E * t * k**4 / (radius**2 * s**2)) / (2 * k * eta * t)

    for n, m, mode in (
        (result.n_positive, result.axial_half_waves_positive, result.mode_positive),
        (result.n_negative, result.axial_half_waves_negative, result.mode_negative),
    ):
        best = scipy.optimize.minimize_scalar(
            tau, bounds=(np.log(1e-3), np.log(10.0)), method="bounded", args=(n,), options={"xatol": 1e-10}
        )
        half_waves = np.exp(best.x) * span / np.pi
        assert abs(half_waves - round(half_waves)) < 0.05  # the chosen spans (module docstring)
        assert m == round(half_waves)
        assert abs(mode[m - 1]) == pytest.approx(1.0, rel=1e-12)  # W_m of sin(mπx/L), m from 1, max |W| = 1
