"""Report figures of shapes along the driveline: static deflection and mode shapes.

Plain arrays in (positions [m], displacements [m]); matplotlib is imported lazily.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import MM_PER_M, new_figure, styled, vector

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["deflected_shape_figure", "mode_shapes_figure"]


@styled
def deflected_shape_figure(
    shaft_x: ArrayLike,
    shaft_v: ArrayLike,
    shaft_w: ArrayLike,
    boom_x: ArrayLike | None = None,
    boom_v: ArrayLike | None = None,
    boom_w: ArrayLike | None = None,
    bearings_x: Sequence[float] = (),
) -> Figure:
    """Static deflected shape of shaft and tailboom: vertical (v) and lateral (w) panels.

    Parameters
    ----------
    shaft_x : array_like, shape (n,)
        Shaft node positions [m].
    shaft_v, shaft_w : array_like, shape (n,)
        Shaft vertical and lateral deflections [m]; drawn in millimetres.
    boom_x, boom_v, boom_w : array_like, optional
        Tailboom node positions and deflections [m]; omitted when ``boom_x`` is None.
    bearings_x : sequence of float
        Bearing stations [m], marked by vertical lines and a marker on the shaft.

    Returns
    -------
    matplotlib.figure.Figure
    """
    x = vector("shaft_x", shaft_x)
    shaft = {"v": vector("shaft_v", shaft_v, x.size), "w": vector("shaft_w", shaft_w, x.size)}
    boom = None
    if boom_x is not None:
        bx = vector("boom_x", boom_x)
        boom = {"v": vector("boom_v", boom_v if boom_v is not None else np.zeros(bx.size), bx.size),
                "w": vector("boom_w", boom_w if boom_w is not None else np.zeros(bx.size), bx.size)}
    stations = vector("bearings_x", bearings_x)

    fig, axes = new_figure(2, 1, (8.0, 6.0))
    names = {"v": "vertical deflection v [mm]", "w": "lateral deflection w [mm]"}
    for ax, component in zip(axes[:, 0], ("v", "w")):
        ax.plot(x, shaft[component] * MM_PER_M, color="C0", label="shaft")
        if boom is not None:
            ax.plot(bx, boom[component] * MM_PER_M, color="C2", ls="--", label="tailboom")
        for k, station in enumerate(stations):
            ax.axvline(station, color="0.5", ls=":", lw=1.0)
            ax.plot(station, np.interp(station, x, shaft[component]) * MM_PER_M, "^", color="k", ms=7,
                    label="bearing" if k == 0 else None)
        ax.axhline(0.0, color="0.2", lw=0.6)
        ax.set_ylabel(names[component])
        ax.legend(loc="best")
    axes[0, 0].set_title("Static deflected shape")
    axes[1, 0].set_xlabel("axial position x [m]")
    return fig


def _normalise(parts: list[np.ndarray]) -> list[np.ndarray]:
    """Scale complex shapes so that max |(v, w)| = 1 and the largest component is real."""
    v_all = np.concatenate(parts[0::2])
    w_all = np.concatenate(parts[1::2])
    radius = np.sqrt(np.abs(v_all) ** 2 + np.abs(w_all) ** 2)
    both = np.concatenate([v_all, w_all])
    if radius.max(initial=0.0) == 0.0:
        return parts
    scale = radius.max() * np.exp(1j * np.angle(both[np.argmax(np.abs(both))]))
    return [p / scale for p in parts]


@styled
def mode_shapes_figure(
    shaft_x: ArrayLike,
    shapes: Sequence[Mapping[str, Any]],
    boom_x: ArrayLike | None = None,
    boom_shapes: Sequence[Mapping[str, Any]] | None = None,
) -> Figure:
    """Small multiples of mode shapes: real parts of v and w and the orbit size |(v, w)|.

    Each shape is scaled so that its largest orbit radius is 1 and its largest component is
    real (complex shapes of rotating systems are drawn at that phase).

    Parameters
    ----------
    shaft_x : array_like, shape (n,)
        Shaft node positions [m].
    shapes : sequence of mapping
        One per mode, with "label" (str, e.g. "mode 3, 41.2 Hz, forward") and "v", "w"
        (array_like, shape (n,), real or complex) shaft displacements [any length unit].
    boom_x : array_like, optional
        Tailboom node positions [m].
    boom_shapes : sequence of mapping, optional
        Tailboom "v", "w" for each entry of ``shapes``, on the same scale as the shaft.

    Returns
    -------
    matplotlib.figure.Figure
    """
    x = vector("shaft_x", shaft_x)
    if not shapes:
        raise ValueError("shapes: at least one mode shape is required")
    if boom_shapes is not None and (boom_x is None or len(boom_shapes) != len(shapes)):
        raise ValueError(f"boom_shapes: need boom_x and one entry per shape ({len(shapes)}), got {len(boom_shapes)}")
    bx = vector("boom_x", boom_x) if boom_x is not None else None
    ncols = min(3, len(shapes))
    nrows = -(-len(shapes) // ncols)
    fig, axes = new_figure(nrows, ncols, (4.2 * ncols, 2.9 * nrows + 0.6))
    for k, shape in enumerate(shapes):
        ax = axes.flat[k]
        parts = [np.asarray(shape["v"], dtype=complex).ravel(), np.asarray(shape["w"], dtype=complex).ravel()]
        if parts[0].size != x.size or parts[1].size != x.size:
            raise ValueError(f"shapes[{k}]: v and w need {x.size} values like shaft_x")
        if boom_shapes is not None:
            parts += [np.asarray(boom_shapes[k]["v"], dtype=complex).ravel(),
                      np.asarray(boom_shapes[k]["w"], dtype=complex).ravel()]
        parts = _normalise(parts)
        ax.plot(x, parts[0].real, color="C0", label="shaft v")
        ax.plot(x, parts[1].real, color="C1", label="shaft w")
        ax.plot(x, np.hypot(np.abs(parts[0]), np.abs(parts[1])), color="0.55", lw=1.0, label="shaft |(v, w)|")
        if boom_shapes is not None:
            ax.plot(bx, parts[2].real, color="C0", ls="--", lw=1.2, label="boom v")
            ax.plot(bx, parts[3].real, color="C1", ls="--", lw=1.2, label="boom w")
        ax.set_ylim(-1.1, 1.1)
        ax.set_title(str(shape.get("label", f"mode {k + 1}")), fontsize=9.5)
    for ax in axes.flat[len(shapes):]:
        ax.set_visible(False)
    for ax in axes[-1, :]:
        ax.set_xlabel("x [m]")
    for ax in axes[:, 0]:
        ax.set_ylabel("normalised [-]")
    handles, names = axes.flat[0].get_legend_handles_labels()
    fig.legend(handles, names, loc="outside lower center", ncols=len(names))
    return fig
