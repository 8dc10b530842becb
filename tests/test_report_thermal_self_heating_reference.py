"""The report's thermal results (``add_report_detail`` at the governing point) keep the
self-heating equilibrium and the runaway rule the verdict's temperature check reads.

Documented rules (docs/thermal.md, "Self-heating equilibrium and runaway"): the baseline's shaft
has an equilibrium at its operating speed below the 100 °C allowable, and "**Runaway** = an
iterate exceeds the allowable temperature, i.e. no fixed point below it". ``add_report_detail``
says the verdict's numbers do not change with the report's detail, and the verdict re-judges the
governing point with them (docs/architecture.md, "What only the report shows is computed once,
at the governing point"): so the report's thermal results must hold that equilibrium. Checked on
the embedded tuned design (its shaft and speed are the baseline's thermal case), bounds derived
here: the shaft only gains heat (its hysteresis heat and the sunlit boom's air, above the
ambient), so its converged peak lies above the design's ambient temperature (25.6 °C) and below
the allowable; with the allowable lowered to that ambient the first iterate already exceeds it:
runaway.
"""

from __future__ import annotations

from flexshaft.assembly import build_model
from flexshaft.design import tuned_design, with_overrides
from flexshaft.units import celsius_to_kelvin
from flexshaft.verdict import point_tasks

MESH = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}


def test_the_report_thermal_holds_the_documented_equilibrium():
    design = with_overrides(tuned_design(), MESH)
    found = point_tasks.report_thermal(build_model(design))
    assert found.self_heating is not None and found.self_heating.status == "converged"
    peak = found.self_heating.max_temperature
    assert celsius_to_kelvin(design.thermal.ambient_temperature_c) < peak
    assert peak < celsius_to_kelvin(design.thermal.allowable_temperature_c)


def test_an_allowable_at_the_ambient_is_a_runaway_in_the_report():
    ambient = tuned_design().thermal.ambient_temperature_c
    model = build_model(with_overrides(tuned_design(), {**MESH, "thermal.allowable_temperature_c": ambient}))
    found = point_tasks.report_thermal(model)
    assert found.self_heating is not None and found.self_heating.status == "runaway"
