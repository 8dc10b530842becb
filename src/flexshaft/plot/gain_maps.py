"""Maps over the actuator gains (K_p, K_d): thesis figures 3.12, 3.15, 3.16
(:func:`gain_map_figure`) and the whirl-stability margin map (:func:`stability_margin_figure`).

Both gains are drawn on logarithmic axes (cells centred on the grid values in log10, edges
half-way between neighbours). A derivative gain of zero, the thesis's starting point, has no
place on a log axis: its row is drawn as a strip of its own under the map, separated by a gap
and labelled "0", so the map's decades stay true. Marked points (the best gains ★, the design's
gains ○) are drawn at their own gains, not snapped to a cell; a ring is larger than the star, so
both stay visible when they coincide.

Plain arrays in (gains [N/m], [N s/m], values in SI); matplotlib imported lazily through
:func:`flexshaft.plot.style.styled`; every function returns a Figure.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import new_figure, nice_colorbar, plain_log_label, styled, vector

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["gain_map_figure", "stability_margin_figure", "gain_label"]

BEST_MARKER = {"marker": "*", "ms": 15, "mfc": "gold", "mec": "k", "mew": 1.0, "ls": "none", "zorder": 6}
_RING_COLOURS = ("tab:red", "w", "tab:orange")


def gain_label(value: float) -> str:
    """A gain as a short tick label: ``0``, ``300``, ``1170``, ``5e5``, ``4.28e5``."""
    value = float(value)
    if value == 0.0:
        return "0"
    if 1e-2 <= abs(value) < 1e4:
        return f"{float(f'{value:.3g}'):g}"  # 3 significant digits without an exponent: 1170, 15.6
    mantissa, exponent = f"{value:.3g}".split("e")
    return f"{mantissa}e{int(exponent)}"


def _grid(name: str, values: ArrayLike, shape: tuple[int, int]) -> np.ndarray:
    array = np.asarray(values, dtype=float)
    if array.shape != shape:
        raise ValueError(f"{name}: expected shape {shape} (K_p axis, K_d axis), got {array.shape}")
    return array


def _edges(centres: np.ndarray) -> np.ndarray:
    c = np.asarray(centres, dtype=float)
    if c.size == 1:
        return np.array([c[0] - 0.5, c[0] + 0.5])
    mid = 0.5 * (c[1:] + c[:-1])
    return np.concatenate([[2 * c[0] - mid[0]], mid, [2 * c[-1] - mid[-1]]])


def _ticks(values: np.ndarray) -> tuple[list[float], list[str]]:
    """Tick positions (log10) and labels of positive gains: each value when there are few,
    else the decades (10ⁿ)."""
    logs = np.log10(values)
    if values.size <= 8:
        return [float(v) for v in logs], [gain_label(v) for v in values]
    decades = range(int(np.ceil(logs.min() - 1e-9)), int(np.floor(logs.max() + 1e-9)) + 1)
    return [float(d) for d in decades], [plain_log_label(f"$\\mathdefault{{10^{{{d}}}}}$") for d in decades]


@dataclass
class _GainAxes:
    """The map's axes: ``main`` holds the positive K_d rows (log10 positions), ``zero`` the
    K_d = 0 strip (None when the grid has no zero); ``cax`` the colour bar."""

    main: Any
    zero: Any
    cax: Any
    x: np.ndarray  # log10 K_p of every column
    y: np.ndarray  # log10 K_d of the positive rows
    positive: np.ndarray  # mask of the K_d values > 0
    zero_index: int | None

    @property
    def bottom(self):
        return self.zero if self.zero is not None else self.main

    @property
    def all(self) -> list:
        return [a for a in (self.main, self.zero) if a is not None]

    def place(self, kp: float, kd: float):
        """(axes, x, y) of a point at gains (kp, kd), clipped to the map."""
        xe = _edges(self.x)
        x = float(np.clip(np.log10(kp), xe[0], xe[-1])) if kp > 0 else float(xe[0])
        if kd <= 0 and self.zero is not None:
            return self.zero, x, 0.5
        if self.y.size == 0:  # only a K_d = 0 row, drawn on the main axes
            return self.main, x, 0.5
        ye = _edges(self.y)
        y = float(np.clip(np.log10(kd), ye[0], ye[-1])) if kd > 0 else float(ye[0])
        return self.main, x, y


def _gain_axes(fig, ax, kp: np.ndarray, kd: np.ndarray) -> _GainAxes:
    from mpl_toolkits.axes_grid1 import make_axes_locatable

    if np.any(~np.isfinite(kp)) or np.any(kp <= 0):
        raise ValueError(f"kp: proportional gains must be finite and > 0 for the log axis, got {kp.tolist()}")
    if np.any(~np.isfinite(kd)) or np.any(kd < 0):
        raise ValueError(f"kd: derivative gains must be finite and >= 0, got {kd.tolist()}")
    positive = kd > 0
    zeros = np.flatnonzero(~positive)
    zero_index = int(zeros[0]) if zeros.size else None
    x = np.log10(kp)
    y = np.log10(kd[positive])
    divider = make_axes_locatable(ax)
    zero = None
    if zero_index is not None and y.size:
        height = ax.get_position().height * fig.get_figheight()
        size = float(np.clip(height / (y.size + 1), 0.3, 0.55))
        zero = divider.append_axes("bottom", size=size, pad=0.12, sharex=ax)
        ax.tick_params(labelbottom=False)
    cax = divider.append_axes("right", size=0.18, pad=0.15)
    return _GainAxes(ax, zero, cax, x, y, positive, zero_index)


def _draw_cells(g: _GainAxes, z: np.ndarray, **mesh_kw):
    """pcolormesh of z (n_kp, n_kd) on the map and its K_d = 0 strip; returns the main mesh."""
    xe = _edges(g.x)
    mesh = None
    if g.y.size:
        mesh = g.main.pcolormesh(xe, _edges(g.y), z[:, g.positive].T, shading="flat", **mesh_kw)
    if g.zero_index is not None:
        target = g.zero if g.zero is not None else g.main
        strip = target.pcolormesh(xe, [0.0, 1.0], z[:, g.zero_index][None, :], shading="flat", **mesh_kw)
        mesh = mesh if mesh is not None else strip
    return mesh


def _cells(g: _GainAxes):
    """(i, j, axes, x, y) of every cell centre: column i (K_p), row j (K_d)."""
    rows = np.flatnonzero(g.positive)
    for i, x in enumerate(g.x):
        for k, j in enumerate(rows):
            yield i, int(j), g.main, float(x), float(g.y[k])
        if g.zero_index is not None:
            yield i, g.zero_index, (g.zero if g.zero is not None else g.main), float(x), 0.5


def _finish_axes(g: _GainAxes, kp: np.ndarray, kd: np.ndarray, title: str) -> None:
    xe = _edges(g.x)
    xt, xl = _ticks(kp)
    for a in g.all:
        a.set_xlim(xe[0], xe[-1])
        a.grid(False)
    g.bottom.set_xticks(xt, xl)
    g.bottom.set_xlabel("proportional gain K_p [N/m]")
    if g.y.size:
        yt, yl = _ticks(kd[g.positive])
        ye = _edges(g.y)
        g.main.set_ylim(ye[0], ye[-1])
        g.main.set_yticks(yt, yl)
    if g.zero_index is not None:
        strip = g.zero if g.zero is not None else g.main
        strip.set_ylim(0.0, 1.0)
        strip.set_yticks([0.5], ["0"])
    g.main.set_ylabel("derivative gain K_d [N s/m]")
    g.main.set_title(title)


def _band(entries: int) -> float:
    """Bottom margin [in]: the x label and a legend of ``entries`` lines under it."""
    return 0.7 + (0.22 * entries + 0.15 if entries else 0.0)


def _legend(fig, g: _GainAxes, own: bool, handles=None) -> None:
    handles = handles if handles is not None else []
    for a in g.all:
        handles += list(a.get_legend_handles_labels()[0])
    if not handles:
        return
    if own:  # in the band under the map: it hides neither a marker nor a cell
        g.main.legend(
            handles=handles,
            loc="lower center",
            bbox_to_anchor=(0.5, 0.01),
            bbox_transform=fig.transFigure,
            ncols=1,
            fontsize=7.5,
        )
    else:
        g.main.legend(handles=handles, loc="lower left", fontsize=7.5)


@styled
def gain_map_figure(
    kp: ArrayLike,
    kd: ArrayLike,
    values: ArrayLike,
    label: str,
    *,
    scale: float = 1.0,
    best: tuple[float, float] | None = None,
    other: Mapping[str, tuple[float, float]] | None = None,
    log_values: bool = True,
    title: str = "",
    ax=None,
) -> Figure:
    """A quantity over the (K_p, K_d) grid (thesis figures 3.12, 3.15, 3.16).

    Parameters
    ----------
    kp, kd : array_like
        Gains [N/m] (> 0), [N s/m] (>= 0); log axes, a zero K_d drawn as a strip under the map.
    values : array_like, shape (n_kp, n_kd)
        The quantity in SI units, multiplied by ``scale`` for display (1e3: m to mm).
    label : str
        Colour-bar label with its display unit.
    best : (kp, kd), optional
        Marked with a star at its gains. ``other``: more labelled points, each a ring larger
        than the star, e.g. ``{"design": (1e7, 0)}``.
    log_values : bool
        Logarithmic colour scale.
    ax : matplotlib Axes, optional
        The map's axes (the K_d = 0 strip and the colour bar are taken from its space).
    """
    from matplotlib.colors import LogNorm

    kp_v = vector("kp", kp)
    kd_v = vector("kd", kd)
    z = _grid("values", values, (kp_v.size, kd_v.size)) * scale
    own = ax is None
    entries = (best is not None) + len(other or {})
    fig, axes = new_figure(1, 1, (7.0, 5.4 + _band(entries)), ax=ax, left=1.0, bottom=_band(entries), right=1.05)
    g = _gain_axes(fig, axes[0, 0], kp_v, kd_v)
    finite = z[np.isfinite(z) & (z > 0)]
    norm = LogNorm(finite.min(), finite.max()) if log_values and finite.size and finite.max() > finite.min() else None
    mesh = _draw_cells(g, z, cmap="viridis", norm=norm)
    zp = z[:, g.positive]
    if zp.shape[0] > 2 and zp.shape[1] > 2 and np.isfinite(zp).sum() > 4 and finite.size > 4:
        levels = np.geomspace(finite.min(), finite.max(), 9)[1:-1] if norm is not None else 7
        cs = g.main.contour(g.x, g.y, zp.T, levels=levels, colors="w", linewidths=0.6, alpha=0.8)
        g.main.clabel(cs, fontsize=6.5, fmt="%.3g")
    if best is not None:
        a, x, y = g.place(*best)
        a.plot(x, y, **BEST_MARKER, label=f"best: K_p = {best[0]:.3g} N/m, K_d = {best[1]:.3g} N s/m")
    for k, (name, (px, py)) in enumerate(dict(other or {}).items()):
        a, x, y = g.place(px, py)
        a.plot(
            x,
            y,
            "o",
            ms=21 + 5 * k,
            mfc="none",
            mec=_RING_COLOURS[k % len(_RING_COLOURS)],
            mew=2.0,
            ls="none",
            zorder=7,
            label=f"{name}: K_p = {px:.3g} N/m, K_d = {py:.3g} N s/m (ring)",
        )
    nice_colorbar(fig, mesh, g.main, label, log=norm is not None, cax=g.cax)
    _finish_axes(g, kp_v, kd_v, title)
    _legend(fig, g, own)
    return fig


def _diverging_map():
    """Red (unstable, ζ < 0: never near white) below the centre, white to navy above."""
    import matplotlib
    from matplotlib.colors import ListedColormap

    reds = matplotlib.colormaps["Reds"](np.linspace(0.95, 0.5, 128))
    blues = matplotlib.colormaps["Blues"](np.linspace(0.03, 0.95, 128))
    return ListedColormap(np.vstack([reds, blues]), name="stability_margin")


def _luminance(rgba) -> float:
    r, g, b = rgba[:3]
    return 0.299 * r + 0.587 * g + 0.114 * b


@styled
def stability_margin_figure(
    kp: ArrayLike,
    kd: ArrayLike,
    margin: ArrayLike,
    onset_rpm: ArrayLike | None = None,
    best: tuple[float, float] | None = None,
    *,
    ax=None,
) -> Figure:
    """Smallest damping ratio ζ at the operating speed over (K_p, K_d).

    A diverging colour scale centred at ζ = 0: stable cells white to navy, unstable cells
    (ζ < 0, however small) red and hatched; the colour bar shows the sign. ``onset_rpm``
    (n_kp, n_kd) [rpm], NaN where stable over the analysed range, is written in each cell when
    the grid is small (in white on dark cells). ``best`` (kp, kd): the tuned gains, a star.
    """
    from matplotlib.colors import TwoSlopeNorm
    from matplotlib.patches import Patch, Rectangle

    kp_v = vector("kp", kp)
    kd_v = vector("kd", kd)
    z = _grid("margin", margin, (kp_v.size, kd_v.size))
    own = ax is None
    entries = (best is not None) + bool(np.any(z < 0))
    fig, axes = new_figure(1, 1, (7.0, 5.4 + _band(entries)), ax=ax, left=1.0, bottom=_band(entries), right=1.05)
    g = _gain_axes(fig, axes[0, 0], kp_v, kd_v)
    finite = z[np.isfinite(z)]
    low = float(finite.min()) if finite.size else -1.0
    high = float(finite.max()) if finite.size else 1.0
    top = high if high > 0 else 0.1 * abs(low)
    bottom = low if low < 0 else -0.1 * top
    norm = TwoSlopeNorm(0.0, bottom, top)
    cmap = _diverging_map()
    mesh = _draw_cells(g, z, cmap=cmap, norm=norm)
    onset = None if onset_rpm is None or z.size > 64 else _grid("onset_rpm", onset_rpm, z.shape)
    unstable_handle = None
    for i, j, a, x, y in _cells(g):
        xe = _edges(g.x)
        width = xe[i + 1] - xe[i]
        if a is g.main and g.y.size:
            ye = _edges(g.y)
            k = int(np.searchsorted(np.flatnonzero(g.positive), j))
            y0, height = ye[k], ye[k + 1] - ye[k]
        else:
            y0, height = 0.0, 1.0
        if np.isfinite(z[i, j]) and z[i, j] < 0:
            a.add_patch(Rectangle((xe[i], y0), width, height, fill=False, hatch="///", ec="k", lw=0.0, alpha=0.7))
            unstable_handle = Patch(fc=cmap(0.15), ec="k", hatch="///", label="unstable at the operating speed (ζ < 0)")
        if onset is not None:
            text = "stable" if not np.isfinite(onset[i, j]) else f"onset\n{onset[i, j]:.0f} rpm"
            colour = "w" if np.isfinite(z[i, j]) and _luminance(cmap(norm(z[i, j]))) < 0.5 else "k"
            a.text(x, y, text, ha="center", va="center", fontsize=6.5, color=colour, zorder=4)
    if best is not None:
        a, x, y = g.place(*best)
        a.plot(x, y, **BEST_MARKER, label=f"tuned gains K_p = {best[0]:.3g} N/m, K_d = {best[1]:.3g} N s/m")
    bar = nice_colorbar(fig, mesh, g.main, "smallest damping ratio ζ at the operating speed [-]", cax=g.cax)
    for at, text, colour in ((0.25, "unstable ζ < 0", "w"), (0.75, "stable ζ > 0", "k")):
        bar.ax.text(
            0.5, at, text, rotation=90, ha="center", va="center", fontsize=7, color=colour, transform=bar.ax.transAxes
        )
    _finish_axes(g, kp_v, kd_v, "Whirl-stability margin over the actuator gains")
    _legend(fig, g, own, [unstable_handle] if unstable_handle is not None else [])
    return fig
