"""Figures of the thermal analysis (matplotlib imported lazily)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import new_figure, styled, vector

__all__ = ["shaft_temperature_figure", "temperature_profiles_figure"]


@styled
def shaft_temperature_figure(
    x_nodes: ArrayLike,
    rise: Mapping[str, ArrayLike],
    x_elements: ArrayLike,
    heat_per_length: Mapping[str, ArrayLike],
    *,
    ax=None,
):
    """Temperature rise above the air along the shaft [K] and the heat generated [W/m], one
    curve per loss model (``ax``: two axes)."""
    x = vector("x_nodes", x_nodes)
    xe = vector("x_elements", x_elements)
    fig, axes = new_figure(2, 1, (8.0, 6.0), sharex=True, ax=ax, hspace=0.3)
    for name, values in rise.items():
        axes[0, 0].plot(x, np.asarray(values, dtype=float), label=name)
    axes[0, 0].set_ylabel("T − T_air [K]")
    axes[0, 0].set_title("Shaft temperature rise")
    axes[0, 0].legend(loc="best")
    for name, values in heat_per_length.items():
        axes[1, 0].step(xe, np.asarray(values, dtype=float), where="mid", label=name)
    axes[1, 0].set_ylabel("heat generated [W/m]")
    axes[1, 0].set_xlabel("axial position x [m]")
    axes[1, 0].legend(loc="best")
    return fig


@styled
def temperature_profiles_figure(
    x_nodes: ArrayLike, by_wall: Mapping[str, ArrayLike], by_h: Mapping[str, ArrayLike], *, ax=None
):
    """Shaft temperature rise along x [K] for several wall thicknesses and several convection
    coefficients (thesis figures 3.18 and 3.19; ``ax``: two axes)."""
    x = vector("x_nodes", x_nodes)
    fig, axes = new_figure(1, 2, (11.0, 4.2), sharex=False, ax=ax, wspace=0.8)
    for a, curves, title in (
        (axes[0, 0], by_wall, "wall thickness (fixed D_o)"),
        (axes[0, 1], by_h, "convection coefficient"),
    ):
        for name, values in curves.items():
            v = np.asarray(values, dtype=float)
            a.plot(np.linspace(x[0], x[-1], v.size) if v.size != x.size else x, v, label=name)
        a.set_title(f"Temperature profile vs {title}", fontsize=10)
        a.set_xlabel("x [m]")
        a.set_ylabel("T − T_air [K]")
        a.legend(loc="best")
    return fig
