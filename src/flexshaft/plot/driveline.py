"""Report figures for ``flexshaft run``: Campbell diagram, responses, shapes, safety factor.

Every function takes plain numpy arrays (SI units, speeds in rpm, frequencies in Hz) and
returns a :class:`matplotlib.figure.Figure`. Lengths are given in metres and drawn in
millimetres; this module is the edge where that conversion happens. matplotlib is imported
inside the functions (Agg backend, no pyplot state), so importing this module stays light.
The module knows nothing of models or analyses.
"""

from __future__ import annotations

import sys
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import (
    MM_PER_M,
    RPM_PER_HZ,
    WHIRL_LINESTYLE,
    magnitude,
    mark_operating,
    new_figure,
    styled,
    vector,
)
from flexshaft.plot.shapes import deflected_shape_figure, mode_shapes_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "campbell_figure",
    "imbalance_response_figure",
    "deflected_shape_figure",
    "safety_factor_figure",
    "mode_shapes_figure",
    "actuator_figure",
    "save_figure",
]


@styled
def campbell_figure(
    speeds_rpm: ArrayLike,
    frequencies_hz: ArrayLike,
    whirl: ArrayLike,
    critical_speeds_rpm: Sequence[float] = (),
    operating_rpm: float | None = None,
    harmonics: Sequence[float] = (1,),
) -> Figure:
    """Campbell diagram: tracked natural frequencies against spin speed.

    Parameters
    ----------
    speeds_rpm : array_like, shape (n_speeds,)
        Spin speeds [rpm].
    frequencies_hz : array_like, shape (n_speeds, n_modes)
        Damped natural frequency of each tracked mode [Hz]; NaN where a mode is not found.
    whirl : array_like of str, shape (n_speeds, n_modes)
        "forward" (solid line), "backward" (dashed) or "planar" (dotted) at each point.
    critical_speeds_rpm : sequence of float
        Critical speeds [rpm], marked on the 1x excitation line (f = Omega / 60).
    operating_rpm : float, optional
        Operating speed [rpm], drawn as a vertical line.
    harmonics : sequence of float
        Orders k of the excitation lines f = k Omega / 60 [Hz].

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.lines import Line2D

    speeds = vector("speeds_rpm", speeds_rpm)
    freqs = np.asarray(frequencies_hz, dtype=float)
    freqs = freqs.reshape(-1, 1) if freqs.ndim == 1 else freqs
    labels = np.asarray(whirl, dtype=str).reshape(freqs.shape) if np.size(whirl) == freqs.size else None
    if freqs.ndim != 2 or freqs.shape[0] != speeds.size or labels is None:
        raise ValueError(
            f"frequencies_hz and whirl must both have shape (n_speeds={speeds.size}, n_modes); "
            f"got {np.shape(frequencies_hz)} and {np.shape(whirl)}"
        )
    unknown = set(np.unique(labels)) - set(WHIRL_LINESTYLE)
    if unknown:
        raise ValueError(f"whirl: unknown labels {sorted(unknown)}; allowed {sorted(WHIRL_LINESTYLE)}")

    fig, axes = new_figure(1, 1, (8.0, 5.5))
    ax = axes[0, 0]
    import matplotlib

    colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]  # tab10, set by styled()
    for mode in range(freqs.shape[1]):
        color = colors[mode % len(colors)]
        f, w = freqs[:, mode], labels[:, mode]
        start = 0
        for stop in range(1, speeds.size + 1):
            if stop == speeds.size or w[stop] != w[start]:
                end = min(stop + 1, speeds.size)  # one point of overlap keeps the curve continuous
                ax.plot(speeds[start:end], f[start:end], color=color, ls=WHIRL_LINESTYLE[w[start]])
                start = stop
        finite = np.flatnonzero(np.isfinite(f))
        if finite.size:
            ax.annotate(str(mode + 1), (speeds[finite[-1]], f[finite[-1]]), xytext=(3, 0),
                        textcoords="offset points", color=color, fontsize=7.5, va="center")

    f_max = np.nanmax(freqs) if np.isfinite(freqs).any() else 1.0
    span = np.array([speeds.min(), speeds.max()])
    handles = [Line2D([], [], color="0.3", ls=WHIRL_LINESTYLE[name],
                      label="torsional / axial (no 1× critical)" if name == "none" else f"{name} whirl")
               for name in WHIRL_LINESTYLE if name in labels]
    for k, order in enumerate(harmonics):
        (line,) = ax.plot(span, order * span / RPM_PER_HZ, color="0.15", lw=1.0,
                          ls=(0, (6, 2, 1, 2)) if k else "-", alpha=0.8, label=f"{order:g}× excitation")
        handles.append(line)
    critical = vector("critical_speeds_rpm", critical_speeds_rpm)
    if critical.size:
        (marker,) = ax.plot(critical, critical / RPM_PER_HZ, "o", mfc="none", mec="k", mew=1.4, ms=8,
                            label="critical speed")
        handles.append(marker)
        for rpm in critical:
            ax.annotate(f"{rpm:.0f} rpm", (rpm, rpm / RPM_PER_HZ), xytext=(5, -12),
                        textcoords="offset points", fontsize=8)
    mark_operating(ax, operating_rpm)
    if operating_rpm is not None:
        handles.append(ax.get_lines()[-1])
    ax.set_xlim(span[0], span[1])
    ax.set_ylim(0.0, 1.08 * max(f_max, critical.max(initial=0.0) / RPM_PER_HZ))
    ax.set_xlabel("spin speed Ω [rpm]")
    ax.set_ylabel("natural frequency [Hz]")
    ax.set_title("Campbell diagram")
    ax.legend(handles=handles, loc="upper left")
    return fig


@styled
def imbalance_response_figure(
    speeds_rpm: ArrayLike,
    amplitudes: Mapping[str, ArrayLike],
    operating_rpm: float | None = None,
    gap: float | None = None,
    *,
    log_y: bool = False,
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

    Returns
    -------
    matplotlib.figure.Figure
    """
    speeds = vector("speeds_rpm", speeds_rpm)
    fig, axes = new_figure(1, 1, (8.0, 4.8))
    ax = axes[0, 0]
    for name, values in amplitudes.items():
        amplitude_mm = magnitude(f"amplitudes[{name!r}]", values, speeds.size) * MM_PER_M
        if log_y:
            amplitude_mm = np.where(amplitude_mm > 0.0, amplitude_mm, np.nan)
        ax.plot(speeds, amplitude_mm, label=name)
    if gap is not None:
        ax.axhline(gap * MM_PER_M, color="k", ls="--", lw=1.2,
                   label=f"auxiliary-bearing gap {gap * MM_PER_M:.3g} mm")
    mark_operating(ax, operating_rpm)
    if log_y:
        ax.set_yscale("log")
        ax.grid(which="minor", alpha=0.12)
    else:
        ax.set_ylim(bottom=0.0)
    ax.set_xlim(speeds.min(), speeds.max())
    ax.set_xlabel("spin speed Ω [rpm]")
    ax.set_ylabel("amplitude [mm]")
    ax.set_title("Imbalance response")
    ax.legend(loc="best")
    return fig


@styled
def safety_factor_figure(
    x: ArrayLike,
    safety_factor: ArrayLike,
    critical_x: float | None = None,
    label: str | None = None,
    *,
    log_y: bool | None = None,
) -> Figure:
    """Minimum Tsai-Wu safety factor along the shaft with the critical point annotated.

    Parameters
    ----------
    x : array_like, shape (n,)
        Axial stations [m].
    safety_factor : array_like, shape (n,)
        Minimum safety factor over plies and circumference at each station [-]; inf or NaN
        (unloaded) are not drawn.
    critical_x : float, optional
        Station of the critical point [m]; default the minimum of ``safety_factor``.
    label : str, optional
        What fails there, e.g. "ply 3 (+55°), φ = 120°, σ2 dominates".
    log_y : bool, optional
        Logarithmic axis; by default chosen when the finite values span more than 50:1.

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
    critical_r = float(np.interp(critical_x, xs[finite], factor[finite]))
    if log_y is None:
        log_y = np.nanmax(factor) / np.nanmin(factor) > 50.0

    fig, axes = new_figure(1, 1, (8.0, 4.5))
    ax = axes[0, 0]
    ax.plot(xs, factor, color="C0", label="minimum safety factor R")
    ax.axhline(1.0, color="tab:red", ls="--", lw=1.3, label="failure (R = 1)")
    ax.plot(critical_x, critical_r, "o", color="tab:red", ms=7, label="critical point")
    text = f"R = {critical_r:.3g} at x = {critical_x:.3g} m"
    text = f"{label}\n{text}" if label else text
    right_half = critical_x > 0.5 * (xs.min() + xs.max())
    ax.annotate(text, (critical_x, critical_r), xytext=(-25 if right_half else 25, 35),
                textcoords="offset points", ha="right" if right_half else "left", fontsize=9,
                bbox={"boxstyle": "round", "fc": "white", "ec": "0.6"},
                arrowprops={"arrowstyle": "->", "color": "0.3"})
    if log_y:
        ax.set_yscale("log")
        ax.grid(which="minor", alpha=0.12)
    else:
        ax.set_ylim(0.0, max(1.15 * np.nanmax(factor), 1.3))
    ax.set_xlim(xs.min(), xs.max())
    ax.set_xlabel("axial position x [m]")
    ax.set_ylabel("Tsai-Wu safety factor R [-]")
    ax.set_title("Shaft strength")
    ax.legend(loc="best")
    return fig


@styled
def actuator_figure(
    speeds_rpm: ArrayLike,
    displacement: Mapping[str, ArrayLike],
    force: Mapping[str, ArrayLike],
    gap: float | None = None,
    *,
    operating_rpm: float | None = None,
) -> Figure:
    """Actuator (magnetic bearing) relative displacement and force against spin speed.

    Parameters
    ----------
    speeds_rpm : array_like, shape (n_speeds,)
        Spin speeds [rpm].
    displacement : mapping of str to array_like, each shape (n_speeds,)
        Shaft-to-stator relative displacement amplitude at each actuator [m]; drawn in mm.
    force : mapping of str to array_like, each shape (n_speeds,)
        Actuator force amplitude [N].
    gap : float, optional
        Actuator air gap or auxiliary-bearing clearance [m], drawn on the displacement panel.
    operating_rpm : float, optional
        Operating speed [rpm].

    Returns
    -------
    matplotlib.figure.Figure
    """
    speeds = vector("speeds_rpm", speeds_rpm)
    fig, axes = new_figure(2, 1, (8.0, 6.5))
    top, bottom = axes[0, 0], axes[1, 0]
    for name, values in displacement.items():
        top.plot(speeds, magnitude(f"displacement[{name!r}]", values, speeds.size) * MM_PER_M, label=name)
    for name, values in force.items():
        bottom.plot(speeds, magnitude(f"force[{name!r}]", values, speeds.size), label=name)
    if gap is not None:
        top.axhline(gap * MM_PER_M, color="k", ls="--", lw=1.2, label=f"gap {gap * MM_PER_M:.3g} mm")
    for ax in (top, bottom):
        mark_operating(ax, operating_rpm)
        ax.set_ylim(bottom=0.0)
        ax.legend(loc="best")
    top.set_xlim(speeds.min(), speeds.max())
    top.set_ylabel("relative displacement [mm]")
    bottom.set_ylabel("actuator force [N]")
    bottom.set_xlabel("spin speed Ω [rpm]")
    top.set_title("Active bearing actuators")
    return fig


def save_figure(fig: Figure, folder: str | Path, stem: str) -> dict[str, Path]:
    """Write ``stem.png`` (150 dpi) and ``stem.svg`` into ``folder`` and release the figure.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure to save.
    folder : str or Path
        Output folder, created if missing.
    stem : str
        File name without extension; no path separators.

    Returns
    -------
    dict
        ``{"png": Path, "svg": Path}``.
    """
    if not stem or Path(stem).name != stem or stem in (".", ".."):
        raise ValueError(f"stem: expected a plain file name without folders, got {stem!r}")
    out = Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    paths = {"png": out / f"{stem}.png", "svg": out / f"{stem}.svg"}
    fig.savefig(paths["png"], dpi=150, format="png")
    fig.savefig(paths["svg"], format="svg", metadata={"Date": None})  # reproducible files
    if "matplotlib.pyplot" in sys.modules:  # only pyplot keeps a reference to figures
        sys.modules["matplotlib.pyplot"].close(fig)
    return paths
