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
    *,
    ax=None,
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
    ax : sequence of two matplotlib Axes, optional
        Draw the v and w panels into these axes.

    Returns
    -------
    matplotlib.figure.Figure
    """
    x = vector("shaft_x", shaft_x)
    shaft = {"v": vector("shaft_v", shaft_v, x.size), "w": vector("shaft_w", shaft_w, x.size)}
    boom = None
    if boom_x is not None:
        bx = vector("boom_x", boom_x)
        boom = {
            "v": vector("boom_v", boom_v if boom_v is not None else np.zeros(bx.size), bx.size),
            "w": vector("boom_w", boom_w if boom_w is not None else np.zeros(bx.size), bx.size),
        }
    stations = vector("bearings_x", bearings_x)

    fig, axes = new_figure(2, 1, (8.0, 6.0), ax=ax, hspace=0.35)
    names = {"v": "vertical deflection v [mm]", "w": "lateral deflection w [mm]"}
    for ax, component in zip(axes[:, 0], ("v", "w")):
        ax.plot(x, shaft[component] * MM_PER_M, color="C0", label="shaft")
        if boom is not None:
            ax.plot(bx, boom[component] * MM_PER_M, color="C2", ls="--", label="tailboom")
        for k, station in enumerate(stations):
            ax.axvline(station, color="0.5", ls=":", lw=1.0)
            ax.plot(
                station,
                np.interp(station, x, shaft[component]) * MM_PER_M,
                "^",
                color="k",
                ms=7,
                label="bearing" if k == 0 else None,
            )
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


def _draw_lateral(ax, x, shape, bx, boom, k: int) -> None:
    """The two planes of a lateral mode, scaled by its largest orbit radius (and the boom's)."""
    parts = [np.asarray(shape["v"], dtype=complex).ravel(), np.asarray(shape["w"], dtype=complex).ravel()]
    if parts[0].size != x.size or parts[1].size != x.size:
        raise ValueError(f"shapes[{k}]: v and w need {x.size} values like shaft_x")
    if boom is not None:
        parts += [np.asarray(boom["v"], dtype=complex).ravel(), np.asarray(boom["w"], dtype=complex).ravel()]
    parts = _normalise(parts)
    envelope = np.hypot(np.abs(parts[0]), np.abs(parts[1]))
    ax.fill_between(x, -envelope, envelope, color="0.88", lw=0, label="shaft orbit size ±|(v, w)|")
    ax.plot(x, parts[0].real, color="C0", label="shaft v (vertical)")
    ax.plot(x, parts[1].real, color="C1", label="shaft w (lateral)")
    if boom is not None:
        ax.plot(bx, parts[2].real, color="C0", ls="--", lw=1.1, label="boom v")
        ax.plot(bx, parts[3].real, color="C1", ls="--", lw=1.1, label="boom w")


#: What a torsional or axial mode's curve is (the "along" entry of a shape).
_ALONG = {"torsional": ("C3", "shaft twist θ (torsion)"), "axial": ("C4", "shaft axial u")}


def _draw_along(ax, x, kind: str, values, k: int) -> None:
    """A torsional mode's twist or an axial mode's u along the shaft, scaled by its largest value
    and turned so that it is real."""
    if kind not in _ALONG:
        raise ValueError(f"shapes[{k}]: 'along' must be torsional or axial (got {kind!r})")
    z = np.asarray(values, dtype=complex).ravel()
    if z.size != x.size:
        raise ValueError(f"shapes[{k}]: {kind} values need {x.size} values like shaft_x")
    biggest = z[np.argmax(np.abs(z))] if z.size else 0.0
    colour, label = _ALONG[kind]
    ax.plot(x, (z / biggest).real if biggest != 0 else z.real, color=colour, label=label)


@styled
def mode_shapes_figure(
    shaft_x: ArrayLike,
    shapes: Sequence[Mapping[str, Any]],
    boom_x: ArrayLike | None = None,
    boom_shapes: Sequence[Mapping[str, Any]] | None = None,
    *,
    bearings_x: Sequence[float] = (),
    title: str | None = None,
    ax=None,
) -> Figure:
    """Small multiples of mode shapes in the two planes: v and w along shaft and boom.

    Each shape is scaled so that its largest orbit radius is 1 and its largest component is
    real (complex shapes of rotating systems are drawn at that phase); the grey envelope is
    the orbit size |(v, w)| of the shaft, so a whirling mode shows its full amplitude whatever
    its phase.

    Parameters
    ----------
    shaft_x : array_like, shape (n,)
        Shaft node positions [m].
    shapes : sequence of mapping
        One per mode, with "label" (str, e.g. "mode 3, 41.2 Hz, forward") and "v", "w"
        (array_like, shape (n,), real or complex) shaft displacements [any length unit]; a
        torsional or axial mode may carry "along": ("torsional", twist θ) or ("axial", u), each
        shape (n,): that is drawn instead (its v and w are round-off, which normalised to 1
        would look like a lateral shape).
    boom_x : array_like, optional
        Tailboom node positions [m].
    boom_shapes : sequence of mapping, optional
        Tailboom "v", "w" for each entry of ``shapes``, on the same scale as the shaft.
    bearings_x : sequence of float
        Bearing stations [m], marked ▲ on the axis.
    title : str, optional
        Figure title (when the figure is made here).
    ax : sequence of matplotlib Axes, optional
        One axes per shape.

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
    stations = vector("bearings_x", bearings_x)
    own = ax is None
    ncols = min(3, len(shapes)) if own else 1
    nrows = -(-len(shapes) // ncols) if own else len(shapes)
    top_band = 0.75 if title else 0.4
    fig, axes = new_figure(
        nrows,
        ncols,
        (4.1 * ncols, 2.5 * nrows + top_band + 0.95),
        ax=ax,
        left=0.75,
        bottom=0.95,
        top=top_band,
        hspace=0.55,
        wspace=0.45,
    )
    handles: dict[str, Any] = {}
    for k, shape in enumerate(shapes):
        ax_k = axes.flat[k]
        if "along" in shape:
            kind, values = shape["along"]
            _draw_along(ax_k, x, kind, values, k)
        else:
            _draw_lateral(ax_k, x, shape, bx, None if boom_shapes is None else boom_shapes[k], k)
        if stations.size:
            ax_k.plot(stations, np.full(stations.size, -1.12), "^", color="k", ms=6, clip_on=False, label="bearing")
        ax_k.axhline(0.0, color="0.3", lw=0.6)
        ax_k.set_ylim(-1.15, 1.15)
        ax_k.set_title(str(shape.get("label", f"mode {k + 1}")), fontsize=9)
        for handle, name in zip(*ax_k.get_legend_handles_labels()):
            handles.setdefault(name, handle)
    for ax_k in axes.flat[len(shapes) :]:
        ax_k.set_visible(False)
    for ax_k in axes[-1, :]:
        ax_k.set_xlabel("axial position x [m]")
    for ax_k in axes[:, 0]:
        ax_k.set_ylabel("normalised [-]")
    if own:
        for ax_k in axes.flat[len(shapes) - ncols : len(shapes)]:  # bottom panel of each column shows x
            ax_k.xaxis.set_tick_params(labelbottom=True)
            ax_k.set_xlabel("axial position x [m]")
        if title:
            fig.suptitle(title, fontsize=11, y=1 - 0.12 / fig.get_figheight())
        fig.legend(
            list(handles.values()),
            list(handles),
            loc="lower center",
            ncols=min(6, len(handles)),
            bbox_to_anchor=(0.5, 0.0),
            fontsize=8,
        )
    else:
        axes.flat[0].legend(loc="best", fontsize=7)
    return fig
