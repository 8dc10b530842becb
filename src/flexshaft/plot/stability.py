"""Figures of the whirl-stability analysis (matplotlib imported lazily).

:func:`log_decrement_figure` is the engineer's view (damping of every tracked mode against
speed, the onset of instability marked); :func:`real_parts_figure` shows Re(s) as in the
thesis's figures 4.2-4.4.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import WHIRL_LINESTYLE, mark_operating, new_figure, styled, vector

__all__ = ["log_decrement_figure", "real_parts_figure", "stability_map_figure"]


def _panel_curves(speeds: np.ndarray, name: str, values: ArrayLike, what: str) -> np.ndarray:
    array = np.asarray(values, dtype=float)
    array = array[:, None] if array.ndim == 1 else array
    if array.ndim != 2 or array.shape[0] != speeds.size:
        raise ValueError(f"{what}[{name!r}]: expected shape ({speeds.size}, n_modes), got {np.shape(values)}")
    return array


#: Colour of the modes a requirement does not judge (:func:`log_decrement_figure`'s ``judged``).
NOT_JUDGED_COLOR = "0.72"


def _draw_modes(
    ax, speeds: np.ndarray, values: np.ndarray, whirl: np.ndarray | None, judged: np.ndarray | None = None
) -> None:
    import matplotlib

    colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
    for m in range(values.shape[1]):
        color = colors[m % len(colors)] if judged is None or judged[m] else NOT_JUDGED_COLOR
        if whirl is None:
            ax.plot(speeds, values[:, m], color=color, lw=1.2)
            continue
        w = whirl[:, m]
        start = 0
        for stop in range(1, speeds.size + 1):
            if stop == speeds.size or w[stop] != w[start]:
                end = min(stop + 1, speeds.size)
                ax.plot(
                    speeds[start:end],
                    values[start:end, m],
                    color=color,
                    lw=1.2,
                    ls=WHIRL_LINESTYLE.get(str(w[start]), "-"),
                )
                start = stop


def _mark_onset(ax, onset_rpm: float | None, text: str | None, max_rpm: float, unstable_label: bool) -> None:
    """Onset: a red ✕ on the zero line, a thin vertical line and a boxed label; else "stable"."""
    if onset_rpm is None or not np.isfinite(onset_rpm):
        ax.text(
            0.99,
            0.96,
            f"stable up to {max_rpm:.0f} rpm",
            transform=ax.transAxes,
            ha="right",
            va="top",
            fontsize=8,
            bbox={"boxstyle": "round,pad=0.25", "fc": "white", "ec": "0.7"},
        )
        return
    ax.axvline(onset_rpm, color="tab:red", lw=0.9, ls=(0, (1, 1.5)))
    ax.plot(
        [onset_rpm],
        [0.0],
        "X",
        color="tab:red",
        mec="k",
        mew=0.6,
        ms=9,
        zorder=5,
        label="onset of instability" if unstable_label else None,
    )
    label = f"onset {onset_rpm:.0f} rpm" + (f"\n{text}" if text else "")
    right = onset_rpm > np.mean(ax.get_xlim())
    ax.annotate(
        label,
        (onset_rpm, 0.0),
        xytext=(-8 if right else 8, 0),
        textcoords="offset points",
        xycoords=("data", "axes fraction"),
        ha="right" if right else "left",
        va="bottom",
        fontsize=8,
        color="tab:red",
        bbox={"boxstyle": "round,pad=0.25", "fc": "white", "ec": "tab:red", "alpha": 0.9},
    )


@styled
def log_decrement_figure(
    speeds_rpm: ArrayLike,
    log_decrements: Mapping[str, ArrayLike],
    onset_rpm: Mapping[str, float | None] | None = None,
    operating_rpm: float | None = None,
    *,
    onset_text: Mapping[str, str] | None = None,
    whirl: Mapping[str, ArrayLike] | None = None,
    required: float | None = None,
    judged: Mapping[str, ArrayLike] | None = None,
    ax=None,
):
    """Logarithmic decrement of the tracked modes against speed, one panel per set, the onset
    of whirl instability marked.

    Parameters
    ----------
    speeds_rpm : array_like, shape (n_speeds,)
        Spin speeds [rpm].
    log_decrements : mapping of str to array_like, each (n_speeds, n_modes)
        δ of every tracked mode of each design [-]; δ < 0 (shaded) is unstable.
    onset_rpm : mapping of str to float or None, optional
        Onset speed of each design [rpm] (None: stable over the range), marked by a red ✕ on
        δ = 0 with its value.
    operating_rpm : float, optional
        Operating speed [rpm].
    onset_text : mapping of str to str, optional
        A second line for the onset label, e.g. "mode 6, forward whirl".
    whirl : mapping of str to array_like of str, optional
        Whirl label of every point, drawn as line style (solid forward, dashed backward).
    required : float, optional
        Required log decrement (e.g. 0.1), drawn as a dashed line.
    judged : mapping of str to array_like of bool, optional
        Which tracked modes of a set (n_modes,) the required log decrement judges (the
        verdict's: the shaft's whirl modes); the others are drawn in light grey, with a legend
        entry saying so.
    ax : sequence of matplotlib Axes, optional
        One axes per design.

    Returns
    -------
    matplotlib.figure.Figure
    """
    speeds = vector("speeds_rpm", speeds_rpm)
    n = len(log_decrements)
    if n == 0:
        raise ValueError("log_decrements: at least one set of curves is required")
    own = ax is None
    fig, axes = new_figure(n, 1, (8.0, 2.5 * n + 1.35), ax=ax, hspace=0.5, bottom=0.95, top=0.45)
    onsets = dict(onset_rpm or {})
    for k, (a, (name, values)) in enumerate(zip(axes[:, 0], log_decrements.items())):
        delta = _panel_curves(speeds, name, values, "log_decrements")
        labels = None if whirl is None or name not in whirl else np.asarray(whirl[name], dtype=str).reshape(delta.shape)
        finite = delta[np.isfinite(delta)]
        low = min(float(finite.min()), 0.0) if finite.size else -0.1
        high = float(finite.max()) if finite.size else 0.1
        top = max(min(high, max(0.3, 4.0 * abs(low))), 1.15 * (required or 0.0))
        bottom = min(low, -0.08 * top)
        pad = 0.08 * (top - bottom)
        a.set_ylim(bottom - pad, top + pad)
        a.set_xlim(speeds.min(), speeds.max())
        a.axhspan(bottom - pad, 0.0, color="tab:red", alpha=0.07, lw=0)
        mask = None
        if judged is not None and name in judged:
            mask = np.asarray(judged[name], dtype=bool).ravel()
            if mask.size != delta.shape[1]:
                raise ValueError(f"judged[{name!r}]: expected {delta.shape[1]} entries, one per mode (got {mask.size})")
            faded = not mask.all()
        else:
            faded = False
        _draw_modes(a, speeds, delta, labels, mask)
        if faded:  # a legend entry for the grey curves (an empty line carries it)
            a.plot([], [], color=NOT_JUDGED_COLOR, lw=1.2, label="not judged by the δ requirement")
        a.axhline(0.0, color="k", lw=1.0)
        if required is not None:
            a.axhline(required, color="tab:green", ls=(0, (6, 3)), lw=1.2, label=f"required δ ≥ {required:g}")
        mark_operating(a, operating_rpm, label=k == 0)
        _mark_onset(a, onsets.get(name), (onset_text or {}).get(name), speeds.max(), k == 0)
        if high > top + pad:  # a curve runs off the panel's top, not only into its margin
            a.text(
                0.01,
                0.97,
                f"curves above δ = {top + pad:.3g} cut",
                transform=a.transAxes,
                ha="left",
                va="top",
                fontsize=7,
                color="0.35",
            )
        a.set_ylabel("log decrement δ [-]")
        a.set_title(name, fontsize=10)
    axes[-1, 0].set_xlabel("spin speed Ω [rpm]")
    handles, names = axes[0, 0].get_legend_handles_labels()
    if handles and own:  # in a band at the bottom: it hides no curve
        from matplotlib.lines import Line2D

        handles += [
            Line2D([], [], color="0.3", ls=WHIRL_LINESTYLE[w], label=f"{w} whirl")
            for w in ("forward", "backward", "planar")
            if whirl is not None
        ]
        # two rows at most: the band below the axes holds two (a third covered the x label, audit a2)
        ncols = max(3, -(-len(handles) // 2))
        fig.legend(handles=handles, loc="lower center", ncols=ncols, fontsize=7.5, bbox_to_anchor=(0.5, 0.0))
    elif handles:
        axes[0, 0].legend(loc="best", fontsize=7.5)
    return fig


@styled
def real_parts_figure(
    speeds_rpm: ArrayLike,
    real_parts: Mapping[str, ArrayLike],
    operating_rpm: float | None = None,
    *,
    onset_rpm: Mapping[str, float | None] | None = None,
    ax=None,
):
    """Real parts of the tracked eigenvalues against speed, one panel per shaft (thesis
    figures 4.2-4.4). ``real_parts[name]`` is (n_speeds, n_modes) [1/s]; Re > 0 is unstable;
    ``onset_rpm[name]`` [rpm] marks the onset. ``ax``: one axes per shaft."""
    speeds = vector("speeds_rpm", speeds_rpm)
    n = len(real_parts)
    fig, axes = new_figure(n, 1, (8.0, 2.5 * n + 1.0), ax=ax, hspace=0.5, bottom=0.6, top=0.45)
    onsets = dict(onset_rpm or {})
    for _k, (a, (name, re)) in enumerate(zip(axes[:, 0], real_parts.items())):
        re = _panel_curves(speeds, name, re, "real_parts")
        a.set_xlim(speeds.min(), speeds.max())
        _draw_modes(a, speeds, re, None)
        a.axhline(0.0, color="k", lw=1.0)
        a.axhspan(0.0, max(np.nanmax(re), 0.0) * 1.05 + 1e-12, color="tab:red", alpha=0.07, lw=0)
        mark_operating(a, operating_rpm, label=False)
        if name in onsets:
            _mark_onset(a, onsets[name], None, speeds.max(), False)
        a.set_ylabel("Re(s) [1/s]")
        a.set_title(name, fontsize=10)
    axes[-1, 0].set_xlabel("spin speed Ω [rpm]")
    return fig


@styled
def stability_map_figure(
    kd: ArrayLike,
    onset_rpm: Mapping[str, ArrayLike],
    operating_rpm: float | None = None,
    max_rpm: float | None = None,
    *,
    required_rpm: float | None = None,
    design: tuple[float, float | None, str] | None = None,
    ax=None,
):
    """Onset speed of whirl instability against the actuators' derivative gain K_d [N s/m];
    NaN onsets (stable over the analysed range) are drawn at ``max_rpm`` with open markers.

    ``required_rpm``: the onset the whirl-onset requirement asks for (dashed). ``design``:
    (K_d, onset [rpm] or None when stable to ``max_rpm``, label) of the design itself, a star
    (open when stable).

    Each series' markers are 3 pt smaller than the one before it: series stable at the same
    K_d share a point at ``max_rpm``, and equal rings there would leave only the last drawn
    visible; nested, each shows its colour."""
    kd = vector("kd", kd)
    own = ax is None
    fig, axes = new_figure(1, 1, (8.0, 4.6), ax=ax, bottom=1.25)
    ax = axes[0, 0]
    for i, (name, values) in enumerate(onset_rpm.items()):
        v = vector(f"onset_rpm[{name!r}]", values, kd.size)
        size = 5.0 + 3.0 * (len(onset_rpm) - 1 - i)
        (line,) = ax.plot(kd, v, "o-", label=name, markersize=size)
        if max_rpm is not None and np.any(np.isnan(v)):
            ax.plot(
                kd[np.isnan(v)],
                np.full(np.isnan(v).sum(), max_rpm),
                "o",
                mfc="none",
                color=line.get_color(),
                markersize=size,
            )
    if operating_rpm is not None:
        ax.axhline(operating_rpm, color="tab:red", ls="-.", label=f"operating speed {operating_rpm:.0f} rpm")
    if required_rpm is not None:
        ax.axhline(required_rpm, color="k", ls="--", lw=1.2, label=f"required onset ≥ {required_rpm:.0f} rpm")
    if max_rpm is not None:
        ax.axhline(max_rpm, color="0.5", ls=":", label=f"stable to ≥ {max_rpm:.0f} rpm (open markers)")
    if design is not None:
        kd_design, onset_design, label = design
        stable = onset_design is None
        if not stable or max_rpm is not None:
            ax.plot(
                [kd_design],
                [max_rpm if stable else onset_design],
                "*",
                ms=15,
                mec="k",
                mfc="none" if stable else "gold",
                mew=1.3,
                zorder=5,
                label=label,
            )
    ax.set_xlabel("derivative gain K_d [N s/m]")
    ax.set_ylabel("onset speed [rpm]")
    ax.set_title("Whirl-instability onset")
    if own:
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncols=3, fontsize=8)
    else:
        ax.legend(loc="best")
    return fig
