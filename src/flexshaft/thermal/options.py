"""Thermal options of a design: the ``[thermal]`` table turned into SI runtime objects.

The design package is a data-only leaf; this module is where its plain ``[thermal]`` values
(degrees Celsius and degrees at the file's edge) become the objects the thermal analyses take:

* :func:`environment_from` → :class:`~flexshaft.thermal.environment.ThermalEnvironment`;
* :func:`matrix_law_from` → :class:`~flexshaft.thermal.matrix.MatrixTemperatureLaw` (with the
  lamina's temperature table when a material with one is given);
* :func:`thermal_options` → :class:`ThermalOptions`, both of them plus the correlation choices
  and the ply conductivities;
* :func:`options_of` → the :class:`ThermalOptions` of a model's own design (the default of the
  thermal analyses that take a model, so a notebook's ``self_heating(model)`` solves with the
  design file's ``[thermal]`` table as ``flexshaft run`` does).

Each builder reads attributes only, so it takes the schema's
:class:`~flexshaft.design.thermal_schema.Thermal` or any object with the same fields.
The defaults of :class:`ThermalOptions` equal ``thermal_options(Thermal())``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from flexshaft.thermal.correlations import ForcedMethod, RotatingMethod
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.matrix import MatrixTemperatureLaw, matrix_law_for
from flexshaft.thermal.shaft import FIBRE_CONDUCTIVITY, TRANSVERSE_CONDUCTIVITY
from flexshaft.units import celsius_to_kelvin

if TYPE_CHECKING:
    from flexshaft.design.thermal_schema import Thermal

__all__ = ["ThermalOptions", "environment_from", "matrix_law_from", "options_of", "thermal_options"]

_BOOM_METHODS = ("hilpert", "churchill_bernstein")
_SHAFT_METHODS = ("becker", "kendoush")


@dataclass(frozen=True)
class ThermalOptions:
    """Everything the thermal analyses take from a design's ``[thermal]`` table (SI).

    Parameters
    ----------
    environment : ThermalEnvironment
        Radiative and convective environment of the tailboom; its ambient is the shaft's air
        when the design has no tailboom.
    boom_convection : {"hilpert", "churchill_bernstein"}
        Cross-flow correlation of the hovering tailboom (the shaft's air temperature).
    shaft_convection : {"becker", "kendoush"}
        Convection correlation of the spinning shaft.
    fibre_conductivity, transverse_conductivity : float
        Ply conductivities along and across the fibres [W/(m K)], giving the wall's axial
        conductivity.
    matrix_law : MatrixTemperatureLaw
        Temperature dependence of the matrix properties and the allowable temperature.
    """

    environment: ThermalEnvironment = field(default_factory=ThermalEnvironment)
    boom_convection: ForcedMethod = "hilpert"
    shaft_convection: RotatingMethod = "becker"
    fibre_conductivity: float = FIBRE_CONDUCTIVITY
    transverse_conductivity: float = TRANSVERSE_CONDUCTIVITY
    matrix_law: MatrixTemperatureLaw = field(default_factory=MatrixTemperatureLaw)

    def __post_init__(self) -> None:
        if self.boom_convection not in _BOOM_METHODS:
            raise ValueError(
                f"ThermalOptions.boom_convection must be one of {_BOOM_METHODS}, got {self.boom_convection!r}"
            )
        if self.shaft_convection not in _SHAFT_METHODS:
            raise ValueError(
                f"ThermalOptions.shaft_convection must be one of {_SHAFT_METHODS}, got {self.shaft_convection!r}"
            )
        for name in ("fibre_conductivity", "transverse_conductivity"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"ThermalOptions.{name} must be finite and > 0 [W/(m K)], got {value!r}")

    @property
    def allowable_temperature(self) -> float:
        """Matrix allowable temperature [K]."""
        return self.matrix_law.allowable_temperature


def environment_from(thermal: Thermal) -> ThermalEnvironment:
    """The :class:`ThermalEnvironment` of a ``[thermal]`` table (°C and degrees → K and rad)."""
    return ThermalEnvironment(
        rotorcraft_mass=thermal.rotorcraft_mass,
        rotor_radius=thermal.rotor_radius,
        emissivity=thermal.emissivity,
        solar_absorptivity=thermal.solar_absorptivity,
        solar_constant=thermal.solar_constant,
        solar_fraction=thermal.solar_fraction,
        solar_zenith=math.radians(thermal.solar_zenith_deg),
        sky_temperature=celsius_to_kelvin(thermal.sky_temperature_c),
        air_density=thermal.air_density,
        ambient_temperature=celsius_to_kelvin(thermal.ambient_temperature_c),
        solar_area_fraction=thermal.solar_area_fraction,
    )


def matrix_law_from(thermal: Thermal, material=None) -> MatrixTemperatureLaw:
    """The :class:`MatrixTemperatureLaw` of a ``[thermal]`` table (°C → K).

    ``material``: a design-file material whose ``temperature_table``, when it has one,
    replaces the law (:func:`~flexshaft.thermal.matrix.matrix_law_for`).
    """
    law = MatrixTemperatureLaw(
        reference_temperature=celsius_to_kelvin(thermal.matrix_reference_temperature_c),
        modulus_decay=thermal.matrix_modulus_decay,
        loss_growth=thermal.matrix_loss_growth,
        allowable_temperature=celsius_to_kelvin(thermal.allowable_temperature_c),
    )
    return matrix_law_for(material, law)


def thermal_options(thermal: Thermal, material=None) -> ThermalOptions:
    """The :class:`ThermalOptions` of a ``[thermal]`` table: every field of it, in SI.

    ``material``: the shaft's design-file material, whose temperature table (if any) the
    matrix law then carries (:func:`matrix_law_from`). The self-heating analysis attaches the
    table of each element's own lamina in any case.
    """
    return ThermalOptions(
        environment=environment_from(thermal),
        boom_convection=thermal.boom_convection,
        shaft_convection=thermal.shaft_convection,
        fibre_conductivity=thermal.fibre_conductivity,
        transverse_conductivity=thermal.transverse_conductivity,
        matrix_law=matrix_law_from(thermal, material),
    )


def options_of(model) -> ThermalOptions:
    """The :class:`ThermalOptions` of ``model``'s own design file (its ``[thermal]`` table), or
    the defaults (the baseline's) for a model built without a design."""
    design = getattr(model, "design", None)
    return ThermalOptions() if design is None else thermal_options(design.thermal)
