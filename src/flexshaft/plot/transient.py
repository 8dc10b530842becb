"""Figures of the run-up transient and the Monte-Carlo imbalance (matplotlib imported lazily).

Inputs are duck-typed result objects (no analysis is imported here): a run has ``speed``
[rad/s], ``shaft_peak`` [m] (n_t,), ``actuator_displacement`` [m] and ``actuator_force`` [N]
(n_act, n_t) (:class:`flexshaft.analyses.transient.TransientResult`); a steady curve has
``speeds`` [rad/s] and the same three envelopes over them
(:class:`flexshaft.analyses.transient.SteadyEnvelope`); a Monte-Carlo sample set is an
:class:`xarray.Dataset` over ``sample`` with the outputs of
:mod:`flexshaft.montecarlo`. Speeds are drawn in rpm, lengths in mm.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from flexshaft.plot.style import MM_PER_M, mark_operating, new_figure, styled
from flexshaft.units import rad_s_to_rpm

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["runup_envelope_figure", "montecarlo_figure"]


def _positive(values) -> np.ndarray:
    v = np.asarray(values, dtype=float)
    return np.where(v > 0, v, np.nan)


@styled
def runup_envelope_figure(
    runs: Mapping[str, Any],
    steady: Any = None,
    *,
    operating_rpm: float | None = None,
    gap: float | None = None,
    force_limit: float | None = None,
    decades: float = 3.0,
    ax: Axes | None = None,
) -> Figure:
    """Run-up (or run-down) envelopes against speed, with the steady-state spin-up curve.

    Each log axis spans ``decades`` below the largest value drawn in its panel (the curves'
    peaks and the limits): the start of a run from rest reaches 1e-7 mm, which would otherwise
    take half of every panel.

    Parameters
    ----------
    runs : mapping of str to run
        Label (e.g. "10 s run-up") → run result.
    steady : steady curve, optional
        Drawn dashed black.
    operating_rpm : float, optional
        Operating speed [rpm].
    gap, force_limit : float, optional
        Actuator radial gap [m] and force capacity [N], drawn as horizontal lines.
    decades : float
        Decades shown below each panel's largest value (> 0).
    ax : matplotlib Axes, optional
        Draw only the shaft panel on it; otherwise a new figure with three panels (largest
        shaft deflection, actuator relative orbit, actuator force).

    Returns
    -------
    matplotlib.figure.Figure
    """
    if not (np.isfinite(decades) and decades > 0):
        raise ValueError(f"decades: must be a positive number of decades, got {decades!r}")
    if ax is None:
        fig, axes = new_figure(3, 1, (8.5, 9.0), sharex=True)
        panels = list(axes[:, 0])
    else:
        fig, panels = ax.figure, [ax]
    for label, run in runs.items():
        rpm = rad_s_to_rpm(np.asarray(run.speed, dtype=float))
        (line,) = panels[0].plot(rpm, _positive(run.shaft_peak) * MM_PER_M, lw=1.0, label=label)
        if len(panels) > 1 and np.size(run.actuator_displacement):
            panels[1].plot(
                rpm,
                _positive(np.max(run.actuator_displacement, axis=0)) * MM_PER_M,
                lw=1.0,
                color=line.get_color(),
                label=label,
            )
            panels[2].plot(
                rpm, _positive(np.max(run.actuator_force, axis=0)), lw=1.0, color=line.get_color(), label=label
            )
    if steady is not None:
        rpm = rad_s_to_rpm(np.asarray(steady.speeds, dtype=float))
        panels[0].plot(rpm, _positive(steady.shaft_peak) * MM_PER_M, "k--", lw=1.2, label="steady-state spin-up")
        if len(panels) > 1 and np.size(steady.actuator_displacement):
            panels[1].plot(
                rpm,
                _positive(np.max(steady.actuator_displacement, axis=0)) * MM_PER_M,
                "k--",
                lw=1.2,
                label="steady-state spin-up",
            )
            panels[2].plot(
                rpm, _positive(np.max(steady.actuator_force, axis=0)), "k--", lw=1.2, label="steady-state spin-up"
            )
    panels[0].set_ylabel("largest shaft deflection [mm]")
    panels[0].set_title("Run-up through the criticals: deflection envelope against speed")
    if len(panels) > 1:
        panels[1].set_ylabel("actuator relative orbit [mm]\n(largest over the actuators)")
        panels[2].set_ylabel("actuator force [N]")
        if gap is not None:
            panels[1].axhline(gap * MM_PER_M, color="tab:red", ls=":", lw=1.4, label=f"gap {gap * MM_PER_M:.3g} mm")
        if force_limit is not None:
            panels[2].axhline(force_limit, color="tab:red", ls=":", lw=1.4, label=f"force limit {force_limit:.4g} N")
    for panel in panels:
        panel.set_yscale("log")
        top = _largest_drawn(panel)
        if top is not None:  # the meaningful range: `decades` below the peak, a little room above
            panel.set_ylim(top * 10.0**-decades, top * 2.0)
        panel.grid(which="minor", alpha=0.12)
        mark_operating(panel, operating_rpm, label=panel is panels[0])
        panel.legend(loc="lower right", fontsize=8)
    panels[-1].set_xlabel("spin speed Ω [rpm]")
    return fig


def _largest_drawn(ax) -> float | None:
    """The largest finite positive y of the lines drawn on ``ax`` (horizontal limit lines
    included; vertical lines, in axes coordinates, left out)."""
    top = None
    for line in ax.get_lines():
        if line.get_transform() == ax.get_xaxis_transform():  # a vertical line: y in axes units
            continue
        y = np.asarray(line.get_ydata(), dtype=float)
        y = y[np.isfinite(y) & (y > 0)]
        if y.size:
            top = float(y.max()) if top is None else max(top, float(y.max()))
    return top


def _mark_bound(ax, limit: float, count: int, n: int, upper: float) -> None:
    """The exceedance of ``limit``: ▼ at the upper confidence bound, a bar down to the
    estimate k/N when k > 0, and the numbers in a box."""
    p = count / n
    if count:
        ax.plot([limit, limit], [p, upper], color="tab:red", lw=2.0, solid_capstyle="butt", zorder=4)
        ax.plot([limit], [p], "o", color="tab:red", ms=4, zorder=5)
    ax.plot([limit], [upper], "v", color="tab:red", mec="k", mew=0.6, ms=8, zorder=5, label="95 % upper bound of P")
    text = (
        f"0 of {n} samples exceed:\nP < {upper:.3g} (95 % upper bound)"
        if count == 0
        else f"{count} of {n} samples exceed:\nP = {p:.3g}, < {upper:.3g} (95 %)"
    )
    ax.text(
        0.98,
        0.97,
        text,
        transform=ax.transAxes,
        ha="right",
        va="top",
        fontsize=8,
        bbox={"boxstyle": "round,pad=0.3", "fc": "white", "ec": "tab:red", "alpha": 0.9},
    )


def _exceedance(ax, values, label, scale=1.0):
    v = np.sort(np.asarray(values, dtype=float)[np.isfinite(values)]) * scale
    if v.size:
        p = 1.0 - np.arange(v.size) / v.size  # P(X ≥ v_k), ≥ 1/N
        ax.step(v, p, where="pre", label=label)  # on (v_{k-1}, v_k]: P(X ≥ x) = p_k


@styled
def montecarlo_figure(
    samples: Any,
    *,
    gap: float | None = None,
    force_limit: float | None = None,
    exceedances: Mapping[str, tuple[int, int, float]] | None = None,
    axes: Any = None,
) -> Figure:
    """Monte-Carlo imbalance: histograms of the peak deflection and the safety factor,
    exceedance curves P(X ≥ x) of the actuator orbit and force with their limits.

    Parameters
    ----------
    samples : Dataset or mapping of str to Dataset
        One sample set, or several labelled (e.g. by balance grade) drawn together.
    gap, force_limit : float, optional
        Actuator radial gap [m] and force capacity [N].
    exceedances : mapping, optional
        ``{"gap": (events, samples, upper), "force": (...)}``: how many samples exceeded each
        limit and the upper confidence bound [-] of the probability (95 %,
        :func:`flexshaft.montecarlo.confidence.clopper_pearson_upper`), drawn at the limit as
        ▼ with the count and bound written beside it (with no exceedance the estimate is 0, and
        the bound is the number to read).
    axes : array of 4 matplotlib Axes, optional
        Where to draw (row-major 2 x 2); default a new figure.
    """
    sets = {"samples": samples} if hasattr(samples, "data_vars") else dict(samples)  # a Dataset is a Mapping too
    if axes is None:
        fig, grid = new_figure(2, 2, (10.0, 7.5), sharex=False)
        (a, b), (c, d) = grid
    else:
        a, b, c, d = np.ravel(axes)
        fig = a.figure
    for label, ds in sets.items():
        n = ds.sizes["sample"]
        peak = np.asarray(ds["shaft_peak"].values, dtype=float) * MM_PER_M
        a.hist(peak[np.isfinite(peak)], bins=40, histtype="step", lw=1.4, label=f"{label} (N = {n})")
        factor = np.asarray(ds["safety_factor"].values, dtype=float)
        if np.isfinite(factor).any():
            b.hist(factor[np.isfinite(factor)], bins=40, histtype="step", lw=1.4, label=label)
        # static + dynamic, as the verdict's actuator checks (older sample sets: the dynamic part)
        excursion = "actuator_excursion_max" if "actuator_excursion_max" in ds else "actuator_orbit_max"
        load = "actuator_load_max" if "actuator_load_max" in ds else "actuator_force_max"
        _exceedance(c, ds[excursion].values, label, MM_PER_M)
        _exceedance(d, ds[load].values, label)
    a.set_xlabel("peak steady-state spin-up deflection [mm]")
    a.set_ylabel("samples")
    a.set_title("Peak shaft deflection")
    b.set_xlabel("Tsai-Wu safety factor at the operating speed [-]")
    b.set_ylabel("samples")
    b.set_title("Shaft strength")
    c.set_xlabel("actuator excursion: static offset + peak orbit [mm]")
    d.set_xlabel("actuator force: static + peak dynamic [N]")
    events = dict(exceedances or {})
    for ax, limit, name, key in (
        (c, None if gap is None else gap * MM_PER_M, "gap {:.3g} mm", "gap"),
        (d, force_limit, "force limit {:.4g} N", "force"),
    ):
        ax.set_yscale("log")
        ax.set_ylabel("P(X ≥ x)")
        ax.grid(which="minor", alpha=0.12)
        if limit is not None:
            ax.axvline(limit, color="tab:red", ls=":", lw=1.4, label=name.format(limit))
            if key in events:
                _mark_bound(ax, limit, *events[key])
    c.set_title("Actuator excursion exceedance")
    d.set_title("Actuator force exceedance")
    for ax in (a, b, c, d):
        if ax.has_data():
            ax.legend(fontsize=8, loc="lower left" if ax in (c, d) else "best")
    if axes is None:
        fig.subplots_adjust(hspace=0.42)  # the lower titles clear the upper x labels
    return fig
