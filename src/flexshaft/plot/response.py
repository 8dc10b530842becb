"""Figures of forced responses from plain arrays: Bode plots and orbits.

Complex amplitudes in metres are drawn in millimetres; matplotlib is imported lazily.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import MM_PER_M, log_scale, mark_operating, new_figure, styled, vector

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["bode_figure", "orbit_figure", "orbit_ellipse", "orbit_amplitude_mm"]


@styled
def bode_figure(
    speeds: ArrayLike,
    responses: Mapping[str, ArrayLike],
    operating_rpm: float | None = None,
    gap: float | None = None,
    *,
    x_label: str = "spin speed Ω [rpm]",
    title: str = "Imbalance response (Bode)",
    ax=None,
) -> Figure:
    """Amplitude and phase of complex responses against speed or frequency.

    Parameters
    ----------
    speeds : array_like, shape (n,)
        Abscissa: spin speed [rpm] for a synchronous (imbalance) response, or excitation
        frequency [Hz] with ``x_label`` saying so.
    responses : mapping of str to array_like, each shape (n,)
        Complex amplitude of each output [m] (phase relative to the excitation, e.g. the
        imbalance force in the vertical direction); amplitude drawn in mm on a log axis, phase
        unwrapped in degrees (negative: lag).
    operating_rpm : float, optional
        Operating speed [rpm], drawn as a vertical line.
    gap : float, optional
        Auxiliary-bearing radial gap [m], drawn on the amplitude panel.
    x_label, title : str
        Abscissa label and title.
    ax : sequence of two matplotlib Axes, optional
        Amplitude and phase panels.

    Returns
    -------
    matplotlib.figure.Figure
    """
    x = vector("speeds", speeds)
    if not responses:
        raise ValueError("responses: at least one complex response is required")
    fig, axes = new_figure(2, 1, (8.0, 6.2), ax=ax, hspace=0.3)
    amp_ax, phase_ax = axes[0, 0], axes[1, 0]
    positive = gap is not None and gap > 0  # something the log axis can show
    for name, values in responses.items():
        z = np.asarray(values, dtype=complex).ravel()
        if z.size != x.size:
            raise ValueError(f"responses[{name!r}]: expected {x.size} values to match the speed axis, got {z.size}")
        amplitude = np.abs(z) * MM_PER_M
        positive = positive or bool(np.any(amplitude > 0))
        (line,) = amp_ax.plot(x, np.where(amplitude > 0, amplitude, np.nan), label=name)
        phase = np.degrees(np.unwrap(np.angle(z)))
        phase -= 360.0 * np.round(phase[np.flatnonzero(amplitude > 0)[0]] / 360.0) if np.any(amplitude > 0) else 0.0
        phase_ax.plot(x, np.where(amplitude > 0, phase, np.nan), color=line.get_color(), label=name)
    if gap is not None:
        amp_ax.axhline(
            gap * MM_PER_M, color="k", ls="--", lw=1.2, label=f"auxiliary-bearing gap {gap * MM_PER_M:.3g} mm"
        )
    for a in (amp_ax, phase_ax):
        mark_operating(a, operating_rpm, label=a is amp_ax)
    if positive:  # else a zero response (a design without imbalance): a linear axis
        log_scale(amp_ax)
    amp_ax.set_ylabel("amplitude [mm]")
    amp_ax.set_title(title)
    amp_ax.legend(loc="best", fontsize=7.5)
    from matplotlib.ticker import MultipleLocator

    lo, hi = phase_ax.get_ylim()
    if hi - lo < 90.0:  # a phase that does not turn (an undamped response: 0 or −180° and round-off)
        centre = 90.0 * np.round(0.5 * (lo + hi) / 90.0)
        lo, hi = centre - 100.0, centre + 100.0
        phase_ax.set_ylim(lo, hi)
    phase_ax.yaxis.set_major_locator(MultipleLocator(90.0 if hi - lo <= 1080 else 180.0))
    phase_ax.set_ylabel("phase [deg]")
    phase_ax.set_xlabel(x_label)
    phase_ax.set_xlim(x.min(), x.max())
    return fig


def orbit_amplitude_mm(v: complex, w: complex) -> float:
    """Major semi-axis of the orbit of (v, w) [m], in mm."""
    v, w = complex(v), complex(w)
    return float(np.sqrt(0.5 * (abs(v) ** 2 + abs(w) ** 2 + abs(v * v + w * w)))) * MM_PER_M


def orbit_ellipse(v: complex, w: complex, n: int = 121) -> tuple[np.ndarray, np.ndarray]:
    """The orbit (Re(v e^{iφ}), Re(w e^{iφ})) for φ in [0, 2π] (n points) [unit of v, w]."""
    phi = np.linspace(0.0, 2.0 * np.pi, n)
    turn = np.exp(1j * phi)
    return (complex(v) * turn).real, (complex(w) * turn).real


@styled
def orbit_figure(
    orbits: Mapping[str, tuple[complex, complex]],
    gaps: Mapping[str, float] | float | None = None,
    *,
    centres: Mapping[str, tuple[float, float]] | None = None,
    title: str = "Orbits",
    ax=None,
) -> Figure:
    """Orbits (v, w) of points of the shaft, one panel each, with the auxiliary-bearing gap.

    The orbit of a complex amplitude pair (v, w) at one frequency is the ellipse
    (Re(v e^{iφ}), Re(w e^{iφ})); the dot marks φ = 0 (the key phasor: the imbalance force
    pointing in +v) and the arrow the direction of whirl. Lateral w is horizontal, vertical v
    up, equal scales, in mm (μm for orbits below 0.1 mm); the view is along +x (looking aft),
    where forward whirl of a shaft spinning about +x runs clockwise.

    Parameters
    ----------
    orbits : mapping of str to (complex, complex)
        (v, w) amplitude of each point [m], e.g. the shaft relative to its bearing.
    gaps : mapping of str to float, or float, optional
        Radial clearance of the auxiliary (backup) bearing at each point [m] (a float for
        all), drawn as a circle about the bearing's centre; when the orbit is much smaller,
        the panel shows the orbit and states the fraction of the gap it uses.
    centres : mapping of str to (float, float), optional
        Static (v, w) position of each orbit's centre relative to the bearing [m] (the shaft's
        static offset: a magnetic bearing's sag under its share of the weight); the orbit is
        drawn about it, and the fraction of the gap is that of static offset + orbit (the
        actuator excursion the verdict checks). Default: orbits about the bearing's centre.
    title : str
        Figure title (when the figure is made here).
    ax : sequence of matplotlib Axes, optional
        One axes per orbit.

    Returns
    -------
    matplotlib.figure.Figure
    """
    if not orbits:
        raise ValueError("orbits: at least one (v, w) pair is required")
    own = ax is None
    n = len(orbits)
    ncols = min(4, n) if own else 1
    nrows = -(-n // ncols) if own else n
    fig, axes = new_figure(
        nrows,
        ncols,
        (2.9 * ncols + 0.6, 2.85 * nrows + 0.75),
        False,
        ax=ax,
        left=0.7,
        right=0.15,
        bottom=0.55,
        top=0.7,
        wspace=0.85,
        hspace=0.75,
    )
    for k, (name, pair) in enumerate(orbits.items()):
        a = axes.flat[k]
        try:
            v, w = (complex(c) for c in pair)
        except (TypeError, ValueError):
            raise ValueError(
                f"orbits[{name!r}]: expected a (v, w) pair of complex amplitudes [m], got {pair!r}"
            ) from None
        gap = gaps.get(name) if isinstance(gaps, Mapping) else gaps
        cv, cw = (0.0, 0.0) if centres is None or name not in centres else (float(c) for c in centres[name])
        radius_mm = float(orbit_amplitude_mm(v, w))
        offset_mm = float(np.hypot(cv, cw)) * MM_PER_M
        if offset_mm <= 1e-6 * max(radius_mm, 0.0 if gap is None else gap * MM_PER_M):
            # round-off of a held position (an integrating bearing's 6e-13 μm, audit a2): none
            cv, cw, offset_mm = 0.0, 0.0, 0.0
        reach_mm = offset_mm + radius_mm  # the farthest the shaft can be from the bearing's centre
        gap_mm = None if gap is None else gap * MM_PER_M
        shows_gap = gap_mm is not None and gap_mm <= 4.0 * max(reach_mm, 1e-300)
        extent_mm = max(reach_mm, gap_mm if gap_mm is not None and shows_gap else 0.0) or 1e-6
        unit, scale = ("μm", 1e3) if extent_mm < 0.1 else ("mm", 1.0)  # plain tick labels, no offset text
        ov, ow = orbit_ellipse(v * MM_PER_M * scale, w * MM_PER_M * scale)
        ov, ow = ov + cv * MM_PER_M * scale, ow + cw * MM_PER_M * scale
        a.plot(ow, ov, color="C0", lw=1.6)
        a.plot(ow[0], ov[0], "o", color="C0", ms=5)
        if offset_mm > 0.0:  # the static offset: from the bearing's centre to the orbit's
            a.plot([0.0, cw * MM_PER_M * scale], [0.0, cv * MM_PER_M * scale], color="0.35", ls=":", lw=1.0)
        j = len(ov) // 8
        a.annotate(
            "",
            (ow[j + 1], ov[j + 1]),
            xytext=(ow[j], ov[j]),
            arrowprops={"arrowstyle": "-|>", "color": "C0", "lw": 1.2, "mutation_scale": 12},
        )
        note = f"max {radius_mm * scale:.3g} {unit}"
        if offset_mm > 0.0:
            note = f"static {offset_mm * scale:.3g} {unit} + orbit {radius_mm * scale:.3g} {unit}"
        if gap_mm is not None:
            note += f"\n{100 * reach_mm / gap_mm:.3g} % of gap {gap_mm:.3g} mm"
            if shows_gap:
                circle = orbit_ellipse(gap_mm * scale, -1j * gap_mm * scale)
                a.plot(circle[1], circle[0], color="tab:red", ls="--", lw=1.1)
        extent = extent_mm * scale
        a.set_xlim(-1.15 * extent, 1.15 * extent)
        a.set_ylim(-1.15 * extent, 1.15 * extent)
        a.set_aspect("equal", adjustable="box")
        a.axhline(0.0, color="0.6", lw=0.6)
        a.axvline(0.0, color="0.6", lw=0.6)
        a.set_title(str(name), fontsize=9.5)
        a.text(
            0.03,
            0.97,
            note,
            transform=a.transAxes,
            va="top",
            ha="left",
            fontsize=7.5,
            bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.8", "alpha": 0.85},
        )
        a.set_xlabel(f"w (lateral) [{unit}]", fontsize=9)
        a.set_ylabel(f"v (vertical) [{unit}]", fontsize=9)
    for a in axes.flat[n:]:
        a.set_visible(False)
    if own:
        fig.suptitle(title, fontsize=11, y=1 - 0.12 / fig.get_figheight())
    return fig
