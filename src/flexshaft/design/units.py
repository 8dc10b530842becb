"""Unit conversions used at the design-file edge.

SI floats inside, units at the edges (STYLE.md principle 5): rev/min is converted here and
nowhere else in the design package. Layup strings (angles in degrees) are parsed by
:func:`flexshaft.laminate.parse_layup`, the one layup parser of the package.
"""

from __future__ import annotations

import math

__all__ = [
    "rad_s_to_rpm",
    "rpm_to_rad_s",
]


def rpm_to_rad_s(speed_rpm: float) -> float:
    """Convert a rotational speed from [rev/min] to [rad/s]."""
    return speed_rpm * 2.0 * math.pi / 60.0


def rad_s_to_rpm(speed: float) -> float:
    """Convert a rotational speed from [rad/s] to [rev/min]."""
    return speed * 60.0 / (2.0 * math.pi)
