"""The thermal summary (what ``flexshaft thermal --self-heating`` prints) with the self-heating
equilibrium asked for.

Documented rules, docs/thermal.md: the CLI line documents the ``--self-heating`` flag, and
"Numbers for a verdict" (lines 362-366) says `thermal_results(design, model, self_heat=True)`'s
"`max_shaft_temperature` [K] and `max_shaft_temperature_c` [°C] (the self-heating
equilibrium's peak, or the reference-property peak without self-heating;
`max_shaft_temperature_source` says which)", with `allowable_temperature_c` and
`temperature_margin` [K]. The baseline's "peak 44.12 °C, margin 55.9 K to the 100 °C allowable"
(same page) reads the margin as the allowable less the peak; the allowable is the design's
``[thermal] allowable_temperature_c`` on the kelvin scale (SI brochure: T/K = t/°C + 273.15).
The summary's ``self_heating`` block (status, iterations, margin) and its ``"converged"``
status are the code's own labels (``SelfHeating.status``), not a documented wording.

Physics, derived here: the equilibrium's heat sources are non-negative (dissipation) and the
shaft's ends are held at the air, so by the minimum principle of the conduction-convection
equation -k A θ'' + h P θ = q ≥ 0 with θ = 0 at the ends, the rise θ = T - T_air is nowhere
negative: the peak is at or above the air; the baseline's peak rise is small (44.12 °C against
the 100 °C allowable above), so the margin is positive.

On the baseline the equilibrium's peak and the reference-property peak differ by 5.6e-5 K
(measured here), under the summary's 1e-4 K rounding: there only the source label and the
``self_heating`` block tell the two apart. A vertical load factor of -35 (the static bending
heat) raises the peak rise to about 0.05 K, and the equilibrium's peak (2 Picard iterations)
lies 4.1 mK below the reference-property one (measured here): more than ten roundings, so the
summary's peak must be the equilibrium's and not the reference-property one.

Tolerances: the summary rounds K values to 1e-4 and the margin to 1e-3, so the margin identity
holds to 1e-3 + 1e-4 (asserted 2e-3); the °C/K identity to the rounding 1e-4 each (asserted 1e-3);
the summary's peak against a second self-heating run of the same inputs to the rounding 1e-4
(the iteration is deterministic). The minimum principle is checked on unrounded node
temperatures (rise 6.6e-4 K on the baseline) to 1e-9 K: node temperatures of ~317 K carry
round-off ~1e-13 K per operation, amplified by the condition number of a 13-node
conduction-convection system (~1e2).

The baseline design on a coarse mesh (12 shaft elements, 6 boom elements: the CPU budget; the
statements hold on any mesh).
"""

from __future__ import annotations

import pytest

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.selfheating import self_heating
from flexshaft.thermal.study import thermal_results, thermal_summary

COARSE = {"mesh.shaft_elements": 12, "mesh.boom_elements": 6}
SUMMARY_ROUNDING_K = 1e-4


@pytest.fixture(scope="module")
def baseline():
    design = with_overrides(fs.baseline_design(), COARSE)
    return design, fs.build_model(design)


@pytest.fixture(scope="module")
def summary(baseline):
    design, model = baseline
    return design, thermal_summary(design, model, self_heat=True)


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
    assert out["max_shaft_temperature_c"] == pytest.approx(peak_K - 273.15, abs=1e-3)
    assert out["self_heating"]["margin_K"] == pytest.approx(allowable_K - peak_K, abs=2e-3)
    assert out["temperature_margin_K"] == pytest.approx(allowable_K - peak_K, abs=1e-3)
    assert out["self_heating"]["margin_K"] > 0.0


def test_the_equilibrium_is_nowhere_below_the_air(baseline):
    design, model = baseline
    r = thermal_results(design, model, self_heat=True)
    T = r.shaft_temperature
    assert T is r.self_heating.thermal.temperature
    assert T.temperature.min() >= T.air_temperature - 1e-9  # minimum principle, unrounded
    assert r.max_shaft_temperature > T.air_temperature  # positive dissipation somewhere


def test_the_summary_peak_is_the_equilibrium_s_not_the_reference_property_one():
    design = with_overrides(fs.baseline_design(), {**COARSE, "loads.load_factor": [0.0, -35.0, 0.0]})
    model = fs.build_model(design)
    out = thermal_summary(design, model, self_heat=True)
    equilibrium_K = self_heating(model, thermal_options(design.thermal)).max_temperature
    reference_K = thermal_results(design, model).max_shaft_temperature
    assert abs(equilibrium_K - reference_K) > 10 * SUMMARY_ROUNDING_K  # the two are told apart
    assert out["max_shaft_temperature_K"] == pytest.approx(equilibrium_K, abs=SUMMARY_ROUNDING_K)
    assert out["max_shaft_temperature_source"] == "self_heating"
