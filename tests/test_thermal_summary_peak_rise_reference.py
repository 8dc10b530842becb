"""The thermal summary's peak rise of each loss model (flexshaft.thermal.study.thermal_summary)
against the definition of the rise and the shaft's convective heat balance.

References, derived here:

* **Definition of the rise** (thesis §2.8.2: θ = T − T_∞, the temperature above the shaft's
  air). The peak rise is max_i T_i − T_∞, so for the design's own loss model (the summary's
  ``max_shaft_temperature_K`` without self-heating is that model's hottest node)::

      peak_rise_K = max_shaft_temperature_K − (air_c + 273.15)

  (SI brochure: T/K = t/°C + 273.15). The summary rounds the air to 0.01 °C and the maximum to
  1e-4 K, so the tolerance is 0.006 K. The baseline's rise is below 1 mK, so this relation
  only tells the rise from an absolute temperature (≈ 290 K); the next one pins it.
* **Convective balance bound**: the heat leaving by convection is Q_c = Σ_i h π D_o ℓ_i θ_i
  ≤ h π D_o (Σ_i ℓ_i) θ_max, with Σ ℓ_i = the shaft length L, so θ_max ≥ Q_c / (h π D_o L)
  for each loss model (h the largest coefficient if it varies; the baseline's D_o is uniform),
  and θ_max equals the largest T_i − T_∞ of that model's profile (the summary copies a float:
  round-off, 1e-9). On the baseline the bound is about a third of θ_max, not vacuous.

The baseline design with a coarse mesh (12 shaft elements: both relations hold on any mesh;
CPU budget).
"""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.analysis import shaft_thermal
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.study import thermal_summary


@pytest.fixture(scope="module")
def baseline():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    return design, fs.build_model(design)


def test_the_summary_peak_rise_is_the_hottest_node_above_the_air(baseline):
    design, model = baseline
    out = thermal_summary(design, model)
    own = out[f"shaft_{design.analysis.internal_damping}_loss_model"]
    assert out["max_shaft_temperature_source"] == "reference_properties"  # no self-heating asked
    expected = out["max_shaft_temperature_K"] - (own["air_c"] + 273.15)
    assert own["peak_rise_K"] == pytest.approx(expected, abs=6e-3)


def test_the_summary_peak_rise_of_each_loss_model_bounds_its_convected_heat(baseline):
    design, model = baseline
    options = thermal_options(design.thermal)
    out = thermal_summary(design, model)
    length = design.shaft.x_end - design.shaft.x_start
    outer = design.shaft.outer_diameter
    for lm in ("thesis", "rotating"):
        numbers = out[f"shaft_{lm}_loss_model"]
        temperature = shaft_thermal(model, options, lm).temperature
        rise = np.asarray(temperature.temperature) - temperature.air_temperature
        h = float(np.max(temperature.heat_transfer_coefficient))
        bound = temperature.convected.sum() / (h * np.pi * outer * length)
        assert numbers["peak_rise_K"] >= bound * (1.0 - 1e-9)
        assert numbers["peak_rise_K"] == pytest.approx(rise.max(), rel=1e-9)
