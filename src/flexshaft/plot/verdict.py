"""The requirements verdict as a bar chart of normalised margins (matplotlib imported lazily)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import new_figure, styled, vector

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["margins_figure", "STATUS_COLORS"]

#: Bar colour of each status.
STATUS_COLORS = {"pass": "tab:green", "fail": "tab:red", "not evaluated": "0.75"}


@styled
def margins_figure(
    titles: Sequence[str],
    normalised_margins: ArrayLike,
    status: Sequence[str],
    texts: Sequence[str] | None = None,
    lower_bound: Sequence[bool] | None = None,
    *,
    limits: tuple[float, float] = (-2.0, 3.0),
    title: str = "Requirements: margin / limit",
    xlabel: str = "margin / limit [%]  (negative fails)",
    ax=None,
) -> Figure:
    """One horizontal bar per requirement: its margin divided by its limit, green when it
    passes (to the axis end when there is no finite margin), red when it fails, grey when it
    could not be evaluated.

    Parameters
    ----------
    titles : sequence of str
        Requirement names, drawn top to bottom.
    normalised_margins : array_like
        Margin / |limit| of each [-] (positive passes); NaN when not evaluated, +inf when it
        passed with nothing to measure (a bar to the axis end, "∞: no finite margin").
    status : sequence of str
        "pass", "fail" or "not evaluated".
    texts : sequence of str, optional
        The margin in engineering units, written beside each bar (e.g. "+0.18 mm").
    lower_bound : sequence of bool, optional
        The margin is only a lower bound (drawn with "≥").
    limits : (float, float)
        Axis range [-]; longer bars are cut with an arrow and their value written.
    title : str
        Axes title.
    xlabel : str
        Label of the margin axis (what each margin is divided by).
    ax : matplotlib Axes, optional
        Draw into this axes.

    Returns
    -------
    matplotlib.figure.Figure
    """
    names = [str(t) for t in titles]
    n = len(names)
    if n == 0:
        raise ValueError("titles: at least one requirement is required")
    value = vector("normalised_margins", normalised_margins, n)
    states = [str(s) for s in status]
    if len(states) != n or set(states) - set(STATUS_COLORS):
        raise ValueError(f"status: expected {n} of {sorted(STATUS_COLORS)}, got {states}")
    texts = [""] * n if texts is None else [str(t) for t in texts]
    bounds = [False] * n if lower_bound is None else [bool(b) for b in lower_bound]
    if len(texts) != n or len(bounds) != n:
        raise ValueError(f"texts and lower_bound: expected {n} entries like titles")
    lo_lim, hi_lim = limits
    finite = value[np.isfinite(value)]
    lo = max(lo_lim, min(-0.5, float(finite.min()) if finite.size else 0.0))
    hi = min(hi_lim, max(0.5, float(finite.max()) if finite.size else 0.0))
    span = hi - lo
    left = min(3.6, 0.35 + 0.078 * max(len(t) for t in names))
    fig, axes = new_figure(1, 1, (8.4, 0.42 * n + 1.3), ax=ax, left=left, right=0.3, bottom=0.6, top=0.4)
    ax = axes[0, 0]
    y = np.arange(n)[::-1].astype(float)
    ax.set_xlim(lo - 0.06 * span, hi + 0.3 * span)
    ax.set_ylim(-0.7, n - 0.3)
    for yi, v, state, text, bound in zip(y, value, states, texts, bounds):
        color = STATUS_COLORS[state]
        unbounded = v == np.inf and state == "pass"  # passed with nothing to measure (no phase crossover)
        no_margin = v == -np.inf and state == "fail"  # failed with nothing to measure
        if not np.isfinite(v) and not (unbounded or no_margin):
            ax.barh(yi, 0.02 * span, left=-0.01 * span, color=color, height=0.6, hatch="///", edgecolor="0.5")
            ax.annotate(
                "not evaluated",
                (0.0, yi),
                xytext=(6, 0),
                textcoords="offset points",
                va="center",
                fontsize=8,
                color="0.35",
            )
            continue
        shown = float(np.clip(v, lo, hi))
        ax.barh(yi, shown, color=color, height=0.6, alpha=0.9)
        if shown != v:
            ax.plot([shown], [yi], ">" if v > 0 else "<", color=color, ms=9, mec="k", mew=0.6, clip_on=False)
        if no_margin:
            number = "fails: no finite margin"
        elif state == "fail" and v > -0.005:  # fails without a margin to show (a thermal runaway): not "-0%"
            number = "fails"
        else:
            number = ("≥ " if bound else "") + f"{v:+.0%}"
        label = ("∞: no finite margin" if unbounded else number) + (f"  ({text})" if text else "")
        if v < 0:  # failed: the text on the empty positive side, clear of the names
            ax.annotate(
                label,
                (0.0, yi),
                xytext=(7, 0),
                textcoords="offset points",
                ha="left",
                va="center",
                fontsize=8,
                color="tab:red",
            )
        elif shown != v:  # cut: inside the bar
            ax.annotate(
                label,
                (shown, yi),
                xytext=(-12, 0),
                textcoords="offset points",
                ha="right",
                va="center",
                fontsize=8,
                color="white",
                fontweight="bold",
            )
        else:
            ax.annotate(
                label, (shown, yi), xytext=(7, 0), textcoords="offset points", ha="left", va="center", fontsize=8
            )
    ax.axvline(0.0, color="k", lw=1.0)
    ax.set_yticks(y, names)
    ax.grid(axis="y", visible=False)
    from matplotlib.ticker import PercentFormatter

    ax.xaxis.set_major_formatter(PercentFormatter(1.0, decimals=0))
    ax.set_xlabel(xlabel)
    ax.set_title(title)
    return fig
