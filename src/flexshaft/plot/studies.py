"""Figures of the design studies of thesis chapter 3 (``flexshaft.thesis``).

Same conventions as :mod:`flexshaft.plot.driveline`: inputs are plain numpy arrays (or an
:class:`xarray.Dataset` where named) in SI units with speeds in rpm; lengths are drawn in mm;
every function returns a :class:`matplotlib.figure.Figure`; matplotlib is imported lazily (Agg,
no pyplot state) through :func:`flexshaft.plot.style.styled`. Nothing here knows of models.

Thesis figure numbers: 3.2 :func:`ply_angle_figure`, 3.3 :func:`two_angle_figure`,
3.4 :func:`wall_thickness_figure`, 3.5 :func:`forced_response_figure`, 3.6 :func:`gain_figure`,
3.10 :func:`buckling_figure`, 3.12/3.15/3.16 :func:`gain_map_figure`, 3.13/3.14
:func:`response_surface_figure`, 3.17 :func:`tuned_gains_figure`; the stability margin map
:func:`stability_margin_figure` goes beyond the thesis. The two gain maps live in
:mod:`flexshaft.plot.gain_maps` (re-exported here).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.gain_maps import BEST_MARKER, gain_map_figure, stability_margin_figure
from flexshaft.plot.style import MM_PER_M, log_scale, mark_operating, new_figure, nice_colorbar, styled, vector

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "ply_angle_figure",
    "two_angle_figure",
    "wall_thickness_figure",
    "forced_response_figure",
    "gain_figure",
    "buckling_figure",
    "gain_map_figure",
    "response_surface_figure",
    "tuned_gains_figure",
    "stability_margin_figure",
]

_BEST = BEST_MARKER


def _grid(name: str, values: ArrayLike, shape: tuple[int, int]) -> np.ndarray:
    array = np.asarray(values, dtype=float)
    if array.shape != shape:
        raise ValueError(f"{name}: expected shape {shape} (first axis, second axis), got {array.shape}")
    return array


def _edges(centres: np.ndarray) -> np.ndarray:
    c = np.asarray(centres, dtype=float)
    if c.size == 1:
        return np.array([c[0] - 0.5, c[0] + 0.5])
    mid = 0.5 * (c[1:] + c[:-1])
    return np.concatenate([[2 * c[0] - mid[0]], mid, [2 * c[-1] - mid[-1]]])


@styled
def ply_angle_figure(
    alpha_deg: ArrayLike,
    safety_factor: ArrayLike,
    dominant: Sequence[str] | None = None,
    thesis_optimum_deg: float | None = 55.0,
    *,
    ax=None,
) -> Figure:
    """Safety factor against the ply angle α of (α/−α/−α/α) (thesis figure 3.2).

    Parameters
    ----------
    alpha_deg : array_like, shape (n,)
        Ply angles [deg].
    safety_factor : array_like, shape (n,)
        Tsai-Wu safety factor [-].
    dominant : sequence of str, optional
        Dominant stress at each angle ("sigma1", "sigma2", "tau12"), drawn as marker shapes.
    thesis_optimum_deg : float, optional
        The thesis's optimum, drawn as a dotted line.
    """
    alpha = vector("alpha_deg", alpha_deg)
    sf = vector("safety_factor", safety_factor, alpha.size)
    fig, axes = new_figure(1, 1, (8.0, 4.5), ax=ax)
    ax = axes[0, 0]
    ax.plot(alpha, sf, color="C0", label="safety factor R")
    if dominant is not None:
        dom = np.asarray(dominant, dtype=str)
        for name, marker, label in (
            ("sigma1", "o", "σ1 dominates"),
            ("sigma2", "s", "σ2 dominates"),
            ("tau12", "^", "τ12 dominates"),
        ):
            sel = dom == name
            if sel.any():
                ax.plot(alpha[sel], sf[sel], marker, ms=4.5, color="C0", mfc="white", label=label)
    i = int(np.nanargmax(sf))
    ax.plot(alpha[i], sf[i], **_BEST, label=f"best ±{alpha[i]:g}°: R = {sf[i]:.3g}")
    if thesis_optimum_deg is not None:
        ax.axvline(thesis_optimum_deg, color="0.4", ls=":", lw=1.3, label=f"thesis optimum ±{thesis_optimum_deg:g}°")
    ax.set_xlim(0.0, 90.0)
    ax.set_ylim(bottom=0.0)
    ax.set_xticks(np.arange(0, 91, 15))
    ax.set_xlabel("ply angle α [deg], laminate (α/−α/−α/α)")
    ax.set_ylabel("Tsai-Wu safety factor R [-]")
    ax.set_title("Safety factor vs ply orientation (no imbalance)")
    ax.legend(loc="best")
    return fig


@styled
def two_angle_figure(
    alpha_deg: ArrayLike,
    beta_deg: ArrayLike,
    safety_factor: ArrayLike,
    thesis_best: tuple[float, float] | None = (55.0, 0.0),
    *,
    best: tuple[float, float] | None = None,
    ax=None,
) -> Figure:
    """Safety factor map of (α/−α/β/−β)s (thesis figure 3.3), best laminate marked.

    ``safety_factor`` has shape (n_alpha, n_beta). ``best`` = (α, β) [deg], a point of the
    grid, is the laminate marked as the best: the study's choice among the exact ties of the
    symmetric map (:func:`flexshaft.thesis.two_angles.best_pair`); default, the first largest
    value in (α, β) order.
    """
    a = vector("alpha_deg", alpha_deg)
    b = vector("beta_deg", beta_deg)
    sf = _grid("safety_factor", safety_factor, (a.size, b.size))
    own = ax is None
    fig, axes = new_figure(1, 1, (6.8, 6.0), ax=ax, bottom=1.05)
    ax = axes[0, 0]
    mesh = ax.pcolormesh(_edges(a), _edges(b), sf.T, cmap="viridis", shading="flat")
    if a.size > 2 and b.size > 2 and np.isfinite(sf).sum() > 4:
        cs = ax.contour(a, b, sf.T, levels=8, colors="w", linewidths=0.7, alpha=0.8)
        ax.clabel(cs, fontsize=7, fmt="%.3g")
    if best is None:
        i, j = (int(k) for k in np.unravel_index(int(np.nanargmax(sf)), sf.shape))
    else:
        i, j = int(np.flatnonzero(a == best[0])[0]), int(np.flatnonzero(b == best[1])[0])
    ax.plot(a[i], b[j], **_BEST, label=f"best ({a[i]:g}/−{a[i]:g}/{b[j]:g}/−{b[j]:g})s: R = {sf[i, j]:.3g}")
    if thesis_best is not None:
        ax.plot(
            *thesis_best,
            "X",
            ms=10,
            mfc="none",
            mec="tab:red",
            mew=1.6,
            label=f"thesis ({thesis_best[0]:g}/−{thesis_best[0]:g}/{thesis_best[1]:g}/−{thesis_best[1]:g})s",
        )
    nice_colorbar(fig, mesh, ax, "Tsai-Wu safety factor R [-]", pad=0.03)
    ax.set_xlabel("α [deg]")
    ax.set_ylabel("β [deg]")
    ax.set_title("Safety factor of (α/−α/β/−β)s (no imbalance)")
    if own:  # below the map: it hides no cell
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.11), ncols=2, fontsize=7.5)
    else:
        ax.legend(loc="upper left", fontsize=7.5)
    ax.grid(False)
    return fig


@styled
def wall_thickness_figure(
    wall: ArrayLike,
    with_imbalance: ArrayLike,
    without_imbalance: ArrayLike,
    frequency_hz: ArrayLike | None = None,
    spinup_peak: ArrayLike | None = None,
    *,
    ax=None,
) -> Figure:
    """Safety factor with and without imbalance vs wall thickness at fixed D_o (thesis fig.
    3.4); optionally the shaft's first lateral natural frequency [Hz] and the spin-up peak
    shaft orbit [m], each on a panel of its own (the orbit's NaN entries are left out, and its
    panel when all are NaN: a design without actuators). ``wall`` [m]."""
    t = vector("wall", wall)
    f = None if frequency_hz is None else vector("frequency_hz", frequency_hz, t.size)
    peak = None if spinup_peak is None else vector("spinup_peak", spinup_peak, t.size)
    if peak is not None and not np.isfinite(peak).any():
        peak = None
    nrows = 1 + (f is not None) + (peak is not None)
    fig, axes = new_figure(nrows, 1, (8.0, 3.4 + 2.6 * (nrows - 1)), ax=ax, hspace=0.3)
    ax = axes[0, 0]
    ax.plot(t * MM_PER_M, vector("with_imbalance", with_imbalance, t.size), "o-", label="with imbalance")
    ax.plot(t * MM_PER_M, vector("without_imbalance", without_imbalance, t.size), "s--", label="without imbalance")
    ax.set_ylim(bottom=0.0)
    ax.set_ylabel("Tsai-Wu safety factor R [-]")
    ax.set_title("Safety factor vs wall thickness (fixed outer diameter)")
    ax.legend(loc="best")
    if f is not None:
        axes[1, 0].plot(t * MM_PER_M, f, "o-", color="C2", label="shaft's first lateral mode at rest")
        axes[1, 0].set_ylabel("frequency [Hz]")
        axes[1, 0].legend(loc="best")
    if peak is not None:
        panel, finite, k = axes[-1, 0], np.isfinite(peak), int(np.nanargmin(peak))
        panel.plot(
            t[finite] * MM_PER_M,
            peak[finite] * MM_PER_M,
            "D-",
            color="C4",
            label="spin-up peak shaft orbit (design gains)",
        )
        panel.plot(
            [t[k] * MM_PER_M],
            [peak[k] * MM_PER_M],
            "*",
            ms=13,
            color="gold",
            mec="k",
            label=f"smallest: {peak[k] * MM_PER_M:.3g} mm at {t[k] * MM_PER_M:g} mm wall",
        )
        panel.set_ylim(bottom=0.0)
        panel.set_ylabel("orbit [mm]")
        panel.legend(loc="best")
    axes[-1, 0].set_xlabel("wall thickness [mm]")
    return fig


@styled
def forced_response_figure(
    speeds_rpm: ArrayLike, responses: Mapping[str, ArrayLike], operating_rpm: float | None = None, *, ax=None
) -> Figure:
    """Largest shaft orbit against speed for a few designs, e.g. two walls (thesis fig. 3.5,
    3.9, 3.11). ``responses[label]`` is (n_speeds,) [m]; logarithmic amplitude axis."""
    speeds = vector("speeds_rpm", speeds_rpm)
    fig, axes = new_figure(1, 1, (8.0, 4.5), ax=ax)
    ax = axes[0, 0]
    drawn = False
    for label, values in responses.items():
        amp = vector(f"responses[{label!r}]", values, speeds.size) * MM_PER_M
        ax.plot(speeds, np.where(amp > 0, amp, np.nan), label=label)
        drawn |= bool(np.any(amp > 0))
    mark_operating(ax, operating_rpm)
    if drawn:
        log_scale(ax)
    else:  # no imbalance given: every orbit is 0, nothing to draw on a logarithmic axis
        ax.set_ylim(0.0, 1.0)
        ax.text(
            0.5,
            0.5,
            "no imbalance response: every orbit is 0 (no imbalance given)",
            transform=ax.transAxes,
            ha="center",
            va="center",
            color="0.35",
        )
    ax.set_xlim(speeds.min(), speeds.max())
    ax.set_xlabel("spin speed Ω [rpm]")
    ax.set_ylabel("max shaft orbit [mm]")
    ax.set_title("Maximum shaft response to imbalance")
    ax.legend(loc="best")
    return fig


@styled
def gain_figure(
    kp: ArrayLike,
    safety_factor: ArrayLike,
    actuator_displacement: ArrayLike,
    design_kp: float | None = None,
    *,
    ax=None,
) -> Figure:
    """Safety factor and largest actuator displacement at the operating speed vs K_p
    (thesis figure 3.6). ``kp`` [N/m], displacement [m] (drawn in mm)."""
    k = vector("kp", kp)
    fig, axes = new_figure(2, 1, (8.0, 5.8), ax=ax, hspace=0.3)
    top, bottom = axes[0, 0], axes[1, 0]
    top.plot(k, vector("safety_factor", safety_factor, k.size), "o-")
    top.set_ylabel("Tsai-Wu safety factor R [-]")
    top.set_ylim(bottom=0.0)
    bottom.plot(k, vector("actuator_displacement", actuator_displacement, k.size) * MM_PER_M, "o-", color="C1")
    bottom.set_ylabel("max actuator displacement [mm]")
    log_scale(bottom, minor_grid=False)
    for ax in (top, bottom):
        log_scale(ax, "x", minor_grid=False)
        if design_kp is not None:
            ax.axvline(design_kp, color="0.4", ls=":", lw=1.3, label=f"design K_p = {design_kp:.3g} N/m")
            ax.legend(loc="best")
    bottom.set_xlabel("proportional gain K_p [N/m]")
    top.set_title("Effect of the proportional gain (operating speed, with imbalance)")
    return fig


@styled
def buckling_figure(wall: ArrayLike, safety_factor: ArrayLike, *, ax=None) -> Figure:
    """Torsional buckling safety factor T_cr/T vs wall thickness (thesis figure 3.10)."""
    t = vector("wall", wall)
    sf = vector("safety_factor", safety_factor, t.size)
    fig, axes = new_figure(1, 1, (8.0, 4.2), ax=ax)
    ax = axes[0, 0]
    ax.plot(t * MM_PER_M, sf, "o-")
    ax.axhline(1.0, color="tab:red", ls="--", lw=1.3, label="buckling (T_cr = T)")
    log_scale(ax)
    ax.set_xlabel("wall thickness [mm]")
    ax.set_ylabel("buckling safety factor T_cr / T [-]")
    ax.set_title("Torsional buckling (smaller of the two torque senses)")
    ax.legend(loc="best")
    return fig


def _surface_facets(X: np.ndarray, Y: np.ndarray, Z: np.ndarray, cstride: int) -> tuple[list[np.ndarray], np.ndarray]:
    """The facets of ``Axes3D.plot_surface(X, Y, Z, rstride=1, cstride=cstride)``, in its order
    (row by row, each row's facets along the second axis, the last one narrower when
    ``cstride`` does not divide ``cols - 1``): each facet is the outline of its block of grid
    points, (points, 3) — the first row forward, the last column, the second row backward, the
    first column — and each facet's mean height (its colour). Built block by block over all
    rows at once instead of one facet at a time."""
    rows, cols = Z.shape
    grid = np.stack([X, Y, Z], axis=-1)  # (rows, cols, 3)
    starts = list(range(0, cols - 1, cstride)) + [cols - 1]
    first_row = np.arange(rows - 1)[:, None]
    blocks = []
    for c0, c1 in zip(starts[:-1], starts[1:]):
        w = c1 - c0
        dr = np.concatenate([np.zeros(w + 1, dtype=int), np.ones(w + 1, dtype=int)])
        dc = np.concatenate([np.arange(w + 1), np.arange(w, -1, -1)])
        blocks.append(grid[first_row + dr[None, :], c0 + dc[None, :]])  # (rows - 1, 2w + 2, 3)
    facets = [block[r] for r in range(rows - 1) for block in blocks]
    return facets, np.stack([block[..., 2].mean(axis=1) for block in blocks], axis=1).ravel()


def _surface(ax, X: np.ndarray, Y: np.ndarray, Z: np.ndarray, cstride: int, top: float) -> None:
    """Z over (X, Y) as ``plot_surface(rstride=1, cstride=cstride)`` draws it (viridis over
    [0, top], facets coloured by their mean height, no edges), its facets built vectorised
    (:func:`_surface_facets`): ``plot_surface`` builds a facet at a time in Python when
    ``cstride`` does not divide the columns evenly (26 ms for a 38 × 393 grid). A grid with
    non-finite values goes to ``plot_surface``, which drops those points from the facets."""
    style = {"cmap": "viridis", "linewidth": 0, "antialiased": False}
    if not (np.isfinite(X).all() and np.isfinite(Y).all() and np.isfinite(Z).all()) or min(Z.shape) < 2:
        ax.plot_surface(X, Y, Z, vmin=0.0, vmax=top, rstride=1, cstride=cstride, **style)
        return
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    had_data = ax.has_data()
    facets, heights = _surface_facets(X, Y, Z, cstride)
    surface = Poly3DCollection(facets, **style)
    surface.set_array(heights)
    surface.set_clim(0.0, top)
    ax.add_collection3d(surface, autolim=False)
    ax.auto_scale_xyz(X, Y, Z, had_data)


@styled
def response_surface_figure(
    x: ArrayLike, speeds_rpm: ArrayLike, surfaces: Mapping[str, ArrayLike], bearings_x: Sequence[float] = (), *, ax=None
) -> Figure:
    """Frequency-response surfaces: shaft orbit over position × speed (thesis figures 3.13,
    3.14), one 3-D panel per labelled case. ``surfaces[label]`` is (n_nodes, n_speeds) [m];
    ``x`` the node stations [m]. Panels share the amplitude axis."""
    xs = vector("x", x)
    speeds = vector("speeds_rpm", speeds_rpm)
    n = len(surfaces)
    fig, axes = new_figure(
        1, n, (6.2 * n, 5.0), ax=ax, left=0.25, right=0.25, bottom=0.2, top=0.45, wspace=0.5, projection="3d"
    )
    top = max(float(np.nanmax(np.asarray(v))) for v in surfaces.values()) * MM_PER_M
    X, S = np.meshgrid(xs, speeds, indexing="ij")
    for k, (label, values) in enumerate(surfaces.items()):
        z = _grid(f"surfaces[{label!r}]", values, (xs.size, speeds.size)) * MM_PER_M
        ax = axes[0, k]
        _surface(ax, X, S, z, max(1, speeds.size // 60), top)
        for xb in bearings_x:
            ax.plot([xb, xb], [speeds.min(), speeds.max()], [0, 0], color="k", lw=1.0)
        ax.set_zlim(0.0, top)
        ax.set_xlabel("shaft position x [m]")
        ax.set_ylabel("speed Ω [rpm]")
        ax.set_zlabel("orbit [mm]")
        ax.set_title(f"{label}\npeak {np.nanmax(z):.3g} mm", fontsize=9.5)
        ax.view_init(elev=28, azim=-125)
    return fig


@styled
def tuned_gains_figure(
    speeds_rpm: ArrayLike, curves: Mapping[str, ArrayLike], operating_rpm: float | None = None, *, ax=None
) -> Figure:
    """Largest shaft orbit during spin-up before and after tuning the gains (thesis figure
    3.17). ``curves[label]`` is (n_speeds,) [m]; each peak is annotated."""
    speeds = vector("speeds_rpm", speeds_rpm)
    fig, axes = new_figure(1, 1, (8.0, 4.6), ax=ax)
    ax = axes[0, 0]
    for label, values in curves.items():
        amp = vector(f"curves[{label!r}]", values, speeds.size) * MM_PER_M
        (line,) = ax.plot(speeds, amp, label=label)
        i = int(np.nanargmax(amp))
        ax.annotate(
            f"{amp[i]:.3g} mm",
            (speeds[i], amp[i]),
            xytext=(4, 4),
            textcoords="offset points",
            color=line.get_color(),
            fontsize=8.5,
        )
    mark_operating(ax, operating_rpm)
    ax.set_ylim(bottom=0.0)
    ax.set_xlim(speeds.min(), speeds.max())
    ax.set_xlabel("spin speed Ω [rpm]")
    ax.set_ylabel("max shaft orbit [mm]")
    ax.set_title("Spin-up response: design gains and tuned gains")
    ax.legend(loc="best")
    return fig
