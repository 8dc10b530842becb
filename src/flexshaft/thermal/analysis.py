"""Shaft temperature of a model: heat sources → finite-difference temperature.

The shaft runs inside the boom fairing: its air and both ends are at the boom's hover skin
temperature (the thesis sets the driveline's operating ambient to the boom's 44 °C), or at the
ambient when the design has no tailboom, unless an air temperature is given. Sweeps over other
designs (wall thickness, convection) live in :mod:`flexshaft.thermal.study`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.assembly.model import Model
from flexshaft.thermal.correlations import Nusselt
from flexshaft.thermal.heat import HeatSources, LossModel, element_tubes, heat_sources
from flexshaft.thermal.options import ThermalOptions, options_of
from flexshaft.thermal.shaft import (
    ShaftTemperature,
    laminate_axial_conductivity,
    rotating_shaft_convection,
    solve_shaft_temperature,
)
from flexshaft.thermal.tailboom import boom_equivalent_diameter, tailboom_temperature
from flexshaft.units import kelvin_to_celsius

__all__ = [
    "ShaftThermal",
    "ISOTROPIC_SHAFT_CONDUCTIVITY",
    "shaft_air_temperature",
    "shaft_conductivity",
    "shaft_thermal",
]

#: Conductivity of an isotropic (6061-T6 aluminium) shaft [W/(m K)], handbook value.
ISOTROPIC_SHAFT_CONDUCTIVITY = 167.0


@dataclass(frozen=True)
class ShaftThermal:
    """Heat sources and the steady temperature of the shaft.

    Attributes
    ----------
    sources : HeatSources
        Heat per element [W] by mechanism (and the loss model used).
    temperature : ShaftTemperature
        Node temperatures and energy balance.
    nusselt : Nusselt or None
        Rotating-cylinder correlation used (None when h was given; of the diameter covering the
        most length when a segmented shaft's tubes differ).
    conductivity : float or ndarray
        Axial wall conductivity [W/(m K)]; one per element (nel,) when a segmented shaft's tubes
        differ.
    """

    sources: HeatSources
    temperature: ShaftTemperature
    nusselt: Nusselt | None
    conductivity: float | np.ndarray

    @property
    def peak_rise(self) -> float:
        """Peak shaft temperature above its air [K]."""
        return self.temperature.peak_rise

    @property
    def max_temperature(self) -> float:
        """Maximum shaft temperature [K]."""
        return float(self.temperature.temperature.max())

    @property
    def max_temperature_c(self) -> float:
        """Maximum shaft temperature [°C]."""
        return kelvin_to_celsius(self.max_temperature)


def shaft_air_temperature(tailboom, options: ThermalOptions | None = None) -> float:
    """Air (and end) temperature of the shaft [K]: the boom's hover skin temperature with the
    options' hover correlation, or the ambient when ``tailboom`` is None.

    Parameters
    ----------
    tailboom : design tailboom table or None
        ``root_semi_axes``, ``tip_semi_axes``, ``wall_thickness`` [m]
        (:func:`~flexshaft.thermal.tailboom.boom_equivalent_diameter`).
    options : ThermalOptions
        Environment and boom correlation (default: the baseline's).
    """
    options = options or ThermalOptions()
    if tailboom is None:
        return options.environment.ambient_temperature
    hover = tailboom_temperature(
        "hover", boom_equivalent_diameter(tailboom), options.environment, options.boom_convection
    )
    return hover.temperature


def shaft_conductivity(
    model: Model, options: ThermalOptions | None = None, isotropic: float = ISOTROPIC_SHAFT_CONDUCTIVITY
) -> float | np.ndarray:
    """Axial wall conductivity [W/(m K)]: the laminate rule with the options' ply
    conductivities, or ``isotropic`` for a metal shaft; one value per element (nel,) when the
    tubes of a segmented shaft differ in it."""
    options = options or options_of(model)
    values = {}
    for tube in element_tubes(model):
        if id(tube) not in values:
            lam = tube.laminate
            values[id(tube)] = (
                isotropic
                if lam is None
                else laminate_axial_conductivity(lam, options.fibre_conductivity, options.transverse_conductivity)
            )
    per_element = np.array([values[id(t)] for t in element_tubes(model)])
    return float(per_element[0]) if np.all(per_element == per_element[0]) else per_element


def shaft_thermal(
    model: Model,
    options: ThermalOptions | None = None,
    loss_model: LossModel | None = None,
    *,
    air_temperature: float | None = None,
    heat_transfer_coefficient: float | None = None,
    conductivity: float | None = None,
    sources: HeatSources | None = None,
) -> ShaftThermal:
    """Steady temperature along the shaft at the model's operating speed.

    Parameters
    ----------
    model : Model
        Assembled model (heat from its imbalance response and static deflection).
    options : ThermalOptions
        Environment, correlations and ply conductivities (default: the model's design's
        ``[thermal]`` table, :func:`~flexshaft.thermal.options.options_of`); build them from a
        design with :func:`flexshaft.thermal.options.thermal_options`.
    loss_model : {"thesis", "rotating"} or None
        Heat-generation model (:mod:`flexshaft.thermal.heat`); None: the design's
        ``[analysis] internal_damping``.
    air_temperature : float, optional
        T_∞ and end temperature [K]; default :func:`shaft_air_temperature`.
    heat_transfer_coefficient : float, optional
        h [W/(m^2 K)]; default from the options' rotating-cylinder correlation.
    conductivity : float, optional
        Axial wall conductivity [W/(m K)]; default :func:`shaft_conductivity`.
    sources : HeatSources, optional
        Precomputed heat sources (e.g. from per-element properties).
    """
    options = options or options_of(model)
    tailboom = None if model.design is None else model.design.tailboom
    T_air = shaft_air_temperature(tailboom, options) if air_temperature is None else float(air_temperature)
    tubes = element_tubes(model)
    Do = np.array([t.outer_diameter for t in tubes])
    Di = np.array([t.inner_diameter for t in tubes])
    nusselt = None
    h: float | np.ndarray
    if heat_transfer_coefficient is None:
        ends = model.dofs.shaft_element_x
        lengths = ends[:, 1] - ends[:, 0]
        diameters, inverse = np.unique(Do, return_inverse=True)
        convection = [
            rotating_shaft_convection(D, model.speed, T_air, options.shaft_convection, options.environment.air_pressure)
            for D in diameters
        ]
        h = np.array([coefficient for coefficient, _ in convection])[inverse.ravel()]
        covered = np.bincount(inverse.ravel(), weights=lengths, minlength=diameters.size)
        nusselt = convection[int(np.argmax(covered))][1]
    else:
        h = heat_transfer_coefficient
    k = shaft_conductivity(model, options) if conductivity is None else float(conductivity)
    sources = sources or heat_sources(model, loss_model)
    temp = solve_shaft_temperature(
        sources.x, sources.total, k, np.pi * (Do**2 - Di**2) / 4, np.pi * Do, h, T_air, (T_air, T_air)
    )
    return ShaftThermal(sources, temp, nusselt, k)
