"""Thermal analysis of the driveline (thesis §2.8, §3.5 and beyond).

* :mod:`~flexshaft.thermal.tailboom` — steady tailboom skin temperature, hover and parked;
* :mod:`~flexshaft.thermal.heat` — hysteretic heat generation, thesis (fixed-frame) and
  rotating-frame loss models;
* :mod:`~flexshaft.thermal.shaft` — finite-difference shaft temperature;
* :mod:`~flexshaft.thermal.analysis` — the shaft temperature of a design and the sweeps;
* :mod:`~flexshaft.thermal.selfheating` — temperature-dependent lamina properties and the
  self-heating fixed point / thermal runaway;
* :mod:`~flexshaft.thermal.correlations`, :mod:`~flexshaft.thermal.air` — named Nusselt
  correlations with validity ranges, and air properties.

Importing this package imports ``ht`` and ``fluids`` (not ``import flexshaft``).
"""

from flexshaft.thermal.analysis import ShaftThermal, convection_sweep, shaft_thermal, wall_thickness_sweep
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.heat import HeatSources, heat_sources
from flexshaft.thermal.shaft import ShaftTemperature, solve_shaft_temperature
from flexshaft.thermal.tailboom import BoomTemperature, tailboom_temperature, tailboom_temperatures

__all__ = [
    "ThermalEnvironment", "BoomTemperature", "tailboom_temperature", "tailboom_temperatures",
    "HeatSources", "heat_sources", "ShaftTemperature", "solve_shaft_temperature", "ShaftThermal",
    "shaft_thermal", "wall_thickness_sweep", "convection_sweep",
]
