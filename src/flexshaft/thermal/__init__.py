"""Thermal analysis of the driveline (thesis §2.8, §3.5 and beyond).

* :mod:`~flexshaft.thermal.options` — a design's ``[thermal]`` table as SI runtime objects
  (:class:`ThermalOptions`, :func:`thermal_options`, :func:`options_of`);
* :mod:`~flexshaft.thermal.tailboom` — steady tailboom skin temperature, hover and parked;
* :mod:`~flexshaft.thermal.heat` — hysteretic heat generation, thesis (fixed-frame) and
  rotating-frame loss models;
* :mod:`~flexshaft.thermal.shaft` — finite-difference shaft temperature;
* :mod:`~flexshaft.thermal.analysis` — the shaft temperature of a model;
* :mod:`~flexshaft.thermal.matrix`, :mod:`~flexshaft.thermal.selfheating` — temperature-dependent
  lamina properties (a table over temperature or the assumed law) and the self-heating fixed
  point / thermal runaway;
* :mod:`~flexshaft.thermal.envelope` — the temperatures and laminae at an operating point of a
  design's ``[envelope]`` (:func:`flexshaft.design.points.design_at_point` applies them);
* :mod:`~flexshaft.thermal.correlations`, :mod:`~flexshaft.thermal.air` — named Nusselt
  correlations with validity ranges, and air properties.

These modules take models and plain values; they never load or make designs. The thermal
study of a design (sweeps over wall thickness and convection, the report numbers,
:class:`~flexshaft.thermal.study.ThermalResults`) is :mod:`flexshaft.thermal.study`.
Importing this package imports ``ht`` and ``fluids`` (not ``import flexshaft``).
"""

from flexshaft.thermal.analysis import ShaftThermal, shaft_air_temperature, shaft_thermal
from flexshaft.thermal.envelope import PointConditions, envelope_conditions, point_conditions
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.heat import HeatSources, heat_sources
from flexshaft.thermal.matrix import LaminaTable, MatrixTemperatureLaw
from flexshaft.thermal.options import ThermalOptions, environment_from, matrix_law_from, options_of, thermal_options
from flexshaft.thermal.shaft import ShaftTemperature, solve_shaft_temperature
from flexshaft.thermal.tailboom import (
    BoomTemperature,
    boom_equivalent_diameter,
    tailboom_temperature,
    tailboom_temperatures,
)

__all__ = [
    "ThermalEnvironment",
    "ThermalOptions",
    "MatrixTemperatureLaw",
    "LaminaTable",
    "PointConditions",
    "point_conditions",
    "envelope_conditions",
    "environment_from",
    "matrix_law_from",
    "options_of",
    "thermal_options",
    "BoomTemperature",
    "boom_equivalent_diameter",
    "tailboom_temperature",
    "tailboom_temperatures",
    "HeatSources",
    "heat_sources",
    "ShaftTemperature",
    "solve_shaft_temperature",
    "ShaftThermal",
    "shaft_air_temperature",
    "shaft_thermal",
]
