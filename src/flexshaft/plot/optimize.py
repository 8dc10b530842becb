"""The Pareto-front figure of a design optimization (``flexshaft optimize``).

Plain arrays in (the values of two objectives, already in the units of their labels); matplotlib
imported lazily through :func:`flexshaft.plot.style.styled`; a new figure unless ``ax`` is
given; returns the figure. Nothing here knows about designs or analyses.
"""

from __future__ import annotations

import textwrap
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import new_figure, styled, vector

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["pareto_front"]

_REFERENCE_MARKERS = ("*", "D", "P", "X", "s", "^", "v")
_LABEL_OFFSETS = ((9, 7), (9, -15), (-9, 7), (-9, -15))
_REFERENCE_COLOURS = ("black", "tab:green", "tab:purple", "tab:brown", "tab:olive", "tab:cyan", "tab:pink")


def _finite(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    return np.isfinite(x) & np.isfinite(y)


def _span(values: np.ndarray, pad: float = 0.25) -> tuple[float, float]:
    lo, hi = float(values.min()), float(values.max())
    width = hi - lo if hi > lo else max(abs(hi), 1.0) * 0.1
    return lo - pad * width, hi + pad * width


def _view(fx, fy, ox, oy, references) -> tuple[float, float, float, float] | None:
    """Axes limits (x0, x1, y0, y1) that show the feasible designs, the front and the passing
    references (``fx``, ``fy``), with the other designs (``ox``, ``oy``) that lie within twice
    that box's size of it: a failing design far off (a base with a margin of −90 beside
    feasible margins of 0.01) does not squeeze the feasible ones into a line. None
    (matplotlib's own limits) when nothing passes."""
    keep = _finite(fx, fy)
    refs = [(rx, ry) for rx, ry, passes in references.values() if passes and np.isfinite(rx) and np.isfinite(ry)]
    xs = np.r_[fx[keep], [r[0] for r in refs]]
    ys = np.r_[fy[keep], [r[1] for r in refs]]
    if xs.size == 0:
        return None
    limits = []
    for core, others in ((xs, ox), (ys, oy)):
        lo, hi = _span(core)
        width = hi - lo
        near = others[np.isfinite(others) & (others >= lo - 2 * width) & (others <= hi + 2 * width)]
        limits += list(_span(np.r_[core, near], pad=0.08) if near.size else (lo, hi))
    x0, x1, y0, y1 = limits
    return x0, x1, y0, y1


def _clip(x: float, y: float, view) -> tuple[float, float, str | None]:
    """A point clipped into the view, with the arrowhead marker pointing where it lies (None:
    inside)."""
    if view is None:
        return x, y, None
    x0, x1, y0, y1 = view
    cx, cy = min(max(x, x0), x1), min(max(y, y0), y1)
    if cy != y:
        return cx, cy, "v" if y < y0 else "^"
    if cx != x:
        return cx, cy, "<" if x < x0 else ">"
    return x, y, None


@styled
def pareto_front(
    x: ArrayLike,
    y: ArrayLike,
    feasible: ArrayLike,
    front_x: ArrayLike,
    front_y: ArrayLike,
    *,
    references: Mapping[str, tuple[float, float, bool]] | None = None,
    x_label: str = "objective 1",
    y_label: str = "objective 2",
    senses: Sequence[str] = ("min", "min"),
    title: str = "",
    ax: Axes | None = None,
) -> Figure:
    """Every evaluated design, the feasible ones, the Pareto front and marked reference designs.

    Parameters
    ----------
    x, y : array_like
        Two objectives of every evaluated design (NaN: no result, not drawn).
    feasible : array_like of bool
        Designs that meet every constraint.
    front_x, front_y : array_like
        The Pareto front (drawn as the attainment line between its members).
    references : mapping, optional
        Label -> (x, y, feasible) of designs to mark (the first one: the base design), each an
        open marker under the front's points (a front point on a reference stays visible); one
        that fails its constraints has a thinner edge and "(fails)" in its label.
    x_label, y_label : str
        Axis labels with units.
    senses : pair of {"min", "max"}
        Direction of improvement of each objective (shown in the axis labels).
    title : str
    ax : matplotlib Axes, optional
        Draw on it instead of a new figure.

    Returns
    -------
    matplotlib.figure.Figure
    """
    x = vector("x", x)
    y = vector("y", y, x.size)
    ok = np.asarray(feasible, dtype=bool).ravel()
    if ok.size != x.size:
        raise ValueError(f"feasible: expected {x.size} values to match x, got {ok.size}")
    fx = vector("front_x", front_x)
    fy = vector("front_y", front_y, fx.size)
    own = ax is None
    if ax is None:
        rows = (3 + len(references or {}) + 1) // 2  # legend lines, two entries each
        band = 0.75 + 0.2 * rows
        fig, axes = new_figure(1, 1, (7.5, 4.6 + band), sharex=False, bottom=band)
        ax = axes[0, 0]
    else:
        fig = ax.figure
    shown = _finite(x, y)
    bad = shown & ~ok
    good = shown & ok
    view = _view(np.r_[x[good], fx], np.r_[y[good], fy], x[bad], y[bad], references or {})
    off = (
        0
        if view is None
        else int(np.sum(~((x[bad] >= view[0]) & (x[bad] <= view[1]) & (y[bad] >= view[2]) & (y[bad] <= view[3]))))
    )
    label = f"fails a requirement ({int(bad.sum())}{f', {off} off the axes' if off else ''})"
    ax.plot(x[bad], y[bad], "x", color="0.6", ms=4, mew=0.8, label=label, zorder=1)
    ax.plot(
        x[good],
        y[good],
        "o",
        color="tab:blue",
        ms=4,
        alpha=0.55,
        mec="none",
        label=f"passes every requirement ({int(good.sum())})",
        zorder=2,
    )
    # the references first and hollow: a Pareto point that coincides with the base (its own
    # values are the search's first candidate) or a reference stays visible inside the ring;
    # a reference outside the view (a failing base far below the feasible margins) is drawn at
    # the edge as an arrowhead pointing to where it lies, its values in the label
    for k, (label, (rx, ry, passes)) in enumerate((references or {}).items()):
        if not (np.isfinite(rx) and np.isfinite(ry)):
            continue
        colour = _REFERENCE_COLOURS[k % len(_REFERENCE_COLOURS)]
        marker = _REFERENCE_MARKERS[k % len(_REFERENCE_MARKERS)]
        text = f"{label}{'' if passes else ' (fails)'}"
        px, py, outside = _clip(rx, ry, view)
        if outside:
            marker = outside
        ax.plot(
            [px],
            [py],
            marker,
            ms=20 if k == 0 and not outside else 14,
            mfc="none",
            mec=colour,
            mew=2.0 if passes else 1.2,
            ls="none",
            label=text + (f" at ({rx:.4g}, {ry:.4g}), off the axes" if outside else ""),
            zorder=3,
            clip_on=False,
        )
        dx, dy = _LABEL_OFFSETS[k % len(_LABEL_OFFSETS)]
        if outside:  # beside the arrowhead, towards the middle of the axes
            right_half = view is not None and px > 0.5 * (view[0] + view[1])
            dx, dy = (-9 if right_half else 9), (6 if outside == "v" else -14)
        ax.annotate(
            text,
            (px, py),
            textcoords="offset points",
            xytext=(dx * (1.0 if outside else 1.4), dy * (1.0 if outside else 1.4)),
            fontsize=8.5,
            color=colour,
            ha="left" if dx >= 0 else "right",
        )
    if fx.size:
        order = np.argsort(fx)
        ax.plot(
            fx[order],
            fy[order],
            "-o",
            color="tab:red",
            ms=6,
            mfc="tab:red",
            mec="k",
            mew=0.6,
            lw=1.4,
            drawstyle=("steps-post" if senses[0] == "min" else "steps-pre") if fx.size > 1 else "default",
            label=f"Pareto front ({fx.size})",
            zorder=8,
        )
    if view is not None:
        ax.set_xlim(view[0], view[1])
        ax.set_ylim(view[2], view[3])
    arrows = {"min": "lower is better", "max": "higher is better"}
    ax.set_xlabel(f"{x_label} ({arrows.get(senses[0], '')})")
    ax.set_ylabel(f"{y_label} ({arrows.get(senses[1], '')})")
    ax.set_title(textwrap.fill(title or "Pareto front", 80), fontsize=10)
    if own:  # in a band under the axes: it hides no design and no label
        ax.legend(loc="lower center", bbox_to_anchor=(0.5, 0.01), bbox_transform=fig.transFigure, ncols=2, fontsize=8)
    else:
        ax.legend(loc="best", fontsize=8)
    return fig
