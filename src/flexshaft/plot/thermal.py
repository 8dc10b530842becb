"""Figures of the thermal analysis (matplotlib imported lazily)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import new_figure, styled, vector
from flexshaft.units import kelvin_to_celsius

__all__ = ["shaft_temperature_check_figure", "shaft_temperature_figure", "temperature_profiles_figure"]


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


@styled
def shaft_temperature_check_figure(
    x_nodes: ArrayLike,
    rise: Mapping[str, ArrayLike],
    x_elements: ArrayLike,
    heat_per_length: Mapping[str, ArrayLike],
    *,
    temperature: tuple[ArrayLike, ArrayLike],
    checked: float,
    allowable: float | None = None,
    material_temperature: float | None = None,
    point: str = "",
    ax=None,
):
    """What the temperature check reads above :func:`shaft_temperature_figure`'s two panels
    (``ax``: three axes): the shaft temperature [°C] along x of the self-heating equilibrium
    ``temperature`` = (x [m], T [K]), the point's material temperature [K] (a hot-soaked start
    begins hotter than its running equilibrium: the check then reads it), the ``checked`` value
    [K] and the ``allowable`` [K] (dashed), at operating point ``point``."""
    xt = vector("temperature x", temperature[0])
    celsius = kelvin_to_celsius(vector("temperature", temperature[1]))
    if celsius.size != xt.size:
        raise ValueError(f"temperature: {xt.size} stations but {celsius.size} temperatures")
    fig, axes = new_figure(3, 1, (8.0, 8.8), sharex=True, ax=ax, hspace=0.3)
    shaft_temperature_figure(x_nodes, rise, x_elements, heat_per_length, ax=[axes[1, 0], axes[2, 0]])
    top = axes[0, 0]
    top.plot(xt, celsius, color="k", lw=1.5, label="self-heating equilibrium")
    for value, color, ls, name in (
        (material_temperature, "tab:purple", "-.", "material temperature of the point"),
        (allowable, "tab:red", "--", "allowable"),
    ):
        if value is not None:
            top.axhline(
                kelvin_to_celsius(value), color=color, ls=ls, lw=1.2, label=f"{name} {kelvin_to_celsius(value):.1f} °C"
            )
    top.text(
        0.01,
        0.04,
        f"checked {kelvin_to_celsius(checked):.1f} °C"
        + ("" if allowable is None else f" ≤ {kelvin_to_celsius(allowable):.1f} °C"),
        transform=top.transAxes,
        fontsize=8,
        va="bottom",
        bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.8", "alpha": 0.85},
    )
    lo = min(float(celsius.min()), kelvin_to_celsius(checked))
    hi = max(
        float(celsius.max()),
        kelvin_to_celsius(checked),
        kelvin_to_celsius(allowable) if allowable is not None else -np.inf,
    )
    pad = 0.12 * max(hi - lo, 1.0)
    top.set_ylim(lo - 2.0 * pad, hi + pad)  # room for the note below the curves
    top.set_ylabel("shaft temperature [°C]")
    top.set_title("Shaft temperature the check reads" + (f" ({point})" if point else ""))
    top.legend(loc="center right", fontsize=7.5)
    return fig
