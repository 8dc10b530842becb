"""A lamina's temperature table that ends exactly at the allowable temperature covers the
self-heating's range.

The rule (docs/thermal.md, the temperature table's validation): the table "must ... reach
``allowable_temperature_c`` (the self-heating analysis evaluates the lamina up to it)", and the
``[thermal]`` note: it "must then cover the shaft's air to the allowable". Reaching is a closed
bound: the schema accepts a last row equal to the allowable (``high >= allowable_c``), and a
table is exact at its rows, so the preflight must accept it too; otherwise no design whose table
ends at the allowable, the smallest table the schema asks for, could run.

Worked on the embedded baseline (lamina t700_adiprene, E_L = 115 GPa, ν_LT = 0.35, its table
E_T(T) = 0.1 GPa e^{−(T − 20 °C)/40 K} at rows every 20 °C from −60 to 120 °C; the shaft's air
317.27 K = 44.12 °C, below the allowable):

* allowable 120 °C, the table's last row: the range 44.12-120 °C lies within −60-120 °C (both
  ends go through ``celsius_to_kelvin``, so the bound is met to the bit); the ply at the end
  has ν_LT² E_T/E_L = 0.1225 · 0.1e9 e^{−2.5}/115e9 = 8.7e-6 < 1, valid (the plane-stress
  condition of tests/test_preflight_tabled_lamina_reference.py), and E_T only falls from the air
  up, so nothing is refused;
* the same with the 120 °C row dropped and the allowable back at 100 °C, the new last row.

The schema itself refuses a table ending below the allowable, so the contrast (a range reaching
past the last row) is the cold end's, tested in tests/test_preflight_table_at_the_air_reference.py.
A few ms each, no model built.
"""

from __future__ import annotations

import copy
import math

from flexshaft.design import design_from_dict, embedded_design
from flexshaft.thermal.preflight import thermal_guards

E_L, E_T, NU_LT = 115e9, 0.1e9, 0.35


def baseline_data() -> dict:
    return copy.deepcopy(embedded_design("baseline").model_dump())


def test_the_hand_numbers():
    design = embedded_design("baseline")
    lamina = design.materials["t700_adiprene"]
    assert (lamina.E_L, lamina.E_T, lamina.nu_LT) == (E_L, E_T, NU_LT)
    assert lamina.temperature_table.temperature_c[-2:] == (100.0, 120.0)
    assert design.thermal.allowable_temperature_c == 100.0
    assert NU_LT**2 * E_T * math.exp(-2.5) / E_L < 1e-5  # the 120 degC row: valid


def test_an_allowable_at_the_last_row_is_covered():
    data = baseline_data()
    data["thermal"]["allowable_temperature_c"] = 120.0
    design = design_from_dict(data)
    assert design.materials["t700_adiprene"].temperature_table.temperature_c[-1] == 120.0
    assert thermal_guards(design) == []


def test_a_table_cut_at_the_allowable_is_covered():
    data = baseline_data()
    table = data["materials"]["t700_adiprene"]["temperature_table"]
    for key, column in table.items():
        if column is not None:
            table[key] = tuple(column)[:-1]  # drop the 120 degC row
    design = design_from_dict(data)
    assert design.materials["t700_adiprene"].temperature_table.temperature_c[-1] == 100.0
    assert thermal_guards(design) == []
