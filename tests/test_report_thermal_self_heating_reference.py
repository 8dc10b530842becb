"""The report's thermal results (``add_report_detail`` at the governing point) keep the
self-heating equilibrium the verdict's temperature check reads.

Documented rules (docs/thermal.md, "Self-heating equilibrium and runaway"): the baseline's
equilibrium "exists at 4800 rpm ... (Picard iterations: 1), peak 44.12 °C, margin 55.9 K to the
100 °C allowable", and "**Runaway** = an iterate exceeds the allowable temperature, i.e. no fixed
point below it". ``add_report_detail`` says the verdict's numbers do not change with the report's
detail, and the verdict re-judges the governing point with them (docs/architecture.md, "What
only the report shows is computed once, at the governing point"): so the report's thermal
results must hold that equilibrium. Checked on the embedded tuned design (its shaft and speed are
the baseline's thermal case): peak 44.12 °C to the documented rounding (0.005 K) plus the
coarser mesh (18 shaft elements: measured 44.1234 °C, 0.01 K asserted); with the allowable
temperature lowered to 43 °C, below that peak, the first iterate exceeds it: runaway.
"""

from __future__ import annotations

from flexshaft.assembly import build_model
from flexshaft.design import tuned_design, with_overrides
from flexshaft.units import celsius_to_kelvin
from flexshaft.verdict import point_tasks

MESH = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}


def test_the_report_thermal_holds_the_documented_equilibrium():
    model = build_model(with_overrides(tuned_design(), MESH))
    found = point_tasks.report_thermal(model)
    assert found.self_heating is not None and found.self_heating.status == "converged"
    assert abs(found.self_heating.max_temperature - celsius_to_kelvin(44.12)) < 0.01


def test_an_allowable_below_the_equilibrium_is_a_runaway_in_the_report():
    model = build_model(with_overrides(tuned_design(), {**MESH, "thermal.allowable_temperature_c": 43.0}))
    found = point_tasks.report_thermal(model)
    assert found.self_heating is not None and found.self_heating.status == "runaway"
