"""A lamina temperature table whose first or last row is the reference temperature spans it.

docs/thermal.md ("Validation"): the table must span ``[thermal] matrix_reference_temperature_c``
and reach ``allowable_temperature_c``; the interpolation is "exact at the rows" and only a
temperature *outside* the table is refused. So a closed interval: a reference temperature equal
to the first or the last row is inside (the lamina's keys apply at a row), and one a degree
beyond either end is not. Checked on :func:`flexshaft.design.temperature_table.check_table_range`
with a two-row table (no tolerance: the comparisons are of typed numbers).
"""

from __future__ import annotations

import pytest

from flexshaft.design.fields import Problems
from flexshaft.design.temperature_table import TemperatureTable, check_table_range


def _table(low: float, high: float) -> TemperatureTable:
    return TemperatureTable(
        temperature_c=(low, high), E_T=(9.0e9, 3.0e9), G_LT=(5.0e9, 2.0e9), loss_E_T=(0.02, 0.1), loss_G_LT=(0.03, 0.2)
    )


def _paths(reference_c: float, allowable_c: float, table: TemperatureTable) -> list:
    problems = Problems()
    check_table_range(problems, ("table",), table, reference_c, allowable_c)
    return [path for path, _ in problems.items]


@pytest.mark.parametrize("reference_c", [20.0, 50.0, 100.0])
def test_reference_at_either_row_or_between_is_spanned(reference_c):
    assert _paths(reference_c, 100.0, _table(20.0, 100.0)) == []


@pytest.mark.parametrize("reference_c", [19.0, 101.0])
def test_reference_beyond_either_row_is_refused(reference_c):
    assert _paths(reference_c, 100.0, _table(20.0, 100.0)) == [("table", "temperature_c")]
