"""Shared helpers of the figures: lazy matplotlib with the Agg backend, one style, one layout.

Nothing here imports matplotlib at module level.

Layout. Figures are laid out with fixed margins in inches (:func:`new_figure`), not with
matplotlib's constrained or tight layout: a layout engine costs as much as drawing the figure
again (measured: 35-45 % of a report figure's save time), and every figure here has a known
structure. Text that might be long (legends, annotations) is placed inside the axes or in a
reserved band. When the caller passes ``ax``, the figure is drawn into those axes and its
layout is left alone.
"""

from __future__ import annotations

import functools
import sys
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any, Literal, ParamSpec, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from flexshaft.units import MM_PER_M, RPM_PER_HZ  # the figures' unit conversions (re-exported for plot/)

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.typing import RcKeyType

__all__ = [
    "MM_PER_M",
    "RPM_PER_HZ",
    "WHIRL_LINESTYLE",
    "WHIRL_MARKER",
    "STYLE",
    "styled",
    "new_figure",
    "vector",
    "magnitude",
    "mark_operating",
    "nice_colorbar",
    "log_scale",
]

WHIRL_LINESTYLE = {"forward": "-", "backward": "--", "planar": ":", "none": (0, (1, 4))}  # none: torsional/axial
#: Marker of each whirl label (the ROSS convention: ▲ forward, ▼ backward); torsional ■, axial ◆.
WHIRL_MARKER = {"forward": "^", "backward": "v", "planar": "o", "torsional": "s", "axial": "D", "none": "s"}
STYLE: dict[RcKeyType, Any] = {
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
    # a fixed title position: matplotlib otherwise measures every tick label of the axes at
    # draw time to lift the title over top-side labels (none here), 20 % of a figure's draw
    "axes.titley": 1.0,
}

P = ParamSpec("P")
R = TypeVar("R")


def styled(func: Callable[P, R]) -> Callable[P, R]:
    """Import matplotlib on first use (Agg unless pyplot is already loaded) and apply the style."""

    @functools.wraps(func)
    def wrapper(*args: P.args, **kwargs: P.kwargs) -> R:
        import matplotlib
        from cycler import cycler

        if "matplotlib.pyplot" not in sys.modules:
            matplotlib.use("Agg")
        style: dict[RcKeyType, Any] = {**STYLE, "axes.prop_cycle": cycler(color=matplotlib.color_sequences["tab10"])}
        with matplotlib.rc_context(style):
            return func(*args, **kwargs)

    return wrapper


def new_figure(
    nrows: int,
    ncols: int,
    figsize: tuple[float, float],
    sharex: bool = True,
    *,
    ax=None,
    left: float = 0.85,
    right: float = 0.25,
    bottom: float = 0.6,
    top: float = 0.4,
    hspace: float = 0.55,
    wspace: float = 0.7,
    **subplot_kw,
):
    """A Figure (no pyplot state, no layout engine) and its (nrows, ncols) array of axes.

    Parameters
    ----------
    nrows, ncols : int
        Panels.
    figsize : (float, float)
        Figure size [in].
    sharex : bool
        Panels share the x axis.
    ax : Axes or sequence of Axes, optional
        Draw into these axes instead (exactly ``nrows * ncols`` of them, row-major); the figure
        is theirs and its layout is left alone.
    left, right, bottom, top : float
        Margins [in] between the figure edge and the panels.
    hspace, wspace : float
        Gaps between panels [in].
    **subplot_kw
        Passed to ``add_subplot`` (e.g. ``projection="3d"``).

    Returns
    -------
    (Figure, ndarray of Axes)
    """
    n = nrows * ncols
    if ax is not None:
        axes = np.asarray(ax if isinstance(ax, (Sequence, np.ndarray)) else [ax], dtype=object).ravel()
        if axes.size != n or not all(hasattr(a, "plot") for a in axes):
            raise ValueError(
                f"ax: this figure draws {n} panel(s) ({nrows} × {ncols}); pass {'one Axes' if n == 1 else f'{n} Axes'} "
                f"(got {axes.size} object(s))"
            )
        return axes[0].figure, axes.reshape(nrows, ncols)
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    width, height = figsize
    fig = Figure(figsize=figsize)
    # An Agg canvas from the start: text measured while the figure is built (contour labels)
    # then asks it for a renderer; a bare Figure's base canvas instead prints the whole figure
    # to a PNG in memory for every label measured (31 extra draws in the report).
    FigureCanvasAgg(fig)
    panel_h = (height - top - bottom - (nrows - 1) * hspace) / nrows
    panel_w = (width - left - right - (ncols - 1) * wspace) / ncols
    fig.subplots_adjust(
        left=left / width,
        right=1 - right / width,
        bottom=bottom / height,
        top=1 - top / height,
        hspace=hspace / max(panel_h, 1e-3),
        wspace=wspace / max(panel_w, 1e-3),
    )
    if subplot_kw:
        axes = np.array([fig.add_subplot(nrows, ncols, k + 1, **subplot_kw) for k in range(n)], dtype=object)
        return fig, axes.reshape(nrows, ncols)
    grid = fig.subplots(nrows, ncols, sharex=sharex, squeeze=False)
    in_view_auto, _ = _in_view_locators()
    for a in grid.flat:
        a.xaxis.set_major_locator(in_view_auto())
        a.yaxis.set_major_locator(in_view_auto())
    return fig, grid


@functools.cache
def _in_view_locators() -> tuple[type, type]:
    """matplotlib's ``AutoLocator`` and ``LogLocator`` returning only the ticks inside the view.

    Theirs also return a tick or two beyond each end of the axis, which matplotlib then does not
    draw (``Axis._update_ticks`` keeps the ticks whose position is within the view, to 1e-10 of
    its length) but still builds a Tick object for (lines, labels, deep-copied markers: about a
    fifth of the Tick objects of the report's figures). Same test, applied before: the same
    ticks are drawn."""
    from matplotlib.ticker import AutoLocator, LogLocator

    class InView:
        def __call__(self):
            raw = super().__call__()  # type: ignore[misc]
            locs = np.asarray(raw, dtype=np.float64)
            axis = self.axis  # type: ignore[attr-defined]
            if axis is None or locs.size == 0:
                return locs
            transform = axis.get_transform()
            lo, hi = sorted(transform.transform(np.asarray(axis.get_view_interval(), dtype=float)))
            with np.errstate(invalid="ignore", divide="ignore"):
                at = transform.transform(locs)
            tol = 1e-10 * (hi - lo)
            return locs[(at >= lo - tol) & (at <= hi + tol)]

    class InViewAutoLocator(InView, AutoLocator):
        pass

    class InViewLogLocator(InView, LogLocator):
        pass

    return InViewAutoLocator, InViewLogLocator


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


def mark_operating(
    ax: Axes, operating_rpm: float | None, label: bool = True, speed_range_rpm: tuple[float, float] | None = None
) -> None:
    """Vertical line at the operating speed [rpm], if given; with ``speed_range_rpm`` (lowest,
    highest) [rpm] the operating speed range shaded too (the spin-up checks end at its highest
    speed, the separation margins are measured from its ends)."""
    if speed_range_rpm is not None and speed_range_rpm[0] < speed_range_rpm[1]:
        low, high = (float(v) for v in speed_range_rpm)
        ax.axvspan(
            low,
            high,
            color="tab:red",
            alpha=0.1,
            lw=0,
            label=f"operating speed range {low:.0f}-{high:.0f} rpm" if label else None,
        )
    if operating_rpm is not None:
        ax.axvline(
            operating_rpm,
            color="tab:red",
            ls="-.",
            lw=1.2,
            label=f"operating speed {operating_rpm:.0f} rpm" if label else None,
        )


def log_scale(ax: Axes, axis: Literal["x", "y"] = "y", minor_grid: bool = True) -> None:
    """Logarithmic ``axis`` ("x" or "y") with minor ticks at 2 and 5 of each decade only
    (matplotlib's default eight per decade cost a tick object each at draw time, a third of
    the drawing of a log-scale figure, and add no reading accuracy)."""
    (ax.set_xscale if axis == "x" else ax.set_yscale)("log")
    target = ax.xaxis if axis == "x" else ax.yaxis
    _, in_view_log = _in_view_locators()  # the log scale's own locators, ticks outside the view left out
    target.set_major_locator(in_view_log(10.0))
    target.set_minor_locator(in_view_log(10.0, subs=(2.0, 5.0)))
    formatter = _unicode_log_formatter()  # matplotlib's own labels, as plain text
    target.set_major_formatter(formatter(10.0))
    target.set_minor_formatter(formatter(10.0, labelOnlyBase=False))
    if minor_grid:
        ax.grid(which="minor", axis=axis, alpha=0.12)


_SUPERSCRIPT = str.maketrans("-−0123456789", "⁻⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def plain_log_label(label: str) -> str:
    """A log axis's mathtext tick label (``$\\mathdefault{2\\times10^{-3}}$``) as plain text
    with Unicode superscripts (``2×10⁻³``); any other label is returned unchanged."""
    import re

    match = re.fullmatch(r"\$\\mathdefault\{(.*)\}\$", label)
    if match is None:
        return label
    text = re.sub(r"\^\{([-−]?\d+)\}", lambda m: m.group(1).translate(_SUPERSCRIPT), match.group(1))
    text = text.replace("\\times", "×")
    return label if ("\\" in text or "{" in text or "^" in text) else text


@functools.cache
def _unicode_log_formatter() -> type:
    """matplotlib's ``LogFormatterSciNotation`` (the log scale's default) with plain-text
    labels: mathtext would parse them with pyparsing, whose grammar costs 0.17 s to build in
    every process that draws (and 5 ms a label); the glyphs are DejaVu Sans's own superscripts."""
    from matplotlib.ticker import LogFormatterSciNotation

    class UnicodeLogFormatter(LogFormatterSciNotation):
        def __call__(self, x, pos=None):
            return plain_log_label(super().__call__(x, pos))

    return UnicodeLogFormatter


def _log_ticks(lo: float, hi: float) -> list[float]:
    """At least four 1-2-5 ticks inside [lo, hi] (lo > 0), fewer per decade on wide ranges."""
    decades = np.arange(np.floor(np.log10(lo)), np.ceil(np.log10(hi)) + 1)
    for mantissas in ((1.0,), (1.0, 3.0), (1.0, 2.0, 5.0), (1.0, 1.5, 2.0, 3.0, 5.0, 7.0), tuple(np.arange(1.0, 10.0))):
        ticks = [m * 10.0**d for d in decades for m in mantissas if lo * (1 - 1e-9) <= m * 10.0**d <= hi * (1 + 1e-9)]
        if len(ticks) >= 4:
            return ticks
    return ticks


def nice_colorbar(fig, mappable, ax, label: str, *, log: bool = False, **kwargs):
    """A colour bar with at least four labelled ticks (plain numbers, also on a log scale).

    Parameters
    ----------
    fig : Figure
    mappable : ScalarMappable
        The mesh or collection whose colours the bar explains.
    ax : Axes
        The axes the bar steals its space from.
    label : str
        Quantity and unit, e.g. "max shaft orbit [mm]".
    log : bool
        The norm is logarithmic: ticks on a 1-2-5 sequence, labelled in plain numbers.
    **kwargs
        Passed to :meth:`Figure.colorbar` (``extend``, ``pad``, ...).
    """
    from matplotlib.ticker import FixedLocator, MaxNLocator, NullLocator

    bar = fig.colorbar(mappable, ax=ax, label=label, **kwargs)
    lo, hi = mappable.norm.vmin, mappable.norm.vmax
    if log and lo is not None and hi is not None and 0 < lo < hi:
        ticks = _log_ticks(lo, hi)
        bar.ax.yaxis.set_major_locator(FixedLocator(ticks))
        bar.ax.yaxis.set_minor_locator(NullLocator())
        bar.ax.set_yticklabels([f"{t:.3g}" for t in ticks])
    elif lo is not None and hi is not None and hi > lo:
        center = getattr(mappable.norm, "vcenter", None)
        if center is not None and lo < center < hi:  # two halves of equal length: ticks on each
            candidates = np.concatenate(
                [MaxNLocator(3).tick_values(lo, center), MaxNLocator(5).tick_values(center, hi)]
            )
        else:
            candidates = np.asarray(MaxNLocator(7).tick_values(lo, hi))
        tol = 1e-9 * abs(hi - lo)
        bar.set_ticks(sorted({float(t) for t in candidates if lo - tol <= t <= hi + tol}))
    return bar
