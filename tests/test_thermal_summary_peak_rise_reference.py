"""The thermal summary's peak rise of each loss model (flexshaft.thermal.study.thermal_summary)
against the definition of the rise and the shaft's discrete heat balance.

References, derived here:

* **Definition of the rise** (definition, derived here: θ = T − T_∞, the temperature above the
  shaft's air). The peak rise is max_i T_i − T_∞, so for the design's own loss model (the
  summary's ``loss_model``; ``max_shaft_temperature_K`` without self-heating is that model's
  hottest node)::

      peak_rise_K = max_shaft_temperature_K − T_∞

  with T_∞ the unrounded air temperature of the shaft (the boom's hover skin temperature,
  :func:`flexshaft.thermal.analysis.shaft_air_temperature`, which ``thermal_results`` uses). The
  summary rounds the maximum to 1e-4 K, so the tolerance is half that step, 5e-5 K (plus 1e-9 K
  for round-off of a 317 K float, ~1e-13 K): 7 % of the baseline's 7e-4 K rise, so a rise off by
  more than that is caught, where the 0.01 °C rounding of ``air_c`` would hide it.
* **Convective balance, lower bound**: the heat leaving by convection is
  Q_c = Σ_i h π D_o ℓ_i θ_i ≤ h π D_o (Σ_i ℓ_i) θ_max, with Σ ℓ_i = the shaft length L, so
  θ_max ≥ Q_c / (h π D_o L) for each loss model (h the largest coefficient if it varies:
  ``max(element_heat_transfer)``; the baseline's D_o is uniform). On the baseline it is about
  a third of θ_max, not vacuous.
* **Discrete maximum principle, upper bound**: node i's finite-volume balance (the scheme of
  flexshaft.thermal.shaft) is Σ_j c_ij (T_j − T_i) − conv_i θ_i + s_i = 0 with conductances
  c_ij > 0, the element heat s_i = ½ (P_{i−1} + P_i) and the convecting conductance
  conv_i = ½ π D_o (h_{i−1} ℓ_{i−1} + h_i ℓ_i) (element lengths ℓ, heats P and coefficients h;
  ½ h π D_o (ℓ_{i−1} + ℓ_i) for the baseline's uniform h). Both end nodes are held at
  the air temperature (θ = 0), so the hottest node i* (θ_max > 0) is interior; there every
  T_j ≤ T_{i*}, the conduction term is ≤ 0, hence conv_{i*} θ_max ≤ s_{i*} and

      Q_c / (h π D_o L) ≤ θ_max ≤ max_i s_i / conv_i.

  Conduction along the wall is weak against convection on the baseline (c/conv ≈ 4e-4), so the
  upper bound is tight: max s_i/conv_i exceeds θ_max by 1.05e-4 (thesis loss model) and 1.09e-4
  (rotating), relative. Its allowance is round-off only, 1e-11 K: T is solved as an absolute
  317 K temperature, ε·317 K ≈ 7e-14 K per operation times the tridiagonal system's condition
  number 1.15 and a few operations, 1e-12 K; the slack is 4e-8 K.
* **Definition check**: ``peak_rise_K`` equals the largest T_i − T_∞ of that model's profile
  (the summary copies a float; max(T) − T_∞ and max(T − T_∞) differ by round-off, 1e-9
  relative). This only restates the definition; the sandwich above is the physics check.

The baseline design with a coarse mesh (12 shaft elements: all relations hold on any mesh;
CPU budget).
"""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.analysis import shaft_air_temperature, shaft_thermal
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.study import thermal_summary

#: Round-off allowance on θ [K] (module docstring).
ROUND_OFF_K = 1e-11


@pytest.fixture(scope="module")
def baseline():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    return design, fs.build_model(design)


def test_the_summary_peak_rise_is_the_hottest_node_above_the_air(baseline):
    design, model = baseline
    out = thermal_summary(design, model)
    own = out[f"shaft_{out['loss_model']}_loss_model"]
    assert out["max_shaft_temperature_source"] == "reference_properties"  # no self-heating asked
    air = shaft_air_temperature(design.tailboom, thermal_options(design.thermal))
    expected = out["max_shaft_temperature_K"] - air
    assert own["peak_rise_K"] == pytest.approx(expected, abs=5e-5 + 1e-9)  # 1e-4 K rounding / 2


def test_the_summary_peak_rise_of_each_loss_model_is_sandwiched_by_its_heat_balance(baseline):
    design, model = baseline
    options = thermal_options(design.thermal)
    out = thermal_summary(design, model)
    length = design.shaft.x_end - design.shaft.x_start
    perimeter = np.pi * design.shaft.outer_diameter
    for lm in ("thesis", "rotating"):
        numbers = out[f"shaft_{lm}_loss_model"]
        temperature = shaft_thermal(model, options, lm).temperature
        rise = np.asarray(temperature.temperature) - temperature.air_temperature
        assert rise[[0, -1]] == pytest.approx([0.0, 0.0], abs=ROUND_OFF_K)  # ends at the air
        h_elements = np.asarray(temperature.element_heat_transfer)
        lower = temperature.convected.sum() / (float(np.max(h_elements)) * perimeter * length)
        ell = np.diff(temperature.x)
        power = np.asarray(temperature.element_power)
        source = 0.5 * (power[:-1] + power[1:])  # interior nodes' heat [W]
        conv = 0.5 * perimeter * (h_elements[:-1] * ell[:-1] + h_elements[1:] * ell[1:])  # [W/K]
        upper = float(np.max(source / conv))
        assert numbers["peak_rise_K"] >= lower * (1.0 - 1e-9)
        assert numbers["peak_rise_K"] <= upper + ROUND_OFF_K
        # definition check (not physics): the summary's number is the profile's largest rise
        assert numbers["peak_rise_K"] == pytest.approx(rise.max(), rel=1e-9)
