"""The ``[materials.<name>.temperature_table]`` of a lamina: its properties over temperature.

A polyurethane matrix softens and gets lossier as it warms, by large factors between a cold
day and a hot-soaked boom. The table lists, at increasing temperatures [°C], the ply's storage
moduli [Pa] and loss factors [-] (the complex modulus is E'(1 + iη)). The lamina's own keys
(``E_T``, ``G_LT``, ``loss_E_T``, ...) remain its properties at the reference temperature
``[thermal] matrix_reference_temperature_c``, which the table must span; the table says how
each property varies from there:

    p(T) = p_key · p_table(T) / p_table(T_ref),

so that a table whose reference row repeats the keys (measured data, the packaged designs) is
used as it stands, and a key changed by an override or a sweep moves its whole curve with it.
``E_L`` and ``loss_E_L`` (fibre-dominated) are optional columns; without them they do not vary.

This module only validates the numbers (the design package is a data leaf). The interpolation,
linear in temperature on the logarithm of every property (piecewise exponential, the form of
the assumed law of :mod:`flexshaft.thermal.matrix` and of a DMA curve read on a log scale), and
its refusal to extrapolate outside the table, are in
:class:`flexshaft.thermal.matrix.LaminaTable`.
"""

from __future__ import annotations

from typing import Annotated

from pydantic import Field, model_validator

from flexshaft.design.fields import FrozenModel, Problems, format_number, format_value
from flexshaft.design.quantities import Modulus, quantity_field
from flexshaft.units import ZERO_CELSIUS

__all__ = ["MAX_TABLE_ROWS", "TABLE_COLUMNS", "TemperatureTable", "check_table_range"]

#: Most rows of a temperature table (a DMA sweep every 5 K from -100 to +200 °C has 61).
MAX_TABLE_ROWS = 100
#: The property columns of a table, in the order of the lamina's keys.
TABLE_COLUMNS = ("E_L", "E_T", "G_LT", "loss_E_L", "loss_E_T", "loss_G_LT")

TableCelsius = Annotated[
    float, quantity_field("degC", "temperature above absolute zero and at most 400 °C", gt=-ZERO_CELSIUS, le=400.0)
]
#: A loss factor of the table: strictly positive, because it is interpolated on its logarithm.
TableLossFactor = Annotated[
    float,
    quantity_field("-", "loss factor η in (0, 1) (interpolated on its logarithm, so 0 is not allowed)", gt=0.0, lt=1.0),
]
Rows = Field(min_length=2, max_length=MAX_TABLE_ROWS)


class TemperatureTable(FrozenModel):
    """Storage moduli [Pa] and loss factors [-] of a lamina at listed temperatures [°C].

    Every column has one value per temperature. Between rows each property is interpolated
    linearly in temperature on its logarithm; outside the table nothing is extrapolated (an
    analysis at such a temperature is refused with the temperature and the table's range).
    The lamina's keys are its values at ``[thermal] matrix_reference_temperature_c``, which the
    table must span; a property at T is its key times the table's ratio p(T)/p(T_ref)
    (docs/thermal.md). The table must reach ``[thermal] allowable_temperature_c`` (the self-heating
    analysis evaluates the lamina up to it).

    Attributes
    ----------
    temperature_c : array of floats
        Temperatures of the rows [°C], strictly increasing.
    E_T : array of floats
        Transverse storage modulus at each temperature [Pa].
    G_LT : array of floats
        In-plane shear storage modulus at each temperature [Pa].
    loss_E_T : array of floats
        Loss factor of E_T at each temperature [-].
    loss_G_LT : array of floats
        Loss factor of G_LT at each temperature [-].
    E_L : array of floats or None
        Fibre-direction storage modulus at each temperature [Pa]; omitted: the lamina's E_L at
        every temperature.
    loss_E_L : array of floats or None
        Loss factor of E_L at each temperature [-]; omitted: the lamina's loss_E_L.
    """

    temperature_c: Annotated[tuple[TableCelsius, ...], Rows]
    E_T: Annotated[tuple[Modulus, ...], Rows]
    G_LT: Annotated[tuple[Modulus, ...], Rows]
    loss_E_T: Annotated[tuple[TableLossFactor, ...], Rows]
    loss_G_LT: Annotated[tuple[TableLossFactor, ...], Rows]
    E_L: Annotated[tuple[Modulus, ...], Rows] | None = None
    loss_E_L: Annotated[tuple[TableLossFactor, ...], Rows] | None = None

    @model_validator(mode="after")
    def _check(self) -> TemperatureTable:
        problems = Problems()
        temperatures = self.temperature_c
        for index in range(1, len(temperatures)):
            if not temperatures[index] > temperatures[index - 1]:
                problems.add(
                    ("temperature_c", index),
                    f"must be greater than the previous temperature {format_number(temperatures[index - 1])} °C "
                    f"(the rows must be strictly increasing; got {format_value(temperatures[index])})",
                )
        for name in TABLE_COLUMNS:
            column = getattr(self, name)
            if column is not None and len(column) != len(temperatures):
                problems.add(
                    (name,),
                    f"must have one value per temperature: {len(temperatures)} values like temperature_c "
                    f"(got {len(column)})",
                )
        problems.raise_if_any()
        return self

    def columns(self) -> dict[str, tuple[float, ...]]:
        """The property columns that are given, by lamina key (``E_L`` ... ``loss_G_LT``)."""
        return {name: getattr(self, name) for name in TABLE_COLUMNS if getattr(self, name) is not None}


def check_table_range(
    problems: Problems, path: tuple, table: TemperatureTable, reference_c: float, allowable_c: float
) -> None:
    """Report, under ``path`` (the table's field path), a table that does not span the reference
    temperature ``reference_c`` [°C] (where the lamina's keys apply) or does not reach the
    allowable temperature ``allowable_c`` [°C]."""
    low, high = table.temperature_c[0], table.temperature_c[-1]
    if not low <= reference_c <= high:
        problems.add(
            path + ("temperature_c",),
            f"must span the reference temperature [thermal] matrix_reference_temperature_c = "
            f"{format_number(reference_c)} °C, where the lamina's own keys apply (the table runs from "
            f"{format_number(low)} to {format_number(high)} °C)",
        )
    if not high >= allowable_c:
        problems.add(
            path + ("temperature_c",),
            f"must reach the allowable temperature [thermal] allowable_temperature_c = {format_number(allowable_c)} °C "
            f"(the self-heating analysis evaluates the lamina up to it; the table ends at {format_number(high)} °C)",
        )
