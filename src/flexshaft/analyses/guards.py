"""Argument checks at the top of the public analyses, and the finite-result check at their end.

Every public analysis refuses impossible arguments (a non-finite or negative speed, a count
below one, an unknown option) with a ``ValueError`` naming the argument, its value and what is
allowed, before computing; and checks that what it returns is finite, raising
:class:`NonFiniteResultError` naming the quantity instead of returning NaN or inf.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from flexshaft.assembly.model import Model

__all__ = ["NonFiniteResultError", "check_count", "check_finite_array", "check_model", "check_speed", "require_finite"]


class NonFiniteResultError(ArithmeticError, ValueError):
    """An analysis produced NaN or inf (the design's numbers overflow double precision)."""


def check_model(model: Any) -> None:
    """Refuse anything but an assembled :class:`~flexshaft.assembly.model.Model`."""

    if not isinstance(model, Model):
        raise ValueError(
            f"model must be an assembled flexshaft Model (build_model(design)), got {type(model).__name__}"
        )


def check_speed(value: Any, name: str = "speed", unit: str = "rad/s", positive: bool = False) -> float:
    """A finite real number >= 0 (> 0 with ``positive``) as a float, or a ValueError naming it."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        number = float("nan")
    if (
        isinstance(value, (bool, complex, np.complexfloating))
        or not np.isfinite(number)
        or number < 0
        or (positive and number == 0)
    ):
        raise ValueError(f"{name} must be a finite number {'>' if positive else '>='} 0 {unit} (got {value!r})")
    return number


def check_count(value: Any, name: str, minimum: int = 1) -> int:
    """An integer >= ``minimum`` (an integral float is accepted), or a ValueError naming it."""
    integral = isinstance(value, (int, np.integer)) or (
        isinstance(value, (float, np.floating)) and np.isfinite(value) and float(value).is_integer()
    )
    if isinstance(value, bool) or not integral or value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum} (got {value!r})")
    return int(value)


def check_finite_array(name: str, value: Any, unit: str = "") -> np.ndarray:
    """A finite real or complex array (an input), or a ValueError naming it."""
    try:
        array = np.asarray(value)
        finite = np.all(np.isfinite(array))
    except (TypeError, ValueError):
        raise ValueError(
            f"{name} must be an array of numbers{f' [{unit}]' if unit else ''} (got {type(value).__name__})"
        ) from None
    if not finite:
        raise ValueError(f"{name} must be finite{f' [{unit}]' if unit else ''} (it contains NaN or inf)")
    return array


def require_finite(name: str, value: Any) -> None:
    """Raise :class:`NonFiniteResultError` when the result ``value`` holds NaN or inf."""
    array = np.asarray(value)
    if array.dtype.kind in "fc" and not np.all(np.isfinite(array)):
        raise NonFiniteResultError(
            f"the {name} came out NaN or inf: some combination of the design's numbers "
            "overflows double precision (see docs/limits.md)"
        )
