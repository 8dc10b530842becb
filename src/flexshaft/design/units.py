"""Unit conversions used at the edges (design file, report, CLI).

SI floats inside, units at the edges (STYLE.md principle 5): rev/min and degrees Celsius are
converted here and nowhere else. Layup strings (angles in degrees) are parsed by
:func:`flexshaft.laminate.parse_layup`, the one layup parser of the package.
"""

from __future__ import annotations

import math

__all__ = [
    "ZERO_CELSIUS",
    "celsius_to_kelvin",
    "kelvin_to_celsius",
    "rad_s_to_rpm",
    "rpm_to_rad_s",
]

#: 0 °C in kelvin [K].
ZERO_CELSIUS = 273.15


def rpm_to_rad_s(speed_rpm: float) -> float:
    """Convert a rotational speed from [rev/min] to [rad/s]."""
    return speed_rpm * 2.0 * math.pi / 60.0


def rad_s_to_rpm(speed: float) -> float:
    """Convert a rotational speed from [rad/s] to [rev/min]."""
    return speed * 60.0 / (2.0 * math.pi)


def celsius_to_kelvin(temperature_c: float) -> float:
    """Convert a temperature from [°C] to [K]."""
    return temperature_c + ZERO_CELSIUS


def kelvin_to_celsius(temperature: float) -> float:
    """Convert a temperature from [K] to [°C]."""
    return temperature - ZERO_CELSIUS
