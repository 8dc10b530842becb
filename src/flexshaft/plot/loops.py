"""Figure of the magnetic-bearing loops' robustness: the sensitivity function and the open loop's
phase, with what the verdict's three loop checks read marked.

Every function takes plain arrays (frequencies in Hz, complex sensitivity S(iω) on them) keyed by
the loop's label and returns a :class:`matplotlib.figure.Figure`; matplotlib is imported inside
the functions (see :mod:`flexshaft.plot.style`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import log_scale, new_figure, styled, vector

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["loop_sensitivity_figure"]

#: Fill colours of the zones below the sensitivity-zone limits (A, B, C) and above them (D).
_ZONE_COLORS = ("tab:green", "yellowgreen", "orange", "tab:red")


#: A light box behind a note that sits over the curves.
_NOTE_BOX = {"boxstyle": "round,pad=0.2", "fc": "white", "ec": "none", "alpha": 0.85}


def _right_half(frequencies: np.ndarray, at: float) -> bool:
    """Whether ``at`` lies in the right half of the loop's logarithmic frequency axis: its note
    then runs to the left, inside the axes (audit a2: a peak near the top frequency wrote its
    note past the axes, over the zone labels)."""
    return bool(np.log(at) > 0.5 * (np.log(frequencies.min()) + np.log(frequencies.max())))


@styled
def loop_sensitivity_figure(
    loops: Mapping[str, tuple[ArrayLike, ArrayLike]],
    *,
    peaks: Mapping[str, tuple[float, float]] | None = None,
    phase_margins: Mapping[str, tuple[float, float]] | None = None,
    required_peak: float | None = None,
    required_phase_margin_deg: float | None = None,
    zone_limits: Sequence[float] = (),
    ax=None,
) -> Figure:
    """Sensitivity |S(iω)| (top) and the open loop's phase ∠L(iω), L = (1 − S)/S (bottom), of
    each loop against frequency.

    Parameters
    ----------
    loops : mapping of label to (frequencies_hz, sensitivity)
        Each loop's frequencies [Hz] (> 0) and complex S(iω) on them [-].
    peaks : mapping of label to (frequency_hz, peak), optional
        The sensitivity peak |S|max each loop's check reads (refined between the grid points),
        marked and written.
    phase_margins : mapping of label to (frequency_hz, margin_deg), optional
        Each loop's smallest phase margin and the gain crossover where it is taken: marked on
        the phase panel at ∠L = margin − 180°.
    required_peak : float, optional
        The largest |S|max the requirements allow, a dashed line.
    required_phase_margin_deg : float, optional
        The smallest phase margin they allow: a dashed line at its −180° + margin.
    zone_limits : sequence of float
        Upper limits of the sensitivity zones (e.g. ISO 14839-3's A, B, C: 3, 4, 5), shaded.
    ax : sequence of two matplotlib Axes, optional
        Draw into these (top, bottom).
    """
    if not loops:
        raise ValueError("loops: at least one loop is required")
    fig, axes = new_figure(2, 1, (8.0, 6.4), ax=ax, hspace=0.45, bottom=0.65, right=0.55)
    top, bottom = axes[0, 0], axes[1, 0]
    colors = [f"C{k % 10}" for k in range(len(loops))]
    highest = 1.0
    # every loop's peak and margin marked; the worst of each (the check's value) written
    worst_peak = max(peaks, key=lambda k: peaks[k][1]) if peaks else None
    worst_margin = min(phase_margins, key=lambda k: phase_margins[k][1]) if phase_margins else None
    for (label, (freqs, sensitivity)), color in zip(loops.items(), colors):
        f = vector(f"loops[{label!r}] frequencies", freqs)
        s = np.asarray(sensitivity, dtype=complex).ravel()
        if s.size != f.size:
            raise ValueError(f"loops[{label!r}]: {f.size} frequencies but {s.size} sensitivity values")
        if np.any(f <= 0):
            raise ValueError(f"loops[{label!r}] frequencies: must be > 0 Hz (a logarithmic axis)")
        magnitude = np.abs(s)
        highest = max(highest, float(np.nanmax(magnitude)))
        top.plot(f, magnitude, color=color, lw=1.3, label=label)
        with np.errstate(divide="ignore", invalid="ignore"):
            open_loop = (1.0 - s) / s
        bottom.plot(f, np.degrees(np.angle(open_loop)), color=color, lw=1.1, label=label)
        if peaks and label in peaks:
            f_peak, peak = peaks[label]
            top.plot(f_peak, peak, "o", color=color, ms=6, mec="k", mew=0.6)
            if label == worst_peak:
                top.annotate(
                    f"|S|max {peak:.3g} at {f_peak:.4g} Hz ({label})",
                    (f_peak, peak),
                    xytext=(-8 if _right_half(f, f_peak) else 8, 8),
                    textcoords="offset points",
                    ha="right" if _right_half(f, f_peak) else "left",
                    fontsize=8,
                    color=color,
                    bbox=_NOTE_BOX,  # legible over the curves it sits on
                )
            highest = max(highest, float(peak))
        if phase_margins and label in phase_margins:
            f_cross, margin = phase_margins[label]
            bottom.plot(f_cross, margin - 180.0, "o", color=color, ms=6, mec="k", mew=0.6)
            if label == worst_margin:
                bottom.annotate(
                    f"phase margin {margin:.3g}° at {f_cross:.4g} Hz ({label})",
                    (f_cross, margin - 180.0),
                    xytext=(-8 if _right_half(f, f_cross) else 8, 10),
                    textcoords="offset points",
                    ha="right" if _right_half(f, f_cross) else "left",
                    fontsize=8,
                    color=color,
                    bbox=_NOTE_BOX,  # legible over the curves it sits on
                )
    ceiling = 1.15 * max(highest, required_peak or 0.0, *(zone_limits[-1:] or [0.0]))
    edges = [0.0, *zone_limits, ceiling]
    for k, (lo, hi) in enumerate(zip(edges[:-1], edges[1:])):
        if zone_limits:
            top.axhspan(lo, hi, color=_ZONE_COLORS[min(k, len(_ZONE_COLORS) - 1)], alpha=0.07, lw=0)
    zones = "ABCDEFGH"
    for k, limit in enumerate(zone_limits[: len(zones) - 1]):  # each limit between two zones, at the right edge
        top.text(
            1.005,
            limit,
            f"{zones[k]} | {zones[k + 1]}",
            transform=top.get_yaxis_transform(),
            fontsize=7,
            va="center",
            color="0.35",
        )
    if required_peak is not None:
        top.axhline(required_peak, color="k", ls="--", lw=1.2, label=f"required |S|max ≤ {required_peak:g}")
    top.set_ylim(0.0, ceiling)
    top.set_ylabel("sensitivity |S| [-]")
    top.set_title("Magnetic-bearing loops: sensitivity and open-loop phase")
    bottom.axhline(-180.0, color="0.3", lw=1.0)
    if required_phase_margin_deg is not None:
        bottom.axhline(
            required_phase_margin_deg - 180.0,
            color="k",
            ls="--",
            lw=1.2,
            label=f"required phase margin ≥ {required_phase_margin_deg:g}°",
        )
    bottom.set_ylim(-200.0, 200.0)
    bottom.set_yticks([-180, -90, 0, 90, 180])
    bottom.set_ylabel("open-loop phase ∠L [°]")
    bottom.set_xlabel("frequency [Hz]")
    for a in (top, bottom):
        log_scale(a, "x")
        a.legend(loc="upper left", fontsize=7.5)
    return fig
