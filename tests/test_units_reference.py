"""The unit conversions of :mod:`flexshaft.units` against their definitions.

References (typed from the definitions, not from the code):

* one revolution is 2π rad and one minute 60 s, so 1 rev/min = 2π/60 rad/s and 1 Hz of
  rotation = 1 rev/s = 60 rev/min = 2π rad/s;
* the Celsius scale is the kelvin scale shifted by exactly 273.15 K (SI Brochure, 9th ed.,
  2019, §2.3.1: t/°C = T/K − 273.15), so absolute zero is −273.15 °C and the triple point of
  water, 273.16 K, is 0.01 °C.

Tolerances: each conversion is one or two floating-point operations on exactly representable
or once-rounded inputs, so it is exact to a few units in the last place; ``REL`` = 1e-14
allows some 50 ulp and is still 1e10 times smaller than any mistake tested here.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.units import (
    RPM_PER_HZ,
    celsius_to_kelvin,
    format_quantity,
    hz_to_rpm,
    kelvin_to_celsius,
    m_to_mm,
    mm_to_m,
    rad_s_to_hz,
    rad_s_to_rpm,
    rpm_to_hz,
    rpm_to_rad_s,
)

REL = 1e-14


def test_one_revolution_per_second_in_every_unit():
    """1 rev/s = 60 rev/min = 2π rad/s = 1 Hz, each way."""
    two_pi = 2.0 * math.pi
    assert rpm_to_rad_s(60.0) == pytest.approx(two_pi, rel=REL)
    assert rad_s_to_rpm(two_pi) == pytest.approx(60.0, rel=REL)
    assert rad_s_to_hz(two_pi) == pytest.approx(1.0, rel=REL)
    assert rpm_to_hz(60.0) == pytest.approx(1.0, rel=REL)
    assert hz_to_rpm(1.0) == pytest.approx(60.0, rel=REL)
    assert RPM_PER_HZ == 60.0  # the Campbell diagrams' 1× line: f [Hz] = speed [rpm] / RPM_PER_HZ


def test_one_rpm_is_two_pi_over_sixty_rad_s():
    """1 rev/min = 2π/60 rad/s ≈ 0.10472 rad/s (and 1 rad/s = 9.5493 rev/min)."""
    assert rpm_to_rad_s(1.0) == pytest.approx(0.10471975511965977, rel=REL)
    assert rad_s_to_rpm(1.0) == pytest.approx(9.549296585513721, rel=REL)


def test_celsius_kelvin_fixed_points():
    """Absolute zero is −273.15 °C; the triple point of water is 273.16 K = 0.01 °C."""
    assert kelvin_to_celsius(0.0) == pytest.approx(-273.15, rel=REL)
    assert celsius_to_kelvin(-273.15) == pytest.approx(0.0, abs=REL * 273.15)
    assert celsius_to_kelvin(0.01) == pytest.approx(273.16, rel=REL)
    assert kelvin_to_celsius(273.16) == pytest.approx(0.01, abs=REL * 273.16)


def test_millimetres():
    assert mm_to_m(1000.0) == pytest.approx(1.0, rel=REL)
    assert m_to_mm(0.001) == pytest.approx(1.0, rel=REL)


def test_displayed_temperature_is_celsius():
    """373.15 K, the boiling point of water at 1 atm on ITS-90 to within 0.03 K, shows as 100.0 °C;
    a margin stays in kelvin (a temperature difference is the same in K and °C)."""
    assert format_quantity("temperature", 373.15) == "100.0 °C"
    assert format_quantity("temperature", 12.0, margin=True) == "+12.0 K"
    assert format_quantity("speed", 2.0 * math.pi * 80.0) == "4800 rpm"


def test_displayed_angles_are_degrees_and_lengths_millimetres():
    """π/4 rad is 45° (180° = π rad); 2.5e-3 m is 2.5 mm."""
    assert format_quantity("angle", math.pi / 4) == "45°"
    assert format_quantity("angle", -math.pi / 36, margin=True) == "-5°"
    assert format_quantity("length", 2.5e-3) == "2.5 mm"
