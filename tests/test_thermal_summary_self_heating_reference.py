"""The thermal summary (what ``flexshaft thermal --self-heating`` prints) with the self-heating
equilibrium asked for.

Documented rules (docs/thermal.md, "Numbers for a verdict" and the CLI line): with
``--self-heating`` the peak shaft temperature is the self-heating equilibrium's and
``max_shaft_temperature_source`` says which; the command reports the self-heating margin. The
margin is the allowable temperature less the peak, and the allowable is the design's
``[thermal] allowable_temperature_c`` on the kelvin scale (SI brochure: T/K = t/°C + 273.15).

Physics, derived here: the equilibrium's heat sources are non-negative (dissipation) and the
shaft's ends are held at the air, so by the maximum principle of the conduction-convection
equation its peak is at or above the air temperature; the baseline's peak rise is small (the
docs quote 44.12 °C in hover against a 100 °C allowable), so the margin is positive.

Tolerances: the summary rounds K values to 1e-4 and the margin to 1e-3, so the margin identity
holds to 1e-3 + 1e-4 (asserted 2e-3); the °C/K identity to the rounding 1e-4 each (asserted 1e-3).

The baseline design on a coarse mesh (12 shaft elements, 6 boom elements: the CPU budget; the
statements hold on any mesh).
"""

from __future__ import annotations

import pytest

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.study import thermal_summary


@pytest.fixture(scope="module")
def summary():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    return design, thermal_summary(design, fs.build_model(design), self_heat=True)


def test_the_self_heating_summary_reads_the_equilibrium(summary):
    _, out = summary
    assert out["max_shaft_temperature_source"] == "self_heating"
    sh = out["self_heating"]
    assert sh["status"] == "converged"
    assert sh["iterations"] >= 1


def test_the_self_heating_margin_is_the_allowable_less_the_equilibrium_peak(summary):
    design, out = summary
    allowable_K = design.thermal.allowable_temperature_c + 273.15
    assert out["allowable_temperature_c"] == pytest.approx(design.thermal.allowable_temperature_c, abs=1e-3)
    peak_K = out["max_shaft_temperature_K"]
    assert out["self_heating"]["margin_K"] == pytest.approx(allowable_K - peak_K, abs=2e-3)
    assert out["temperature_margin_K"] == pytest.approx(allowable_K - peak_K, abs=1e-3)
    air_c = out["shaft_thesis_loss_model"]["air_c"]
    assert out["max_shaft_temperature_c"] >= air_c - 6e-3  # maximum principle (air_c rounded to 0.01)
    assert out["self_heating"]["margin_K"] > 0.0
