"""Figures of ``flexshaft compare``: two drivelines overlaid on the same axes.

Every function takes plain arrays keyed by the design's label (SI lengths in metres, drawn in
millimetres; speeds in rpm; frequencies in Hz) and returns a :class:`matplotlib.figure.Figure`.
Design A is drawn in blue, design B in orange, in the order of the mapping. matplotlib is
imported inside the functions (see :mod:`flexshaft.plot.style`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import (
    MM_PER_M,
    RPM_PER_HZ,
    WHIRL_LINESTYLE,
    log_scale,
    mark_operating,
    new_figure,
    styled,
    vector,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "campbell_overlay_figure",
    "mass_breakdown_figure",
    "safety_factor_overlay_figure",
    "spinup_overlay_figure",
    "static_deflection_overlay_figure",
]

_COLORS = ("tab:blue", "tab:orange")


def _two(name: str, data: Mapping) -> list:
    if not 1 <= len(data) <= 2:
        raise ValueError(f"{name}: expected one or two designs, got {len(data)}")
    return list(data.items())


def _per_design(value, labels: Sequence[str]) -> list[tuple[int, str, float]]:
    """``(index, label, value)`` of each design with a value: ``value`` one number for every
    design, or a mapping of each design's label to its own (None: none)."""
    if value is None:
        return []
    own = value if isinstance(value, Mapping) else dict.fromkeys(labels, value)
    return [(k, label, float(own[label])) for k, label in enumerate(labels) if own.get(label) is not None]


def _limit_lines(
    ax, limit, labels: Sequence[str], scale: float, text: str, color: str, unit: str = "", fmt: str = ".3g"
) -> list[float]:
    """Horizontal lines at a requirement's limit (:func:`_per_design`: from each design's
    ``[requirements]``, which the verdict checks it against). One line when the designs' limits
    agree, else one per design in its colour, labelled with its design. Returns the values drawn
    (times ``scale``)."""
    values = [(k, label, value * scale) for k, label, value in _per_design(limit, labels)]
    if len({value for _, _, value in values}) == 1:
        value = values[0][2]
        ax.axhline(value, color=color, ls="--", lw=1.2, label=f"{text} {value:{fmt}}{unit}")
    else:
        for k, label, value in values:
            ax.axhline(value, color=_COLORS[k], ls="--", lw=1.2, label=f"{text} ({label}) {value:{fmt}}{unit}")
    return [value for _, _, value in values]


def _operating_lines(ax, operating, labels: Sequence[str]) -> list:
    """Vertical lines at the operating speed [rpm] (:func:`_per_design`). One line when the
    designs agree (:func:`~flexshaft.plot.style.mark_operating`), else one per design in its
    colour, named after it. Returns the lines drawn."""
    values = _per_design(operating, labels)
    if len({value for _, _, value in values}) == 1:
        mark_operating(ax, values[0][2])
        return [ax.get_lines()[-1]]
    return [
        ax.axvline(value, color=_COLORS[k], ls="-.", lw=1.2, label=f"operating speed ({label}) {value:.0f} rpm")
        for k, label, value in values
    ]


@styled
def campbell_overlay_figure(
    curves: Mapping[str, tuple[ArrayLike, ArrayLike, ArrayLike]],
    operating_rpm: float | Mapping[str, float | None] | None = None,
) -> Figure:
    """Campbell diagrams of two designs on one axes.

    Parameters
    ----------
    curves : mapping of label to (speeds_rpm, frequencies_hz, whirl)
        ``speeds_rpm`` (n_speeds,) [rpm]; ``frequencies_hz`` (n_speeds, n_modes) [Hz] (NaN
        where a mode is not found); ``whirl`` labels of the same shape ("forward", "backward",
        "planar", "none" for torsional/axial modes, not drawn).
    operating_rpm : float or mapping of label to float, optional
        Operating speed [rpm]: one for both designs, or each design's own (one line per design
        where they differ).
    """
    from matplotlib.lines import Line2D

    fig, axes = new_figure(1, 1, (8.0, 5.5))
    ax = axes[0, 0]
    handles, top, f_max = [], 0.0, 0.0
    for (label, (speeds, freqs, whirl)), color in zip(_two("curves", curves), _COLORS):
        speeds = vector(f"curves[{label!r}] speeds", speeds)
        freqs = np.asarray(freqs, dtype=float).reshape(speeds.size, -1)
        whirl = np.asarray(whirl, dtype=str).reshape(freqs.shape)
        for mode in range(freqs.shape[1]):
            f, w = freqs[:, mode], whirl[:, mode]
            start = 0
            for stop in range(1, speeds.size + 1):  # runs of one label, one point of overlap
                if stop == speeds.size or w[stop] != w[start]:
                    end = min(stop + 1, speeds.size)
                    if w[start] != "none":
                        ax.plot(speeds[start:end], f[start:end], color=color, ls=WHIRL_LINESTYLE[w[start]], lw=1.3)
                    start = stop
        handles.append(Line2D([], [], color=color, label=label))
        top = max(top, speeds.max())
        lateral = np.where(whirl != "none", freqs, np.nan)
        if np.isfinite(lateral).any():
            f_max = max(f_max, np.nanmax(lateral))
    span = np.array([0.0, top])
    (line,) = ax.plot(span, span / RPM_PER_HZ, color="0.15", lw=1.0, label="1× excitation")
    handles.append(line)
    handles += [
        Line2D([], [], color="0.35", ls=WHIRL_LINESTYLE[name], label=f"{name} whirl")
        for name in ("forward", "backward", "planar")
    ]
    handles += _operating_lines(ax, operating_rpm, [label for label, _ in _two("curves", curves)])
    ax.set_xlim(0.0, top)
    ax.set_ylim(0.0, 1.08 * max(f_max, top / RPM_PER_HZ))
    ax.set_xlabel("spin speed Ω [rpm]")
    ax.set_ylabel("natural frequency [Hz]")
    ax.set_title("Campbell diagrams, lateral modes")
    ax.legend(handles=handles, loc="upper left")
    return fig


@styled
def spinup_overlay_figure(
    responses: Mapping[str, tuple[ArrayLike, ArrayLike]],
    operating_rpm: float | Mapping[str, float | None] | None = None,
    limit: float | Mapping[str, float | None] | None = None,
) -> Figure:
    """Peak shaft orbit during spin-up of two designs (log scale).

    Parameters
    ----------
    responses : mapping of label to (speeds_rpm, peak_orbit)
        Speeds [rpm] and the largest shaft orbit amplitude over the shaft at each speed [m].
    operating_rpm : float or mapping of label to float, optional
        Operating speed [rpm], as :func:`campbell_overlay_figure`'s.
    limit : float or mapping of label to float, optional
        Spin-up orbit limit [m], drawn as a horizontal line: one for both designs, or each
        design's own (one line per design where they differ).
    """
    fig, axes = new_figure(1, 1, (8.0, 4.8))
    ax = axes[0, 0]
    top = 0.0
    for (label, (speeds, peak)), color in zip(_two("responses", responses), _COLORS):
        speeds = vector(f"responses[{label!r}] speeds", speeds)
        amplitude = vector(f"responses[{label!r}] peak", np.abs(np.asarray(peak)), speeds.size) * MM_PER_M
        ax.plot(speeds, np.where(amplitude > 0, amplitude, np.nan), color=color, label=label)
        top = max(top, speeds.max())
    labels = [label for label, _ in _two("responses", responses)]
    _limit_lines(ax, limit, labels, MM_PER_M, "limit", "k", " mm")
    _operating_lines(ax, operating_rpm, labels)
    log_scale(ax)
    ax.set_xlim(0.0, top)
    ax.set_xlabel("spin speed Ω [rpm]")
    ax.set_ylabel("largest shaft orbit [mm]")
    ax.set_title("Imbalance response during spin-up")
    ax.legend(loc="best")
    return fig


@styled
def safety_factor_overlay_figure(
    curves: Mapping[str, tuple[ArrayLike, ArrayLike, str]], required: float | Mapping[str, float | None] | None = None
) -> Figure:
    """Strength safety factor along the driveline of two designs (log scale).

    Parameters
    ----------
    curves : mapping of label to (x, safety_factor, criterion)
        Stations [m], safety factor at each [-] (inf or NaN not drawn) and what it is, e.g.
        "Tsai-Wu" or "metal: min(yield, fatigue)".
    required : float or mapping of label to float, optional
        Required safety factor, drawn as a horizontal line: one for both designs, or each
        design's own (one line per design where they differ).
    """
    fig, axes = new_figure(1, 1, (8.0, 4.6))
    ax = axes[0, 0]
    lo, hi = np.inf, 0.0
    for (label, (x, factor, criterion)), color in zip(_two("curves", curves), _COLORS):
        xs = vector(f"curves[{label!r}] x", x)
        values = vector(f"curves[{label!r}] safety_factor", factor, xs.size)
        values = np.where(np.isfinite(values) & (values > 0), values, np.nan)
        ax.plot(xs, values, color=color, label=f"{label}: {criterion}")
        if np.isfinite(values).any():
            k = int(np.nanargmin(values))
            ax.plot(xs[k], values[k], "o", color=color, ms=6)
            ax.annotate(
                f"{values[k]:.3g} at {xs[k]:.2f} m",
                (xs[k], values[k]),
                xytext=(6, -14),
                textcoords="offset points",
                color=color,
                fontsize=8.5,
            )
            lo, hi = min(lo, np.nanmin(values)), max(hi, np.nanmax(values))
    drawn = _limit_lines(
        ax, required, [label for label, _ in _two("curves", curves)], 1.0, "required", "tab:red", fmt="g"
    )
    lo = min([lo, *drawn])
    log_scale(ax)
    if np.isfinite(lo):
        ax.set_ylim(0.7 * lo, 1.4 * hi if np.isfinite(hi) else None)
    from matplotlib.ticker import FuncFormatter, NullFormatter

    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))  # 1, 10, 100: no 10^n on a factor
    ax.yaxis.set_minor_formatter(FuncFormatter(lambda v, _: f"{v:g}") if hi / lo < 30 else NullFormatter())
    ax.set_xlabel("axial position x [m]")
    ax.set_ylabel("safety factor [-]")
    ax.set_title("Strength safety factor along the driveline (static + imbalance at Ω_op)")
    ax.legend(loc="best")
    return fig


@styled
def static_deflection_overlay_figure(
    shapes: Mapping[str, tuple[ArrayLike, ArrayLike, ArrayLike]], joints: Mapping[str, Sequence[float]] | None = None
) -> Figure:
    """Static deflection of the shaft of two designs: vertical and lateral panels [mm].

    Parameters
    ----------
    shapes : mapping of label to (x, v, w)
        Shaft node stations [m] and the static vertical v and lateral w displacement [m].
    joints : mapping of label to sequence of float, optional
        Coupling stations [m] of each design, marked on the curves.
    """
    fig, axes = new_figure(2, 1, (8.0, 6.2))
    joints = joints or {}
    for (label, (x, v, w)), color in zip(_two("shapes", shapes), _COLORS):
        xs = vector(f"shapes[{label!r}] x", x)
        for ax, values, name in ((axes[0, 0], v, "v"), (axes[1, 0], w, "w")):
            d = vector(f"shapes[{label!r}] {name}", np.real(np.asarray(values)), xs.size) * MM_PER_M
            ax.plot(xs, d, color=color, label=label)
            stations = np.asarray(joints.get(label, ()), dtype=float)
            if stations.size:
                ax.plot(
                    stations,
                    np.interp(stations, xs, d),
                    "D",
                    color=color,
                    ms=5,
                    mfc="white",
                    label=f"{label}: couplings",
                )
    axes[0, 0].set_ylabel("vertical v [mm]")
    axes[1, 0].set_ylabel("lateral w [mm]")
    axes[1, 0].set_xlabel("axial position x [m]")
    axes[0, 0].set_title("Static deflection of the shaft (manoeuvre, thrust and torque)")
    for ax in axes[:, 0]:
        ax.legend(loc="best")
    return fig


@styled
def mass_breakdown_figure(masses: Mapping[str, Mapping[str, float]]) -> Figure:
    """Stacked bars of the driveline mass by part kind, one bar per design.

    Parameters
    ----------
    masses : mapping of label to mapping of part kind to mass [kg]
    """
    items = _two("masses", masses)
    kinds = list(dict.fromkeys(k for _, parts in items for k in parts))
    fig, axes = new_figure(1, 1, (7.0, 4.4))
    ax = axes[0, 0]
    bottoms = np.zeros(len(items))
    import matplotlib

    colors = matplotlib.color_sequences["tab10"]
    for j, kind in enumerate(kinds):
        values = np.array([float(parts.get(kind, 0.0)) for _, parts in items])
        ax.bar(
            np.arange(len(items)), values, bottom=bottoms, color=colors[(j + 2) % len(colors)], label=kind, width=0.55
        )
        bottoms += values
    for i, total in enumerate(bottoms):
        ax.annotate(f"{total:.1f} kg", (i, total), xytext=(0, 4), textcoords="offset points", ha="center")
    ax.set_xticks(np.arange(len(items)), [label for label, _ in items])
    ax.set_ylim(0.0, 1.35 * max(bottoms.max(), 1.0))  # room for the legend above the bars
    ax.set_ylabel("mass [kg]")
    ax.set_title("Driveline mass by part kind")
    ax.legend(loc="upper center", ncol=min(len(kinds), 5), fontsize=8.5, frameon=False)
    return fig
