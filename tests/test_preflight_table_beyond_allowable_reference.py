"""The thermal preflight judges a lamina's temperature table over the self-heating's range only:
a row beyond the allowable temperature, where no analysis of the self-heating evaluates the ply,
does not refuse the design.

The rule (docs/thermal.md, the ``[thermal]`` table's note): a lamina's table "must then cover
the shaft's air to the allowable and keep the ply valid at every row in between"; the self-
heating stops at the allowable (docs/limits.md: the preflight refuses a table "that makes the
ply invalid over the self-heating's range"). Rows beyond it are the user's data for a hotter
envelope point, judged there by the verdict's own preflight, not by ``thermal_guards``.

The plane-stress condition (as in tests/test_preflight_tabled_lamina_reference.py): a ply is
valid while ν_LT² E_T/E_L < 1. Worked by hand on the embedded baseline (lamina t700_adiprene,
E_L = 115 GPa, ν_LT = 0.35, its table E_T(T) = 0.1 GPa e^{−(T − 20 °C)/40 K} at rows every 20 °C
from −60 to 120 °C, reference 20 °C; the shaft's air 317.27 K = 44.12 °C; allowable 100 °C):

* the 120 °C row set to E_T = 1e12 Pa gives 0.1225 · 1e12/115e9 = 1.065 ≥ 1 there: invalid;
* at the range's top, the 100 °C row, E_T = 0.1 GPa e^{−2} = 13.53 MPa:
  0.1225 · 13.53e6/115e9 = 1.4e-5; the ply is valid over the whole range (E_T falls from the air
  to 100 °C, rows unchanged there), so ``thermal_guards`` returns nothing;
* the same 1e12 Pa on the 100 °C row (the allowable, the range's end) is refused: the contrast,
  showing the row's value would be seen inside the range.

A few ms each, no model built.
"""

from __future__ import annotations

import copy
import math

from flexshaft.design import design_from_dict, embedded_design
from flexshaft.thermal.preflight import thermal_guards

E_L, E_T, NU_LT = 115e9, 0.1e9, 0.35
TABLE = "materials.t700_adiprene.temperature_table"


def with_stiff_row(row_c: float):
    data = copy.deepcopy(embedded_design("baseline").model_dump())
    table = data["materials"]["t700_adiprene"]["temperature_table"]
    row = table["temperature_c"].index(row_c)
    table["E_T"] = tuple(1e12 if i == row else e for i, e in enumerate(table["E_T"]))
    return design_from_dict(data)


def test_the_hand_numbers():
    design = embedded_design("baseline")
    lamina = design.materials["t700_adiprene"]
    assert (lamina.E_L, lamina.E_T, lamina.nu_LT) == (E_L, E_T, NU_LT)
    assert design.thermal.allowable_temperature_c == 100.0
    assert lamina.temperature_table.temperature_c[-2:] == (100.0, 120.0)
    assert NU_LT**2 * 1e12 / E_L >= 1.0  # the stiff row: invalid
    assert NU_LT**2 * E_T * math.exp(-2.0) / E_L < 1e-4  # the 100 degC row: valid


def test_an_invalid_row_beyond_the_allowable_is_not_refused():
    assert thermal_guards(with_stiff_row(120.0)) == []


def test_the_same_row_at_the_allowable_is_refused():
    problems = thermal_guards(with_stiff_row(100.0))
    assert [p.path for p in problems] == [TABLE], problems
    assert "at 373.15 K" in problems[0].message
