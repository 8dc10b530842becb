"""An active bearing's controller, magnet and offset keys against the documented rules.

* **One law, stated once** (docs/magnetic-bearings.md, the table of design-file keys:
  ``controller`` "replaces kp, kd, integral_gain, derivative_cutoff"). A derivative gain
  written next to a transfer-function controller would be dropped without a word (the
  controller is the whole law C(s)), so the damping the user meant to add is missing: refused.
* **One magnet, stated once** (same table: the magnet geometry, "give all four (then not
  ``ks``, ``ki``)"). The geometry gives k = ¼ μ0 N² A_a cos α and k_i = 4 k i_0/g_0² =
  μ0 N² A_a i_0 cos α/g_0² (∝ 1/g_0²), k_s = k_i i_0/g_0 ∝ 1/g_0³ (docs/magnetic-bearings.md,
  "Magnet physics"): without the air gap g_0 neither exists, and a ``ki`` given beside the
  geometry would be replaced by the geometry's. Both are refused.
* **A proper law** (same table: ``controller`` "highest power first, proper"): the degree of
  the numerator is the index of its first non-zero coefficient from the top, whatever its
  sign. C(s) = (−s + 5)/1 has degree 1 over degree 0 (its gain |C(iω)| ≈ ω grows without
  bound): refused, as (s + 5)/1 is; (−s + 5)/(s + 1) is proper and accepted.
* **Signed coefficients** (docs/limits.md: ``ControllerCoefficient`` within ±1e100). The
  first-order Padé model of a controller's delay τ, (1 − sτ/2)/(1 + sτ/2), has a negative
  coefficient; it is accepted and kept as written, and at s = iω its magnitude is 1 and its
  phase −2 atan(ωτ/2) (derived here: the numerator is the conjugate of the denominator).
  The law is evaluated by the product's ``Controller`` (flexshaft.assembly.controller), built
  from ``transfer_function()`` as the model build does, at s = iω: two polyvals of degree 1
  and a division, relative 1e-14.
* **Sensor on either side** (docs/limits.md: ``Coordinate`` for ``sensor_offset``, ±1000 m;
  docs/magnetic-bearings.md: "sensor at ``x + sensor_offset``"): δ = −0.04 m puts the sensor
  4 cm ahead of the magnet, at x − 0.04 (one subtraction: 1e-15).
* **Fast amplifiers** (docs/limits.md: ``FilterFrequency`` for ``derivative_cutoff`` and
  ``amplifier_bandwidth``, 1 mHz to 10 MHz): a 50 kHz current loop and a 10 MHz corner are
  accepted, with ω_a = 2π f_a (relative 1e-15).

Written for the mutations h57f-bearings-controller-with-kd-accepted,
h57f-bearings-given-ki-with-geometry-accepted, h57f-bearings-geometry-without-air-gap,
h57f-bearings-negative-leading-coefficient-dropped, h57f-q-controller-coefficients-nonnegative,
h57f-q-coordinate-nonnegative and h57f-q-filter-corner-cap-10-khz of scripts/mutations.toml.
Only the pydantic models are built (no model is assembled).
"""

from __future__ import annotations

import math

import pydantic
import pytest

from flexshaft.assembly.controller import Controller
from flexshaft.design.bearings import ActiveBearing

X = 0.5  # magnet station [m]
GEOMETRY = {"coil_turns": 200.0, "pole_area": 6.0e-4, "bias_current": 3.0, "air_gap": 5.0e-4}


def active(**keys) -> ActiveBearing:
    return ActiveBearing(kind="active", name="amb", x=X, **keys)


def test_a_derivative_gain_beside_a_controller_is_refused():
    law = {"numerator": (2900.0, 2.0e6), "denominator": (1.0e-3, 1.0)}  # a filtered PD law
    with pytest.raises(pydantic.ValidationError):
        active(controller=law, kd=500.0)
    assert active(controller=law).transfer_function() == ((2900.0, 2.0e6), (1.0e-3, 1.0))


def test_a_current_gain_beside_the_magnet_geometry_is_refused():
    with pytest.raises(pydantic.ValidationError):
        active(kp=1.0e6, ki=150.0, **GEOMETRY)
    assert active(kp=1.0e6, **GEOMETRY).uses_magnet_geometry


def test_a_magnet_geometry_without_its_air_gap_is_refused():
    partial = {key: value for key, value in GEOMETRY.items() if key != "air_gap"}
    with pytest.raises(pydantic.ValidationError):
        active(kp=1.0e6, **partial)


@pytest.mark.parametrize("numerator", [(-1.0, 5.0), (1.0, 5.0), (0.0, -2.0, 5.0)])
def test_an_improper_law_is_refused_whatever_the_sign_of_its_leading_coefficient(numerator):
    with pytest.raises(pydantic.ValidationError):
        active(controller={"numerator": numerator, "denominator": (1.0,)})


def test_a_proper_law_with_a_negative_leading_coefficient_is_accepted():
    bearing = active(controller={"numerator": (-1.0, 5.0), "denominator": (1.0, 1.0)})
    assert bearing.controller is not None and bearing.controller.numerator_degree == 1


def test_a_pade_delay_law_with_a_negative_coefficient_is_kept_as_written():
    tau = 1.0e-4  # s, the delay of a 10 kHz digital controller
    num, den = (-tau / 2.0, 1.0), (tau / 2.0, 1.0)
    bearing = active(controller={"numerator": num, "denominator": den})
    got_num, got_den = bearing.transfer_function()
    assert (tuple(got_num), tuple(got_den)) == (num, den)
    law = Controller(tuple(map(float, got_num)), tuple(map(float, got_den)))  # as build_model does
    for omega in (100.0, 2.0 * math.pi * 1000.0, 3.0e4):
        value = complex(law(1j * omega))
        assert abs(value) == pytest.approx(1.0, rel=1e-14)
        assert math.atan2(value.imag, value.real) == pytest.approx(-2.0 * math.atan(omega * tau / 2.0), rel=1e-14)


def test_a_sensor_ahead_of_its_magnet_is_accepted_at_x_minus_the_offset():
    bearing = active(kp=1.0e6, sensor_offset=-0.04)
    assert bearing.sensor_x == pytest.approx(X - 0.04, rel=1e-15)


@pytest.mark.parametrize("corner", [5.0e4, 1.0e7])
def test_filter_corners_up_to_ten_megahertz_are_accepted(corner):
    bearing = active(kp=1.0e6, kd=500.0, amplifier_bandwidth=corner, derivative_cutoff=corner)
    assert bearing.amplifier_bandwidth_rad_s == pytest.approx(2.0 * math.pi * corner, rel=1e-15)
    assert bearing.derivative_cutoff_rad_s == pytest.approx(2.0 * math.pi * corner, rel=1e-15)
