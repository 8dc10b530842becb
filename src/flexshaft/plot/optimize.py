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
        Label -> (x, y, feasible) of designs to mark (the first one: the base design). A design
        that fails its constraints is drawn hollow with "(fails)" in its label.
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
    if ax is None:
        fig, axes = new_figure(1, 1, (7.5, 5.2), sharex=False)
        ax = axes[0, 0]
    else:
        fig = ax.figure
    shown = _finite(x, y)
    bad = shown & ~ok
    good = shown & ok
    ax.plot(x[bad], y[bad], "x", color="0.6", ms=4, mew=0.8, label=f"fails a requirement ({int(bad.sum())})", zorder=1)
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
            zorder=4,
        )
    for k, (label, (rx, ry, passes)) in enumerate((references or {}).items()):
        if not (np.isfinite(rx) and np.isfinite(ry)):
            continue
        colour = _REFERENCE_COLOURS[k % len(_REFERENCE_COLOURS)]
        marker = _REFERENCE_MARKERS[k % len(_REFERENCE_MARKERS)]
        # the first reference (the base) largest and underneath: the others may sit on it
        ax.plot(
            [rx],
            [ry],
            marker,
            ms=20 if k == 0 else 9,
            mfc=colour if passes else "white",
            mec=colour,
            mew=1.6,
            ls="none",
            label=f"{label}{'' if passes else ' (fails)'}",
            zorder=6 if k == 0 else 7,
        )
        ax.annotate(
            label,
            (rx, ry),
            textcoords="offset points",
            xytext=_LABEL_OFFSETS[k % len(_LABEL_OFFSETS)],
            fontsize=8.5,
            color=colour,
            ha="left" if _LABEL_OFFSETS[k % len(_LABEL_OFFSETS)][0] >= 0 else "right",
        )
    arrows = {"min": "lower is better", "max": "higher is better"}
    ax.set_xlabel(f"{x_label} ({arrows.get(senses[0], '')})")
    ax.set_ylabel(f"{y_label} ({arrows.get(senses[1], '')})")
    ax.set_title(textwrap.fill(title or "Pareto front", 80), fontsize=10)
    ax.legend(loc="best", fontsize=8)
    return fig
