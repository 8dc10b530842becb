"""A lamina's temperature table that starts exactly at the shaft's air covers the self-heating's
range (hunt h46c).

The preflight requires the table's rows to span the self-heating's range, from the shaft's air
to the allowable temperature, because a table is not extrapolated (docs/thermal.md: a closed
interval, "exact at the rows"; tests/test_temperature_table_span_edges_reference.py for the
table itself). A range that begins at the first row is spanned; one that begins half a kelvin
below it is not.

Without a tailboom the shaft's air is the ambient (``shaft_air_temperature``), so the ambient
−60 °C lands on the baseline lamina's first row (−60 °C, rows every 20 °C to 120 °C; allowable
100 °C inside) to the bit: both go through ``celsius_to_kelvin``. A few ms, no model built.
"""

from __future__ import annotations

import copy

from flexshaft.design import design_from_dict, embedded_design
from flexshaft.thermal.preflight import thermal_guards


def without_tailboom(ambient_c: float):
    data = copy.deepcopy(embedded_design("baseline").model_dump())
    data.pop("tailboom")
    data["loads"].pop("point", None)  # the boom's end mass goes with it
    data["thermal"]["ambient_temperature_c"] = ambient_c
    return design_from_dict(data)


def test_a_table_starting_at_the_air_covers_the_range():
    design = without_tailboom(-60.0)
    assert design.materials["t700_adiprene"].temperature_table.temperature_c[0] == -60.0
    assert thermal_guards(design) == []


def test_a_table_starting_above_the_air_does_not():
    problems = thermal_guards(without_tailboom(-60.5))
    assert [p.path for p in problems] == ["materials.t700_adiprene.temperature_table.temperature_c"]
