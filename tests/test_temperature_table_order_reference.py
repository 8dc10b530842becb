"""A lamina temperature table's rows must increase strictly, from the first pair on.

docs/thermal.md (Validation): "at least two strictly increasing" temperatures; the interpolation
between rows needs T_1 < T_2 < ... (a descending pair would make an interval of negative width).
A three-row table whose first pair descends (20, 10, 30 °C) is refused at row 1, one whose last
pair descends (10, 30, 20 °C) at row 2, and (10, 20, 30 °C) is accepted. No tolerance: the
comparisons are of typed numbers.
"""

from __future__ import annotations

import pytest
from pydantic import ValidationError

from flexshaft.design.temperature_table import TemperatureTable


def _table(temperatures) -> TemperatureTable:
    return TemperatureTable(
        temperature_c=temperatures,
        E_T=(9.0e9, 6.0e9, 3.0e9),
        G_LT=(5.0e9, 3.0e9, 2.0e9),
        loss_E_T=(0.02, 0.05, 0.1),
        loss_G_LT=(0.03, 0.1, 0.2),
    )


def test_increasing_rows_are_accepted():
    assert _table((10.0, 20.0, 30.0)).temperature_c == (10.0, 20.0, 30.0)


@pytest.mark.parametrize(
    "temperatures, row", [((20.0, 10.0, 30.0), 1), ((10.0, 30.0, 20.0), 2), ((10.0, 10.0, 30.0), 1)]
)
def test_a_descending_or_repeated_pair_anywhere_is_refused(temperatures, row):
    with pytest.raises((ValidationError, ValueError), match=rf"temperature_c\.{row}: must be greater than"):
        _table(temperatures)
