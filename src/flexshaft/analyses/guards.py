"""Argument checks at the top of the public analyses, and the finite-result check at their end.

Every public analysis refuses impossible arguments (a non-finite or negative speed, a count
below one, an unknown option) with a ``ValueError`` naming the argument, its value and what is
allowed, before computing; and checks that what it returns is finite, raising
:class:`NonFiniteResultError` naming the quantity instead of returning NaN or inf.

Spin speeds are bounded like a design's: at most :data:`MAX_SPEED` (10^6 rev/min,
:data:`flexshaft.design.schema.MAX_SPEED_RPM`; a 0.1 m shaft there has a surface speed of
5 km/s, and tail-rotor drivelines run at 3,000-8,000 rev/min). Far above it the gyroscopic
term Ω G swamps the stiffness: at Ω = 1e30 rad/s the baseline's backward-whirl frequencies
came out 0 and −0 Hz with damping ratios between −1 and 0.63 instead of an error.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from flexshaft.assembly.model import Model
from flexshaft.design.schema import MAX_SPEED_RPM
from flexshaft.units import rpm_to_rad_s

__all__ = [
    "MAX_SPEED",
    "NonFiniteResultError",
    "RefusedInputError",
    "UnstableResponseError",
    "check_count",
    "check_finite_array",
    "check_model",
    "check_speed",
    "check_spin_speed",
    "check_spin_speeds",
    "require_finite",
]

#: Highest spin speed an analysis accepts [rad/s]: the design limit of 10^6 rev/min.
MAX_SPEED = rpm_to_rad_s(MAX_SPEED_RPM)


class RefusedInputError(ValueError):
    """An analysis refuses its input: an argument, or a design it cannot compute. The message
    names the input and what is allowed; the cause is the input, not a fault of flexshaft, so
    a command reports it as a user error (the checks of this module, singular systems,
    non-finite results, unstable responses, and the other refusals of the analyses and thermal
    layers derive from it; a plain ``ValueError`` from inside an analysis is a bug)."""


class NonFiniteResultError(ArithmeticError, RefusedInputError):
    """An analysis produced NaN or inf (the design's numbers overflow double precision)."""


class UnstableResponseError(FloatingPointError, RefusedInputError):
    """A time response grew beyond double precision because the system is unstable there (a
    property of the design, e.g. a controller whose integral gain destabilises the loop); also a
    ``ValueError``, like the other refusals the design causes."""


def check_model(model: Any) -> None:
    """Refuse anything but an assembled :class:`~flexshaft.assembly.model.Model`."""

    if not isinstance(model, Model):
        raise RefusedInputError(
            f"model must be an assembled flexshaft Model (build_model(design)), got {type(model).__name__}"
        )


def check_speed(value: Any, name: str = "speed", unit: str = "rad/s", positive: bool = False) -> float:
    """A finite real number >= 0 (> 0 with ``positive``) as a float, or a ValueError naming it."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        number = float("nan")
    if (
        isinstance(value, (bool, complex, np.complexfloating, str, bytes, np.str_, np.bytes_))
        or not np.isfinite(number)
        or number < 0
        or (positive and number == 0)
    ):
        raise RefusedInputError(f"{name} must be a finite number {'>' if positive else '>='} 0 {unit} (got {value!r})")
    return number


def check_spin_speed(value: Any, name: str = "speed") -> float:
    """A spin speed Ω [rad/s]: :func:`check_speed`, and at most :data:`MAX_SPEED`."""
    number = check_speed(value, name)
    if number > MAX_SPEED:
        raise RefusedInputError(_too_fast(name, value))
    return number


def check_spin_speeds(values: Any, name: str = "speeds", increasing: bool = False) -> np.ndarray:
    """Spin speeds Ω [rad/s] as a non-empty 1-D float array: finite, >= 0, at most
    :data:`MAX_SPEED` (and strictly increasing with ``increasing``), or a ValueError naming them."""
    try:
        if isinstance(values, (str, bytes)) or np.asarray(values).dtype.kind in "USb":  # text or booleans
            raise TypeError
        speeds = np.atleast_1d(np.asarray(values, dtype=float))
    except (TypeError, ValueError):
        raise RefusedInputError(f"{name} must be a 1-D sequence of numbers [rad/s] (got {values!r})") from None
    if speeds.ndim != 1 or speeds.size == 0:
        raise RefusedInputError(f"{name} must be a non-empty 1-D sequence [rad/s]")
    if not np.all(np.isfinite(speeds)) or np.any(speeds < 0):
        raise RefusedInputError(f"{name} must be finite and >= 0 rad/s (got {values!r})")
    if np.any(speeds > MAX_SPEED):
        raise RefusedInputError(_too_fast(name, float(speeds.max())))
    if increasing and np.any(np.diff(speeds) <= 0):
        raise RefusedInputError(f"{name} must be strictly increasing")
    return speeds


def _too_fast(name: str, value: Any) -> str:
    return (
        f"{name} must be at most {MAX_SPEED:,.0f} rad/s (10^6 rev/min, the speed limit of a design: a "
        f"0.1 m shaft there has a surface speed of 5 km/s) (got {value!r})"
    )


def check_count(value: Any, name: str, minimum: int = 1) -> int:
    """An integer >= ``minimum`` (an integral float is accepted), or a ValueError naming it."""
    integral = isinstance(value, (int, np.integer)) or (
        isinstance(value, (float, np.floating)) and np.isfinite(value) and float(value).is_integer()
    )
    if isinstance(value, bool) or not integral or value < minimum:
        raise RefusedInputError(f"{name} must be an integer >= {minimum} (got {value!r})")
    return int(value)


def check_finite_array(name: str, value: Any, unit: str = "") -> np.ndarray:
    """A finite real or complex array (an input), or a ValueError naming it."""
    try:
        array = np.asarray(value)
        finite = np.all(np.isfinite(array))
    except (TypeError, ValueError):
        raise RefusedInputError(
            f"{name} must be an array of numbers{f' [{unit}]' if unit else ''} (got {type(value).__name__})"
        ) from None
    if not finite:
        raise RefusedInputError(f"{name} must be finite{f' [{unit}]' if unit else ''} (it contains NaN or inf)")
    return array


def require_finite(name: str, value: Any) -> None:
    """Raise :class:`NonFiniteResultError` when the result ``value`` holds NaN or inf."""
    array = np.asarray(value)
    if array.dtype.kind in "fc" and not np.all(np.isfinite(array)):
        raise NonFiniteResultError(
            f"the {name} came out NaN or inf: some combination of the design's numbers "
            "overflows double precision (see docs/limits.md)"
        )
