"""Unit conversions used at the edges (design file, report, CLI): the one module for them.

SI floats inside, units at the edges (docs/architecture.md): rev/min, hertz of rotation,
degrees Celsius, millimetres are converted here and nowhere else. The functions work on
floats and numpy arrays alike. Layup strings (angles in degrees) are parsed by
:func:`flexshaft.design.layup.parse_layup`, the one layup parser of the package.

>>> from flexshaft.units import celsius_to_kelvin, rad_s_to_rpm, rpm_to_hz, rpm_to_rad_s
>>> round(rpm_to_rad_s(4800.0), 4)          # the baseline's operating speed [rad/s]
502.6548
>>> rad_s_to_rpm(rpm_to_rad_s(4800.0)), rpm_to_hz(4800.0)
(4800.0, 80.0)
>>> celsius_to_kelvin(25.0)
298.15
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, TypeVar

if TYPE_CHECKING:
    import numpy as np

__all__ = [
    "MM_PER_M",
    "RPM_PER_HZ",
    "ZERO_CELSIUS",
    "celsius_to_kelvin",
    "format_quantity",
    "hz_to_rpm",
    "kelvin_to_celsius",
    "m_to_mm",
    "mm_to_m",
    "rad_s_to_hz",
    "rad_s_to_rpm",
    "rpm_to_hz",
    "rpm_to_rad_s",
]

#: Millimetres per metre.
MM_PER_M = 1000.0
#: rpm per Hz (revolutions per minute of one revolution per second).
RPM_PER_HZ = 60.0

#: 0 °C in kelvin [K].
ZERO_CELSIUS = 273.15

#: A value the conversions take and give back: a float or a numpy array (numpy is imported
#: for the type checker only: ``import flexshaft`` stays light).
Value = TypeVar("Value", float, "np.ndarray")


def rpm_to_rad_s(speed_rpm: Value) -> Value:
    """Convert a rotational speed from [rev/min] to [rad/s]."""
    return speed_rpm * 2.0 * math.pi / 60.0


def rad_s_to_rpm(speed: Value) -> Value:
    """Convert a rotational speed from [rad/s] to [rev/min]."""
    return speed * 60.0 / (2.0 * math.pi)


def celsius_to_kelvin(temperature_c: Value) -> Value:
    """Convert a temperature from [°C] to [K]."""
    return temperature_c + ZERO_CELSIUS


def kelvin_to_celsius(temperature: Value) -> Value:
    """Convert a temperature from [K] to [°C]."""
    return temperature - ZERO_CELSIUS


def rad_s_to_hz(omega: Value) -> Value:
    """Convert an angular frequency from [rad/s] to [Hz]."""
    return omega / (2.0 * math.pi)


def hz_to_rpm(frequency: Value) -> Value:
    """A frequency [Hz] as the spin speed [rev/min] whose 1× line it lies on."""
    return frequency * 60.0


def rpm_to_hz(speed_rpm: Value) -> Value:
    """A spin speed [rev/min] as its rotation frequency [Hz]."""
    return speed_rpm / 60.0


def mm_to_m(length_mm: Value) -> Value:
    """[mm] -> [m]."""
    return length_mm / MM_PER_M


def m_to_mm(length: Value) -> Value:
    """Convert a length from [m] to [mm]."""
    return length * MM_PER_M


def format_quantity(kind: str, value: float | None, *, margin: bool = False) -> str:
    """A value (or a signed margin) of a check's ``kind`` in display units.

    Speeds in rpm, lengths in mm, forces in N, temperatures in °C (margins in K), fractions
    in % (margins in percentage points), angles in degrees, gains in dB, safety factors and log
    decrements plain.
    """
    if value is None:
        return "—"
    sign = "+" if margin else ""
    if kind == "speed":
        return f"{rad_s_to_rpm(value):{sign}.0f} rpm"
    if kind == "length":
        return f"{m_to_mm(value):{sign}.3g} mm"
    if kind == "force":
        return f"{value:{sign}.4g} N"
    if kind == "temperature":
        return f"{value:+.1f} K" if margin else f"{kelvin_to_celsius(value):.1f} °C"
    if kind == "fraction":
        return f"{value * 100:+.1f} pts" if margin else f"{value * 100:.1f} %"
    if kind == "angle":
        return f"{math.degrees(value):{sign}.3g}°"
    if kind == "decibel":
        return f"{value:{sign}.3g} dB"
    return f"{value:{sign}.3g}"
