"""Report figures for ``flexshaft run``: responses over speed, safety factor (and, re-exported
here, the Campbell diagram, shapes and :func:`save_figure`).

Every function takes plain numpy arrays (SI units, speeds in rpm, frequencies in Hz) and an
optional ``ax``, and returns a :class:`matplotlib.figure.Figure`. Lengths are given in metres
and drawn in millimetres; this module is the edge where that conversion happens. matplotlib is
imported inside the functions (Agg backend, no pyplot state), so importing this module stays
light. The module knows nothing of models or analyses.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.campbell import campbell_figure
from flexshaft.plot.output import save_figure
from flexshaft.plot.response import bode_figure, orbit_figure
from flexshaft.plot.shapes import deflected_shape_figure, mode_shapes_figure
from flexshaft.plot.style import MM_PER_M, log_scale, magnitude, mark_operating, new_figure, styled, vector

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "campbell_figure",
    "imbalance_response_figure",
    "deflected_shape_figure",
    "safety_factor_figure",
    "mode_shapes_figure",
    "actuator_figure",
    "bode_figure",
    "orbit_figure",
    "load_shares_figure",
    "save_figure",
]


@styled
def imbalance_response_figure(
    speeds_rpm: ArrayLike,
    amplitudes: Mapping[str, ArrayLike],
    operating_rpm: float | None = None,
    gap: float | None = None,
    *,
    log_y: bool = False,
    title: str = "Imbalance response",
    speed_range_rpm: tuple[float, float] | None = None,
    ax=None,
) -> Figure:
    """Imbalance response amplitude against spin speed, one curve per named output.

    Parameters
    ----------
    speeds_rpm : array_like, shape (n_speeds,)
        Spin speeds [rpm].
    amplitudes : mapping of str to array_like, each shape (n_speeds,)
        Response amplitude of each output, e.g. "max shaft", "amb_1" [m]; the magnitude is
        plotted (complex values allowed), in millimetres.
    operating_rpm : float, optional
        Operating speed [rpm], drawn as a vertical line.
    gap : float, optional
        Auxiliary (touchdown) bearing radial gap [m], drawn as a horizontal line.
    log_y : bool
        Logarithmic amplitude axis.
    title : str
        Axes title.
    speed_range_rpm : (float, float), optional
        The operating speed range [rpm], shaded (the spin-up checks end at its top).
    ax : matplotlib Axes, optional
        Draw into this axes.

    Returns
    -------
    matplotlib.figure.Figure
    """
    speeds = vector("speeds_rpm", speeds_rpm)
    fig, axes = new_figure(1, 1, (8.0, 4.8), ax=ax)
    ax = axes[0, 0]
    positive = gap is not None and gap > 0  # something a log axis can show
    for name, values in amplitudes.items():
        amplitude_mm = magnitude(f"amplitudes[{name!r}]", values, speeds.size) * MM_PER_M
        positive = positive or bool(np.any(amplitude_mm > 0.0))
        if log_y:
            amplitude_mm = np.where(amplitude_mm > 0.0, amplitude_mm, np.nan)
        ax.plot(speeds, amplitude_mm, label=name)
    log_y = log_y and positive  # a zero response (a design without imbalance): a linear axis
    if gap is not None:
        ax.axhline(gap * MM_PER_M, color="k", ls="--", lw=1.2, label=f"auxiliary-bearing gap {gap * MM_PER_M:.3g} mm")
    mark_operating(ax, operating_rpm, speed_range_rpm=speed_range_rpm)
    if log_y:
        log_scale(ax)
    else:
        ax.set_ylim(bottom=0.0)
    ax.set_xlim(speeds.min(), speeds.max())
    ax.set_xlabel("spin speed Ω [rpm]")
    ax.set_ylabel("amplitude [mm]")
    ax.set_title(title)
    ax.legend(loc="best")
    return fig


def _free_band(ax, xs: np.ndarray, values: np.ndarray) -> tuple[float, str]:
    """Axes-fraction height and vertical alignment of the emptiest horizontal band for a text
    box: below the curve when there is room there, else above it."""
    scaled = (ax.transScale + ax.transLimits).transform(np.column_stack([xs, values]))[:, 1]
    scaled = scaled[np.isfinite(scaled)]
    low, high = (float(scaled.min()), float(scaled.max())) if scaled.size else (0.5, 0.5)
    room_below, room_above = low - 0.12, 0.97 - high  # the failure line R = 1 sits near the bottom
    if room_below >= max(room_above, 0.22):
        return 0.12 + 0.5 * room_below, "center"
    if room_above >= 0.22:
        return high + 0.5 * room_above, "center"
    return 0.5, "center"


@styled
def safety_factor_figure(
    x: ArrayLike,
    safety_factor: ArrayLike,
    critical_x: float | None = None,
    label: str | None = None,
    *,
    critical_r: float | None = None,
    required: float | None = None,
    log_y: bool | None = None,
    title: str = "Shaft strength",
    ax=None,
) -> Figure:
    """Minimum Tsai-Wu safety factor along the shaft with the critical point annotated.

    The annotation sits inside the axes in the emptiest band (below the curve when there is
    room), so it covers neither the curve nor the title.

    Parameters
    ----------
    x : array_like, shape (n,)
        Axial stations [m].
    safety_factor : array_like, shape (n,)
        Minimum safety factor over plies and circumference at each station [-]; inf or NaN
        (unloaded) are not drawn.
    critical_x : float, optional
        Station of the critical point [m]; default the minimum of ``safety_factor``.
    critical_r : float, optional
        Safety factor at the critical point [-] (the analysis's own minimum, which can lie between
        the drawn stations); default interpolated from ``safety_factor``.
    label : str, optional
        What fails there, e.g. "ply 3 (+55°), φ = 120°, σ2 dominates".
    required : float, optional
        The safety factor the requirements ask for (the verdict's limit), drawn as a second
        dashed line beside the failure line R = 1.
    log_y : bool, optional
        Logarithmic axis; by default chosen when the finite values span more than 50:1.
    title : str
        Axes title.
    ax : matplotlib Axes, optional
        Draw into this axes.

    Returns
    -------
    matplotlib.figure.Figure
    """
    xs = vector("x", x)
    factor = vector("safety_factor", safety_factor, xs.size)
    finite = np.isfinite(factor) & (factor > 0.0)
    if not finite.any():
        raise ValueError("safety_factor: no finite positive value to plot")
    factor = np.where(finite, factor, np.nan)
    if critical_x is None:
        critical_x = float(xs[np.nanargmin(factor)])
    if critical_r is None:
        critical_r = float(np.interp(critical_x, xs[finite], factor[finite]))
    if log_y is None:
        log_y = bool(np.nanmax(factor) / np.nanmin(factor) > 50.0)

    fig, axes = new_figure(1, 1, (8.0, 4.5), ax=ax)
    ax = axes[0, 0]
    ax.plot(xs, factor, color="C0", label="minimum safety factor R")
    ax.axhline(1.0, color="tab:red", ls="--", lw=1.3, label="failure (R = 1)")
    if required is not None:
        ax.axhline(required, color="tab:orange", ls="--", lw=1.3, label=f"required (R ≥ {required:g})")
    ax.plot(critical_x, critical_r, "o", color="tab:red", ms=7, label="critical point")
    top = max(np.nanmax(factor), required or 0.0)
    if log_y:
        log_scale(ax)
        ax.set_ylim(min(0.7, 0.8 * np.nanmin(factor)), 2.0 * top)
    else:
        ax.set_ylim(0.0, max(1.15 * top, 1.3))
    ax.set_xlim(xs.min(), xs.max())
    text = f"R = {critical_r:.3g} at x = {critical_x:.3g} m"
    text = f"{label}\n{text}" if label else text
    y_text, va = _free_band(ax, xs, factor)
    x_frac = (critical_x - xs.min()) / max(xs.max() - xs.min(), 1e-12)
    right_half = x_frac > 0.5
    ax.annotate(
        text,
        (critical_x, critical_r),
        xytext=(x_frac - 0.04 if right_half else x_frac + 0.04, y_text),
        textcoords="axes fraction",
        ha="right" if right_half else "left",
        va=va,
        fontsize=9,
        bbox={"boxstyle": "round", "fc": "white", "ec": "0.6"},
        arrowprops={"arrowstyle": "->", "color": "0.3"},
    )
    ax.set_xlabel("axial position x [m]")
    ax.set_ylabel("Tsai-Wu safety factor R [-]")
    ax.set_title(title)
    ax.legend(loc="lower right" if not right_half else "lower left", fontsize=8)
    return fig


@styled
def actuator_figure(
    speeds_rpm: ArrayLike,
    displacement: Mapping[str, ArrayLike],
    force: Mapping[str, ArrayLike],
    gap: float | Mapping[str, float] | None = None,
    *,
    operating_rpm: float | None = None,
    force_capacity: float | Mapping[str, float] | None = None,
    static_offset: Mapping[str, float] | None = None,
    static_force: Mapping[str, float] | None = None,
    checked: Mapping[str, tuple[float, float, float, float]] | None = None,
    speed_range_rpm: tuple[float, float] | None = None,
    ax=None,
) -> Figure:
    """Actuator (magnetic bearing) excursion and force against spin speed: static + spin-up
    against each actuator's limits, what the actuator checks judge.

    Parameters
    ----------
    speeds_rpm : array_like, shape (n_speeds,)
        Spin speeds [rpm].
    displacement : mapping of str to array_like, each shape (n_speeds,)
        Spin-up (dynamic) relative displacement amplitude at each actuator [m]; drawn in mm,
        plus the static offset.
    force : mapping of str to array_like, each shape (n_speeds,)
        Spin-up (dynamic) actuator force amplitude [N], drawn plus the static force.
    gap : float or mapping of str to float, optional
        Auxiliary-bearing clearance [m], one for all or per actuator, drawn on the excursion panel.
    operating_rpm : float, optional
        Operating speed [rpm].
    force_capacity : float or mapping of str to float, optional
        Largest force the actuator can produce [N], one or per actuator, drawn on the force panel.
    static_offset, static_force : mapping of str to float, optional
        Static relative displacement [m] and static force [N] of each actuator: the orbit is
        centred on the static position, so the excursion is static + dynamic (the dynamic part
        alone is drawn thin and dashed beside it). Omitted: 0.
    checked : mapping of str to (speed [rpm], excursion [m], speed [rpm], force [N]), optional
        The peaks the actuator checks judge (static + spin-up, to the highest operating speed),
        marked.
    speed_range_rpm : (float, float), optional
        The operating speed range [rpm], shaded (the checks end at its top).
    ax : sequence of two matplotlib Axes, optional
        Excursion and force panels.

    Returns
    -------
    matplotlib.figure.Figure
    """
    speeds = vector("speeds_rpm", speeds_rpm)
    fig, axes = new_figure(2, 1, (8.0, 6.8), ax=ax, hspace=0.3)
    top, bottom = axes[0, 0], axes[1, 0]
    offsets, statics = dict(static_offset or {}), dict(static_force or {})
    highest = [0.0, 0.0]
    for k, name in enumerate(displacement):
        colour = f"C{k % 10}"
        dynamic = magnitude(f"displacement[{name!r}]", displacement[name], speeds.size) * MM_PER_M
        excursion = dynamic + offsets.get(name, 0.0) * MM_PER_M
        top.plot(speeds, excursion, color=colour, lw=1.8, label=f"{name}: static + spin-up")
        if name in offsets:
            top.plot(speeds, dynamic, color=colour, lw=0.8, ls=":", label=f"{name}: spin-up orbit alone")
        highest[0] = max(highest[0], float(np.max(excursion)))
    for k, name in enumerate(force):
        colour = f"C{k % 10}"
        dynamic = magnitude(f"force[{name!r}]", force[name], speeds.size)
        total = dynamic + statics.get(name, 0.0)
        bottom.plot(speeds, total, color=colour, lw=1.8, label=f"{name}: static + spin-up")
        if name in statics:
            bottom.plot(speeds, dynamic, color=colour, lw=0.8, ls=":", label=f"{name}: spin-up force alone")
        highest[1] = max(highest[1], float(np.max(total)))
    names = list(displacement)
    for panel, limits, unit, scale, label in (
        (top, gap, "mm", MM_PER_M, "gap"),
        (bottom, force_capacity, "N", 1.0, "force capacity"),
    ):
        if limits is None:
            continue
        per = dict(limits) if isinstance(limits, Mapping) else dict.fromkeys(names or ["all"], float(limits))
        drawn: dict[float, list[str]] = {}  # limit value: the bearings that have it
        for name, value in per.items():
            drawn.setdefault(float(value), []).append(name)
        for value, owners in drawn.items():
            who = "" if len(drawn) == 1 else f" ({', '.join(owners)})"
            panel.axhline(value * scale, color="k", ls="--", lw=1.2, label=f"{label} {value * scale:.4g} {unit}{who}")
            index = 0 if panel is top else 1
            highest[index] = max(highest[index], value * scale)
    for k, (name, (orbit_rpm, orbit, force_rpm, force_value)) in enumerate((checked or {}).items()):
        colour = f"C{names.index(name) % 10 if name in names else k % 10}"
        top.plot([orbit_rpm], [orbit * MM_PER_M], "D", color=colour, ms=7, mec="k", label=f"{name}: checked peak")
        bottom.plot([force_rpm], [force_value], "D", color=colour, ms=7, mec="k", label=f"{name}: checked peak")
    for panel, high in zip((top, bottom), highest):
        mark_operating(panel, operating_rpm, speed_range_rpm=speed_range_rpm)
        panel.set_ylim(0.0, 1.12 * high if high > 0 else 1.0)
        panel.legend(loc="best", fontsize=7.5, ncols=3)
    top.set_xlim(speeds.min(), speeds.max())
    top.set_ylabel("excursion [mm]")
    bottom.set_ylabel("actuator force [N]")
    bottom.set_xlabel("spin speed Ω [rpm]")
    top.set_title("Active bearing actuators: static + spin-up against the limits")
    return fig


@styled
def load_shares_figure(shares: Mapping[str, float], title: str = "What loads the critical ply", *, ax=None) -> Figure:
    """Horizontal bars of each load's share of the Tsai-Wu failure index at the critical
    point [-] (they sum to 1; a negative share relieves the ply)."""
    if not shares:
        raise ValueError("shares: at least one load share is required")
    names = list(shares)
    values = vector("shares", [shares[k] for k in names])
    fig, axes = new_figure(1, 1, (7.0, 0.45 * len(names) + 1.4), ax=ax, left=1.2, bottom=0.6)
    ax = axes[0, 0]
    colors = np.where(values >= 0, "C0", "C2")
    y = np.arange(len(names))[::-1]
    ax.barh(y, values, color=colors, height=0.6)
    for yi, v in zip(y, values):
        ax.annotate(
            f"{v:+.1%}",
            (v, yi),
            xytext=(4 if v >= 0 else -4, 0),
            textcoords="offset points",
            ha="left" if v >= 0 else "right",
            va="center",
            fontsize=8,
        )
    ax.set_yticks(y, names)
    ax.axvline(0.0, color="k", lw=0.8)
    lo, hi = min(0.0, float(values.min())), max(0.0, float(values.max()))
    ax.set_xlim(lo - 0.2 * (hi - lo) - 1e-9, hi + 0.2 * (hi - lo) + 1e-9)
    ax.set_xlabel("share of the failure index at the critical point [-]")
    ax.set_title(title)
    ax.grid(axis="y", visible=False)
    return fig
