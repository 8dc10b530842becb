"""Campbell diagram from plain arrays: frequencies against speed, damping as colour.

matplotlib is imported lazily (through :func:`flexshaft.plot.style.styled`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.labels import place_point_labels, spread
from flexshaft.plot.style import (
    RPM_PER_HZ,
    WHIRL_LINESTYLE,
    WHIRL_MARKER,
    mark_operating,
    new_figure,
    nice_colorbar,
    styled,
    vector,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["campbell_figure", "damping_colormap"]

#: Colour range of the log decrement [-]: beyond these the colour saturates (colour bar arrows).
LOG_DECREMENT_RANGE = (-0.5, 1.0)
#: A log decrement smaller than this in magnitude is drawn as zero [-]: far above the round-off
#: of an undamped mode's 2πσ/ω (~1e-15: its ±1e-18 is a sign of round-off, not damping) and far
#: below the damping of any structure.
ROUNDOFF_LOG_DECREMENT = 1e-9


def damping_colormap(vmin: float, vmax: float):
    """Colour map and norm for the log decrement: reds below zero (unstable), viridis from
    dark (barely damped) to green (well damped) above; the colour jumps at zero."""
    from matplotlib import colormaps
    from matplotlib.colors import ListedColormap, Normalize, TwoSlopeNorm

    upper = colormaps["viridis"](np.linspace(0.0, 0.85, 128))
    if vmin < 0.0 < vmax:
        lower = colormaps["Reds"](np.linspace(0.95, 0.45, 128))
        return ListedColormap(np.vstack([lower, upper])), TwoSlopeNorm(0.0, vmin, vmax)
    if vmax <= 0.0:
        return ListedColormap(colormaps["Reds"](np.linspace(0.95, 0.45, 128))), Normalize(
            vmin, min(vmax, -1e-12) if vmax == vmin else vmax
        )
    return ListedColormap(upper), Normalize(0.0, vmax)


def _runs(labels: np.ndarray):
    """(start, stop) of runs of equal labels; stop is exclusive."""
    start = 0
    for stop in range(1, labels.size + 1):
        if stop == labels.size or labels[stop] != labels[start]:
            yield start, stop
            start = stop


@styled
def campbell_figure(
    speeds_rpm: ArrayLike,
    frequencies_hz: ArrayLike,
    whirl: ArrayLike,
    critical_speeds_rpm: Sequence[float] = (),
    operating_rpm: float | None = None,
    harmonics: Sequence[float] = (1,),
    *,
    log_decrement: ArrayLike | None = None,
    kind: ArrayLike | None = None,
    main_rotor_hz: Mapping[str, float] | None = None,
    excitation_orders: Mapping[str, float] | None = None,
    response_criticals: Sequence[tuple[float, float]] = (),
    separation: Sequence[tuple[float, float, float, float]] = (),
    speed_range_rpm: tuple[float, float] | None = None,
    torsional: Sequence[tuple[float, float, float, float, str]] = (),
    ax=None,
) -> Figure:
    """Campbell diagram: tracked natural frequencies against spin speed.

    Parameters
    ----------
    speeds_rpm : array_like, shape (n_speeds,)
        Spin speeds [rpm].
    frequencies_hz : array_like, shape (n_speeds, n_modes)
        Damped natural frequency of each tracked mode [Hz]; NaN where a mode is not found.
    whirl : array_like of str, shape (n_speeds, n_modes)
        "forward" (solid line, ▲), "backward" (dashed, ▼), "planar" (dotted, ●) or "none"
        (torsional/axial: sparse dots, ■ torsional, ◆ axial) at each point.
    critical_speeds_rpm : sequence of float
        Critical speeds [rpm], marked on the 1× excitation line (f = Ω/60) and labelled
        without overprinting (coincident ones share a label).
    operating_rpm : float, optional
        Operating speed [rpm], drawn as a vertical line.
    harmonics : sequence of float
        Orders k of the shaft's excitation lines f = kΩ/60 [Hz].
    log_decrement : array_like, shape (n_speeds, n_modes), optional
        Logarithmic decrement of each point [-]: the points are coloured by it (red below
        zero: unstable) with a colour bar; without it, each mode has its own line colour.
    kind : array_like of str, shape (n_speeds, n_modes), optional
        "lateral", "torsional" or "axial"; names the non-lateral modes in the legend.
    main_rotor_hz : mapping of str to float, optional
        Main-rotor excitation frequencies at the operating speed [Hz], e.g.
        ``{"1/rev": 4.3, "4/rev": 17.3}`` (the boom modes' forcing). The main rotor is geared to
        the shaft, so each is drawn as a ray from the origin through (operating speed,
        frequency); without ``operating_rpm`` as a horizontal line.
    excitation_orders : mapping of str to float, optional
        Further excitations geared to the shaft, by name, as orders of the shaft speed (e.g.
        ``{"tail rotor 4/rev": 1.17}``, the torsional separation check's), drawn as labelled rays
        f = order·Ω/60 [Hz].
    response_criticals : sequence of (float, float), optional
        The critical speeds the verdict's separation check uses (peaks of the unbalance
        response) as (speed [rpm], amplification factor): marked on the 1× line as squares and
        labelled with their speed and AF (the crossings of ``critical_speeds_rpm`` are then drawn
        unlabelled).
    separation : sequence of (float, float, float, float), optional
        For each of ``response_criticals``, in its order, the separation check's reading: the
        speed its margin is measured from [rpm] (the operating speed range's nearest end), the
        nearest speed the critical may have [rpm] (that speed moved by the required margin,
        toward the critical's side of the operating speed), its margin and the margin API 684
        requires for its AF [fractions of the first speed]. Each critical's label then gives
        both margins, and the required one is drawn as a bar on the critical's frequency between
        the two speeds (none where no margin is required): a critical inside its bar, or inside
        the operating range, fails the check.
    speed_range_rpm : (float, float), optional
        The operating speed range (lowest, highest) [rpm], shaded (the separation margins are
        measured from its ends).
    torsional : sequence of (float, float, float, float, str), optional
        The torsional separation check's reading of each torsional mode: (natural frequency
        [Hz], the order k of its nearest excitation f_e = k·Ω/60 [Hz], its margin, the required
        margin r, the excitation's name). The margin |f_n − f_e|/f_e falls below r while the
        excitation lies in (f_n/(1 + r), f_n/(1 − r)), i.e. at the speeds
        60·f_n/(k(1 ± r)) [rpm]: drawn as a brown bar on f_n between them (the check fails
        where the operating speed range meets it), the crossing f_e = f_n marked and labelled.
    ax : matplotlib Axes, optional
        Draw into this axes (its figure is returned).

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
    kinds = None
    if kind is not None:
        if np.size(kind) != freqs.size:
            raise ValueError(f"kind: expected shape {freqs.shape} like frequencies_hz, got {np.shape(kind)}")
        kinds = np.asarray(kind, dtype=str).reshape(freqs.shape)
    delta = None
    if log_decrement is not None:
        delta = np.asarray(log_decrement, dtype=float)
        if delta.shape != freqs.shape:
            raise ValueError(f"log_decrement: expected shape {freqs.shape} like frequencies_hz, got {delta.shape}")
    rotor = dict(main_rotor_hz or {})
    bad = {k: v for k, v in rotor.items() if not (np.isfinite(v) and v > 0)}
    if bad:
        raise ValueError(f"main_rotor_hz: frequencies must be finite and > 0 Hz, got {bad}")

    own = ax is None
    fig, axes = new_figure(1, 1, (8.6, 6.3), ax=ax, bottom=1.25, right=1.05, top=0.4)
    ax = axes[0, 0]
    import matplotlib

    colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
    # marker of each point: whirl for lateral points, kind for the others
    markers = labels.astype(object)
    if kinds is not None:
        markers = np.where(labels == "none", np.where(kinds == "axial", "axial", "torsional"), labels)
    for mode in range(freqs.shape[1]):
        color = "0.45" if delta is not None else colors[mode % len(colors)]
        f, w = freqs[:, mode], labels[:, mode]
        for start, stop in _runs(w):
            end = min(stop + 1, speeds.size)  # one point of overlap keeps the curve continuous
            ax.plot(
                speeds[start:end],
                f[start:end],
                color=color,
                ls=WHIRL_LINESTYLE[w[start]],
                lw=1.0 if delta is not None else 1.6,
                zorder=2,
            )

    f_max = np.nanmax(freqs) if np.isfinite(freqs).any() else 1.0
    critical = vector("critical_speeds_rpm", critical_speeds_rpm)
    response_peaks = (
        np.asarray(response_criticals, dtype=float).reshape(-1, 2)[:, 0] if len(response_criticals) else critical
    )
    top = 1.08 * max(f_max, critical.max(initial=0.0) / RPM_PER_HZ, response_peaks.max(initial=0.0) / RPM_PER_HZ)
    span = np.array([speeds.min(), speeds.max()])
    ax.set_xlim(span[0], span[1])
    ax.set_ylim(0.0, top)

    handles: list[Any] = []  # artists, or a tuple of artists sharing one legend entry
    present = [name for name in ("forward", "backward", "planar") if name in labels]
    for name in present:
        handles.append(
            Line2D(
                [],
                [],
                color="0.3",
                ls=WHIRL_LINESTYLE[name],
                marker=WHIRL_MARKER[name] if delta is not None else None,
                ms=5,
                label=f"{name} whirl",
            )
        )
    if "none" in labels:
        names = sorted(set(kinds[labels == "none"])) if kinds is not None else ["torsional / axial"]
        for name in names:
            handles.append(
                Line2D(
                    [],
                    [],
                    color="0.3",
                    ls=WHIRL_LINESTYLE["none"],
                    marker=WHIRL_MARKER.get(name, "s") if delta is not None else None,
                    ms=5,
                    label=f"{name} (no 1× critical)",
                )
            )
    if delta is not None:
        # |δ| below ROUNDOFF_LOG_DECREMENT is an undamped mode's round-off: drawn as 0, not as
        # a colour bar from −1e-18 to 1e-18 that paints its sign
        delta = np.where(np.abs(delta) < ROUNDOFF_LOG_DECREMENT, 0.0, delta)
        finite = delta[np.isfinite(delta) & np.isfinite(freqs)]
        lo = max(float(finite.min()), LOG_DECREMENT_RANGE[0]) if finite.size else 0.0
        hi = min(float(finite.max()), LOG_DECREMENT_RANGE[1]) if finite.size else 1.0
        hi = hi if hi > max(lo, 0.0) else max(lo, 0.0) + 1e-3
        cmap, norm = damping_colormap(lo, hi)
        speeds2d = np.broadcast_to(speeds[:, None], freqs.shape)
        step = max(1, int(np.ceil(speeds.size / 40)))  # at most ~40 markers per curve
        thin = np.zeros(freqs.shape, bool)
        thin[::step] = True
        mappable = None
        for name in np.unique(markers.astype(str)):
            sel = (markers == name) & np.isfinite(freqs) & thin
            if sel.any():
                mappable = ax.scatter(
                    speeds2d[sel],
                    freqs[sel],
                    c=np.clip(delta[sel], lo, hi),
                    cmap=cmap,
                    norm=norm,
                    marker=WHIRL_MARKER.get(name, "o"),
                    s=15,
                    linewidths=0,
                    zorder=3,
                )
        extend = {(False, False): "neither", (True, False): "min", (False, True): "max", (True, True): "both"}[
            (bool(finite.size and finite.min() < lo), bool(finite.size and finite.max() > hi))
        ]
        nice_colorbar(fig, mappable, ax, "log decrement δ [-]", extend=extend, pad=0.045, fraction=0.045)

    for k, order in enumerate(harmonics):
        (line,) = ax.plot(
            span,
            order * span / RPM_PER_HZ,
            color="0.15",
            lw=1.0,
            ls=(0, (6, 2, 1, 2)) if k else "-",
            alpha=0.8,
            label=f"{order:g}× shaft speed",
            zorder=1,
        )
        handles.append(line)
    ray_labels: list[tuple[str, float, float, str]] = []  # (text, x, y, colour) at each ray's end
    for name, f_op in rotor.items():
        if operating_rpm:
            (line,) = ax.plot(
                span,
                f_op * span / operating_rpm,
                color="tab:purple",
                lw=1.1,
                ls=(0, (5, 2, 1, 2)),
                zorder=1,
                label=f"main rotor {name}",
            )
        else:
            line = ax.axhline(
                f_op, color="tab:purple", lw=1.1, ls=(0, (5, 2, 1, 2)), zorder=1, label=f"main rotor {name}"
            )
        handles.append(line)
        x_end = span[1] if not operating_rpm else min(span[1], top * operating_rpm / f_op)
        y_end = f_op if not operating_rpm else f_op * x_end / operating_rpm
        ray_labels.append((f"MR {name}", x_end, y_end, "tab:purple"))
    for name, order in (excitation_orders or {}).items():
        if not (np.isfinite(order) and order > 0):
            raise ValueError(f"excitation_orders: {name!r} must be a finite order > 0, got {order!r}")
        (line,) = ax.plot(
            span,
            order * span / RPM_PER_HZ,
            color="tab:brown",
            lw=1.1,
            ls=(0, (2, 2)),
            zorder=1,
            label=f"{name} ({order:.3g}×)",
        )
        handles.append(line)
        x_end = min(span[1], top * RPM_PER_HZ / order)
        ray_labels.append((name, x_end, order * x_end / RPM_PER_HZ, "tab:brown"))
    _label_rays(ax, ray_labels)
    if critical.size:
        (marker,) = ax.plot(
            critical, critical / RPM_PER_HZ, "o", mfc="none", mec="k", mew=1.3, ms=8, label="critical speed", zorder=4
        )
        handles.append(marker)
        if not len(response_criticals):  # the verdict's criticals carry the labels when given
            _label_criticals(ax, critical)
    peaks = np.asarray(response_criticals, dtype=float).reshape(-1, 2)
    sep = np.asarray(separation, dtype=float).reshape(-1, 4)
    if len(separation) and sep.shape[0] != peaks.shape[0]:
        raise ValueError(
            f"separation: one (reference, bound, margin, required) per response critical, got {sep.shape[0]} for "
            f"{peaks.shape[0]}"
        )
    if len(response_criticals):
        texts = [f"{rpm:.0f} rpm, AF {af:.3g}" if np.isfinite(af) else f"{rpm:.0f} rpm, AF ∞" for rpm, af in peaks]
        if sep.size:
            texts = [f"{t}, margin {m:.1%} (needs {r:.1%})" for t, (_, _, m, r) in zip(texts, sep)]
            handles += _required_separation(ax, peaks[:, 0], sep)
        (marker,) = ax.plot(
            peaks[:, 0],
            peaks[:, 0] / RPM_PER_HZ,
            "s",
            mfc="none",
            mec="tab:red",
            mew=1.4,
            ms=9,
            label="critical speed of the verdict (unbalance-response peak)",
            zorder=5,
        )
        handles.append(marker)
        place_point_labels(
            ax,
            peaks[:, 0],
            peaks[:, 0] / RPM_PER_HZ,
            texts,
            fontsize=7.0,
            avoid=[(c, c / RPM_PER_HZ) for c in critical],
            color="tab:red",
            bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.8},
            zorder=6,
        )
    torsional_bar = _torsional_separation(ax, torsional, span[1])
    lateral_bar = [h for h in handles if h.get_label() == "required separation (API 684)"]
    if torsional_bar and lateral_bar:  # one legend entry of both bars (a 20th entry widens the legend)
        handles[handles.index(lateral_bar[0])] = (lateral_bar[0], *torsional_bar)
    else:
        handles += torsional_bar
    mark_operating(ax, operating_rpm, speed_range_rpm=speed_range_rpm)
    if speed_range_rpm is not None and speed_range_rpm[0] < speed_range_rpm[1]:
        handles.append(ax.patches[-1])
    if operating_rpm is not None:
        handles.append(ax.get_lines()[-1])
    _mode_numbers(ax, speeds, freqs)
    ax.set_xlabel("spin speed Ω [rpm]")
    ax.set_ylabel("natural frequency [Hz]")
    ax.set_title("Campbell diagram" + (" (colour: log decrement δ, red = unstable)" if delta is not None else ""))
    from matplotlib.legend_handler import HandlerTuple

    texts = [
        "required separation (API 684; torsional)" if isinstance(h, tuple) else str(h.get_label()) for h in handles
    ]
    style = {"handler_map": {tuple: HandlerTuple(ndivide=None, pad=0.3)}}
    if own:  # a band below the axes: the legend hides no curve
        fig.legend(handles, texts, loc="lower center", ncols=4, bbox_to_anchor=(0.5, 0.005), fontsize=8, **style)
    else:
        ax.legend(handles, texts, loc="best", fontsize=7.5, **style)
    return fig


#: A required-separation bar: end ticks, square ends, beneath the modes' points (a bar is no mode).
_BAR: dict[str, Any] = {"marker": "|", "ms": 9, "solid_capstyle": "butt", "zorder": 1.5}


def _required_separation(ax, critical_rpm: np.ndarray, sep: np.ndarray) -> list:
    """The required separation of each verdict critical as a bar on its frequency (f = N_c/60)
    from the speed its margin is measured from to the nearest speed it may have (``separation``
    of :func:`campbell_figure`); drawn beneath the modes' points (a bar is no mode) in grey.
    Returns the legend handle (none when no critical needs a margin)."""
    handle = []
    for n_c, (reference, bound, _, required) in zip(critical_rpm, sep):
        if not (np.isfinite(reference) and np.isfinite(bound) and required > 0.0):
            continue
        (bar,) = ax.plot(
            [reference, bound],
            [n_c / RPM_PER_HZ] * 2,
            color="0.15",
            lw=2.2,
            alpha=0.45,
            label="required separation (API 684)",
            **_BAR,
        )
        handle = [bar]
    return handle


def _torsional_separation(ax, torsional, right: float) -> list:
    """Each torsional mode's band of speeds where its nearest excitation comes within the
    required margin (``torsional`` of :func:`campbell_figure`), a brown bar on its frequency,
    and the excitation's crossing of the mode (◇); returns the legend handle (the crowded
    low-frequency corner has no room for a label per mode: the caller states the margins)."""
    handle = None
    for f_n, order, _margin, required, name in torsional:
        if not (np.isfinite(f_n) and f_n > 0 and np.isfinite(order) and order > 0):
            raise ValueError(f"torsional: {name!r} needs a frequency > 0 Hz and an order > 0, got {f_n!r}, {order!r}")
        low = RPM_PER_HZ * f_n / (order * (1.0 + required))
        high = RPM_PER_HZ * f_n / (order * (1.0 - required)) if required < 1.0 else np.inf
        if low >= right:  # beyond the speeds drawn (the bar would only grow the canvas)
            continue
        (handle,) = ax.plot([low, min(high, right)], [f_n, f_n], color="tab:brown", lw=3.0, alpha=0.55, **_BAR)
        if RPM_PER_HZ * f_n / order <= right:
            ax.plot(RPM_PER_HZ * f_n / order, f_n, "D", mfc="none", mec="tab:brown", mew=1.3, ms=7, zorder=5)
    if handle is None:
        return []
    handle.set_label("required torsional separation")
    return [handle]


def _label_rays(ax, labels: list[tuple[str, float, float, str]]) -> None:
    """Name each excitation ray just above its end; the ends on the right edge of the axes
    (rays that leave the diagram there) are moved apart vertically so that no two names print
    over each other (positions in pixels, one line of 7.5-pt text apart); a white ground keeps
    a name legible where it crosses a mode's line."""
    if not labels:
        return
    scale = ax.figure.dpi / 72.0
    ends = ax.transData.transform([(x, y) for _, x, y, _ in labels])
    right = np.isclose(ends[:, 0], ax.transData.transform((ax.get_xlim()[1], 0.0))[0], atol=1.0)
    y_px = ends[:, 1] + 3.0 * scale  # the text's baseline, 3 pt above the ray's end
    if right.sum() > 1:
        y_px[right] = spread(y_px[right], 10.0 * scale)
    for (text, x, y, colour), y_end, y_text in zip(labels, ends[:, 1], y_px, strict=True):
        ax.annotate(
            text,
            (x, y),
            xytext=(-3.0, (y_text - y_end) / scale),
            textcoords="offset points",
            ha="right",
            va="bottom",
            fontsize=7.5,
            color=colour,
            bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8},  # over a mode's line
        )


def _label_criticals(ax, critical: np.ndarray) -> None:
    """One label per cluster of coincident critical speeds (markers closer than 10 px)."""
    px = ax.transData.transform(np.column_stack([critical, critical / RPM_PER_HZ]))
    order = np.argsort(critical)
    clusters: list[list[int]] = []
    for i in order:
        if clusters and np.hypot(*(px[i] - px[clusters[-1][-1]])) < 10.0 * ax.figure.dpi / 72.0:
            clusters[-1].append(i)
        else:
            clusters.append([i])
    xs = [float(np.mean(critical[c])) for c in clusters]
    texts = [" / ".join(f"{critical[i]:.0f}" for i in c) + " rpm" for c in clusters]
    place_point_labels(
        ax,
        xs,
        [x / RPM_PER_HZ for x in xs],
        texts,
        fontsize=7.5,
        bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.8},
    )


def _mode_numbers(ax, speeds: np.ndarray, freqs: np.ndarray) -> None:
    """Mode numbers just right of the last point of each curve, spread so none overprint."""
    ends = []
    for mode in range(freqs.shape[1]):
        finite = np.flatnonzero(np.isfinite(freqs[:, mode]))
        if finite.size:
            ends.append((mode, speeds[finite[-1]], freqs[finite[-1], mode]))
    if not ends:
        return
    to_px = ax.transData.transform
    px = to_px(np.array([[x, y] for _, x, y in ends]))
    scale = ax.figure.dpi / 72.0
    y_new = spread(px[:, 1], 7.5 * scale, ax.bbox.y0, ax.bbox.y1)
    inverse = ax.transData.inverted()
    for (mode, x, _), (xp, _), yn in zip(ends, px, y_new):
        ax.annotate(
            str(mode + 1),
            (x, inverse.transform((xp, yn))[1]),
            xytext=(3, 0),
            textcoords="offset points",
            fontsize=7,
            va="center",
            ha="left",
            annotation_clip=False,
        )
