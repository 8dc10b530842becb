"""The thermal summary's air temperature in degrees Celsius, and the shaft profile the verdict
reads once the self-heating equilibrium is computed.

* Celsius scale (SI brochure): t/°C = T/K − 273.15. The shaft's air (and end) temperature is the
  tailboom's hover skin temperature (:func:`flexshaft.thermal.analysis.shaft_air_temperature`,
  its docstring); ``air_c`` of each loss model's numbers is that temperature in °C, rounded to
  0.01 (so 0.006 K asserted). A temperature left in kelvin is 273 off.
* :attr:`flexshaft.thermal.study.ThermalResults.shaft_temperature` is the self-heating
  equilibrium's profile when it was computed (its docstring): the peak of that profile is the
  peak shaft temperature the results report (a profile's peak is its largest node value; exact).

The baseline design on a coarse mesh (12 shaft elements, 6 boom elements: the CPU budget; both
statements hold on any mesh).
"""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.analysis import shaft_air_temperature
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.study import thermal_results, thermal_summary


@pytest.fixture(scope="module")
def baseline():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    return design, fs.build_model(design)


def test_the_air_temperature_is_reported_in_celsius(baseline):
    design, model = baseline
    air_K = shaft_air_temperature(design.tailboom, thermal_options(design.thermal))
    out = thermal_summary(design, model)
    for lm in ("thesis", "rotating"):
        assert out[f"shaft_{lm}_loss_model"]["air_c"] == pytest.approx(air_K - 273.15, abs=6e-3)


def test_the_profile_read_after_self_heating_is_the_equilibrium_one(baseline):
    design, model = baseline
    r = thermal_results(design, model, self_heat=True, detail=False)
    assert r.max_shaft_temperature_source == "self_heating"
    assert float(np.max(r.shaft_temperature.temperature)) == r.max_shaft_temperature
