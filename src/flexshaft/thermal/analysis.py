"""Shaft temperature of a design: heat sources → finite-difference temperature, and the
thesis's thermal-design sweeps (wall thickness, convection coefficient; figs. 3.18, 3.19).

The shaft runs inside the boom fairing: its air and both ends are at the boom's hover skin
temperature (the thesis sets the driveline's operating ambient to the boom's 44 °C), unless an
air temperature is given.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.assembly.model import Model
from flexshaft.thermal.correlations import Nusselt, RotatingMethod
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.heat import HeatSources, LossModel, heat_sources
from flexshaft.thermal.shaft import (
    FIBRE_CONDUCTIVITY, TRANSVERSE_CONDUCTIVITY, ShaftTemperature, laminate_axial_conductivity,
    rotating_shaft_convection, solve_shaft_temperature,
)

__all__ = ["ShaftThermal", "shaft_air_temperature", "shaft_conductivity", "shaft_thermal",
           "wall_thickness_sweep", "convection_sweep"]


@dataclass(frozen=True)
class ShaftThermal:
    """Heat sources and the steady temperature of the shaft.

    Attributes
    ----------
    sources : HeatSources
        Heat per element [W] by mechanism.
    temperature : ShaftTemperature
        Node temperatures and energy balance.
    nusselt : Nusselt or None
        Rotating-cylinder correlation used (None when h was given).
    conductivity : float
        Axial wall conductivity [W/(m K)].
    """

    sources: HeatSources
    temperature: ShaftTemperature
    nusselt: Nusselt | None
    conductivity: float

    @property
    def peak_rise(self) -> float:
        """Peak shaft temperature above its air [K]."""
        return self.temperature.peak_rise


def shaft_air_temperature(design, env: ThermalEnvironment | None = None) -> float:
    """Air (and end) temperature of the shaft [K]: the boom's hover skin temperature, or the
    ambient when the design has no tailboom."""
    env = env or ThermalEnvironment()
    if design is None or design.tailboom is None:
        return env.ambient_temperature
    from flexshaft.thermal.tailboom import boom_equivalent_diameter, tailboom_temperature

    return tailboom_temperature("hover", boom_equivalent_diameter(design.tailboom), env).temperature


def shaft_conductivity(model: Model, k_L: float = FIBRE_CONDUCTIVITY, k_T: float = TRANSVERSE_CONDUCTIVITY,
                       isotropic: float = 167.0) -> float:
    """Axial wall conductivity [W/(m K)]: laminate rule, or ``isotropic`` (6061-T6: 167) for a
    metal shaft."""
    lam = model.shaft.laminate
    return isotropic if lam is None else laminate_axial_conductivity(lam, k_L, k_T)


def shaft_thermal(
    model: Model, env: ThermalEnvironment | None = None, loss_model: LossModel = "thesis", *,
    air_temperature: float | None = None, heat_transfer_coefficient: float | None = None,
    convection: RotatingMethod = "becker", conductivity: float | None = None,
    sources: HeatSources | None = None,
) -> ShaftThermal:
    """Steady temperature along the shaft at the model's operating speed.

    Parameters
    ----------
    model : Model
        Assembled model (heat from its imbalance response and static deflection).
    env : ThermalEnvironment
        Environment for the boom temperature (thesis defaults).
    loss_model : {"thesis", "rotating"}
        Heat-generation model (:mod:`flexshaft.thermal.heat`).
    air_temperature : float, optional
        T_∞ and end temperature [K]; default the boom's hover temperature.
    heat_transfer_coefficient : float, optional
        h [W/(m^2 K)]; default from the rotating-cylinder ``convection`` correlation.
    conductivity : float, optional
        Axial wall conductivity [W/(m K)]; default :func:`shaft_conductivity`.
    sources : HeatSources, optional
        Precomputed heat sources (e.g. from per-element properties).
    """
    T_air = shaft_air_temperature(model.design, env) if air_temperature is None else float(air_temperature)
    Do, Di = model.shaft.outer_diameter, model.shaft.inner_diameter
    nusselt = None
    if heat_transfer_coefficient is None:
        heat_transfer_coefficient, nusselt = rotating_shaft_convection(Do, model.speed, T_air, convection)
    k = shaft_conductivity(model) if conductivity is None else float(conductivity)
    sources = sources or heat_sources(model, loss_model)
    temp = solve_shaft_temperature(sources.x, sources.total, k, np.pi * (Do**2 - Di**2) / 4, np.pi * Do,
                                   heat_transfer_coefficient, T_air, (T_air, T_air))
    return ShaftThermal(sources, temp, nusselt, k)


def wall_thickness_sweep(design, thicknesses, env: ThermalEnvironment | None = None,
                         loss_model: LossModel = "thesis", **kwargs) -> dict[str, np.ndarray]:
    """Peak temperature rise [K] and total heat [W] against wall thickness [m] at fixed D_o
    (thesis fig. 3.18)."""
    from flexshaft.assembly import build_model
    from flexshaft.design import with_overrides

    T_air = kwargs.pop("air_temperature", None) or shaft_air_temperature(design, env)
    rise, heat = [], []
    for t in np.atleast_1d(thicknesses):
        r = shaft_thermal(build_model(with_overrides(design, {"shaft.wall_thickness": float(t)})), env, loss_model,
                          air_temperature=T_air, **kwargs)
        rise.append(r.peak_rise)
        heat.append(r.sources.total.sum())
    return {"wall_thickness": np.atleast_1d(np.asarray(thicknesses, dtype=float)), "peak_rise": np.array(rise),
            "heat": np.array(heat)}


def convection_sweep(model: Model, coefficients, env: ThermalEnvironment | None = None,
                     loss_model: LossModel = "thesis", **kwargs) -> dict[str, np.ndarray]:
    """Peak temperature rise [K] against the convection coefficient h [W/(m^2 K)] (thesis
    fig. 3.19); the heat sources are computed once."""
    sources = heat_sources(model, loss_model)
    T_air = kwargs.pop("air_temperature", None) or shaft_air_temperature(model.design, env)
    rise = [shaft_thermal(model, env, loss_model, air_temperature=T_air, heat_transfer_coefficient=float(h),
                          sources=sources, **kwargs).peak_rise for h in np.atleast_1d(coefficients)]
    return {"heat_transfer_coefficient": np.atleast_1d(np.asarray(coefficients, dtype=float)), "peak_rise": np.array(rise)}
