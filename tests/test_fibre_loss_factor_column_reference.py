"""A lamina temperature table's optional fibre loss factor column (``loss_E_L``).

docs/thermal.md ("Lamina properties over temperature"): ``E_L`` and ``loss_E_L`` are optional
columns; loss factors must lie in (0, 1); between rows each property is interpolated linearly in
temperature on its logarithm, and a property at T is its key times the table's ratio
p(T) = p_key · p_table(T)/p_table(T_ref).

Hand reference (derived here): rows at 0, 20 and 60 °C with loss_E_L = 0.004, 0.005, 0.02 and
T_ref = 20 °C. At 40 °C, halfway between the 20 and 60 °C rows on the logarithm,
p_table(40 °C) = 0.005 · (0.02/0.005)^(1/2) = 0.005 · 2 = 0.01, so the ratio to the reference row
is 2 and a lamina whose key is loss_E_L = 0.01 has 0.02 there. At the 0 °C row the ratio is
0.004/0.005 = 0.8, giving 0.008. Relative tolerance 1e-12: a ratio, a power and two products of
numbers near 1e-2, a few ulps each (no cancellation), so 1e-12 is 4 orders above the rounding
and far below any wrong column or interpolation (a factor 2 at 40 °C).

A column of loss factors in (0, 1) is accepted, and one holding a value of 5000 (a number in the
modulus range [Pa], not a loss factor) is refused, naming the column.
"""

from __future__ import annotations

import pytest
from pydantic import ValidationError

from flexshaft.design.temperature_table import TemperatureTable
from flexshaft.thermal.matrix import PROPERTY_NAMES, LaminaTable, MatrixTemperatureLaw
from flexshaft.units import celsius_to_kelvin

REL = 1e-12


def _table(loss_E_L) -> TemperatureTable:
    return TemperatureTable(
        temperature_c=(0.0, 20.0, 60.0),
        E_T=(9.0e9, 6.0e9, 3.0e9),
        G_LT=(5.0e9, 3.0e9, 2.0e9),
        loss_E_T=(0.02, 0.05, 0.1),
        loss_G_LT=(0.03, 0.1, 0.2),
        loss_E_L=loss_E_L,
    )


def test_a_fibre_loss_factor_column_is_accepted_and_interpolated_on_its_logarithm():
    table = _table((0.004, 0.005, 0.02))
    assert table.columns()["loss_E_L"] == (0.004, 0.005, 0.02)
    law = MatrixTemperatureLaw(reference_temperature=celsius_to_kelvin(20.0), table=LaminaTable.from_schema(table))
    keys = dict.fromkeys(PROPERTY_NAMES, 1.0e9) | {"loss_E_L": 0.01, "loss_E_T": 0.05, "loss_G_LT": 0.1}
    at_40 = law.properties(keys, celsius_to_kelvin(40.0))
    assert at_40["loss_E_L"] == pytest.approx(0.02, rel=REL)
    at_0 = law.properties(keys, celsius_to_kelvin(0.0))
    assert at_0["loss_E_L"] == pytest.approx(0.008, rel=REL)


def test_a_fibre_loss_factor_outside_zero_one_is_refused():
    with pytest.raises(ValidationError, match="loss_E_L"):
        _table((0.004, 0.005, 5000.0))
