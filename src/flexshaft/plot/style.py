"""Shared helpers of the report figures: lazy matplotlib with the Agg backend, one style.

Nothing here imports matplotlib at module level.
"""

from __future__ import annotations

import functools
import sys
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["MM_PER_M", "RPM_PER_HZ", "WHIRL_LINESTYLE", "STYLE", "styled", "new_figure", "vector",
           "magnitude", "mark_operating"]

MM_PER_M = 1e3
RPM_PER_HZ = 60.0
WHIRL_LINESTYLE = {"forward": "-", "backward": "--", "planar": ":", "none": (0, (1, 4))}  # none: torsional/axial
STYLE = {
    "font.size": 10,
    "axes.titlesize": 11,
    "axes.labelsize": 10,
    "legend.fontsize": 8.5,
    "legend.framealpha": 0.9,
    "axes.grid": True,
    "axes.grid.which": "major",
    "grid.alpha": 0.35,
    "grid.linewidth": 0.6,
    "lines.linewidth": 1.6,
}

F = TypeVar("F", bound=Callable[..., Any])


def styled(func: F) -> F:
    """Import matplotlib on first use (Agg unless pyplot is already loaded) and apply the style."""

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        import matplotlib

        if "matplotlib.pyplot" not in sys.modules:
            matplotlib.use("Agg")
        style = {**STYLE, "axes.prop_cycle": matplotlib.cycler(color=matplotlib.colormaps["tab10"].colors)}
        with matplotlib.rc_context(style):
            return func(*args, **kwargs)

    return wrapper  # type: ignore[return-value]


def new_figure(nrows: int, ncols: int, figsize: tuple[float, float], sharex: bool = True):
    """A constrained-layout Figure (no pyplot state) and its (nrows, ncols) array of axes; figsize [in]."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize, layout="constrained")
    axes = fig.subplots(nrows, ncols, sharex=sharex, squeeze=False)
    return fig, axes


def vector(name: str, values: ArrayLike, size: int | None = None) -> NDArray[np.float64]:
    """Flat float array, checked against ``size``; the error names the argument."""
    array = np.asarray(values, dtype=float).ravel()
    if size is not None and array.size != size:
        raise ValueError(f"{name}: expected {size} values to match the speed/station axis, got {array.size}")
    return array


def magnitude(name: str, values: ArrayLike, size: int) -> NDArray[np.float64]:
    """Flat array of magnitudes (complex amplitudes allowed), checked against ``size``."""
    array = np.abs(np.asarray(values)).astype(float).ravel()
    if array.size != size:
        raise ValueError(f"{name}: expected {size} values to match the speed axis, got {array.size}")
    return array


def mark_operating(ax: Axes, operating_rpm: float | None, label: bool = True) -> None:
    """Vertical line at the operating speed [rpm], if given."""
    if operating_rpm is not None:
        ax.axvline(operating_rpm, color="tab:red", ls="-.", lw=1.2,
                   label=f"operating speed {operating_rpm:.0f} rpm" if label else None)
