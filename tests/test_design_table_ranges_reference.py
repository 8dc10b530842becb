"""Ranges of design-file fields against docs/design-reference.md (mutation hunt h41b).

* ``[materials.<name>.temperature_table]``: every column "2 to 100 items", and "every column
  has one value per temperature". A DMA sweep every 5 K from −100 to +200 °C has
  (200 − (−100))/5 + 1 = 61 rows and must be accepted; one row (no variation to interpolate)
  and 101 rows are refused as too short and too long, and a column longer than
  ``temperature_c`` is refused.
* ``[[couplings]] torsional_stiffness``: docs/design.schema.json, the field's numeric branch,
  "torsional stiffness above 0 and at most 1e12 N m/rad (it carries the torque)" (its
  ``exclusiveMinimum`` 0 and ``maximum`` 1e12; the row of docs/design-reference.md shows no
  range, as the reference renders none for a number-or-"rigid" field): 1e12 is accepted, 1e10
  too (a stiff disc pack), 0 and 1.0000001e12 refused by those two bounds.
* "floats are strict (``"3"`` and ``true`` are refused; integers are accepted)" (the
  reference's preamble), on the ``Finite`` field type every finite float key uses.

Validation only (no model): milliseconds of CPU.
"""

from __future__ import annotations

import numpy as np
import pydantic
import pytest

from flexshaft.design.fields import Finite
from flexshaft.design.segments import Coupling
from flexshaft.design.temperature_table import TemperatureTable


def _table(temperatures, **overrides) -> TemperatureTable:
    n = len(temperatures)
    columns = {
        "E_T": tuple(np.geomspace(9e9, 3e9, n)) if n > 1 else (9e9,),
        "G_LT": tuple(np.geomspace(5e9, 2e9, n)) if n > 1 else (5e9,),
        "loss_E_T": (0.05,) * n,
        "loss_G_LT": (0.08,) * n,
    }
    columns.update(overrides)
    return TemperatureTable(temperature_c=tuple(float(t) for t in temperatures), **columns)


def test_a_dma_sweep_every_5_k_of_61_rows_is_accepted():
    temperatures = np.arange(-100.0, 200.0 + 1e-9, 5.0)
    assert temperatures.size == 61
    assert len(_table(temperatures).temperature_c) == 61


@pytest.mark.parametrize("rows", [2, 100])
def test_two_to_a_hundred_rows_are_accepted(rows):
    assert len(_table(np.linspace(-50.0, 150.0, rows)).temperature_c) == rows


@pytest.mark.parametrize(("rows", "error"), [(1, "too_short"), (101, "too_long")])
def test_one_or_101_rows_are_refused(rows, error):
    with pytest.raises(pydantic.ValidationError) as refused:
        _table(np.linspace(-50.0, 150.0, rows))
    assert {e["loc"][0] for e in refused.value.errors() if e["type"] == error} >= {"temperature_c"}


def test_a_column_longer_than_the_temperatures_is_refused():
    with pytest.raises(pydantic.ValidationError, match="one value per temperature"):
        _table((20.0, 80.0), loss_E_T=(0.05, 0.06, 0.07))


def _coupling(torsional):
    return Coupling(name="c", x=1.0, angular_stiffness=1e3, axial_stiffness="rigid", torsional_stiffness=torsional)


@pytest.mark.parametrize("torsional", [1e10, 1e12])
def test_a_stiff_torsional_coupling_up_to_1e12_is_accepted(torsional):
    assert _coupling(torsional).torsional_stiffness == torsional


@pytest.mark.parametrize(("torsional", "error"), [(0.0, "greater_than"), (1.0000001e12, "less_than_equal")])
def test_torsional_stiffness_outside_0_1e12_is_refused(torsional, error):
    with pytest.raises(pydantic.ValidationError) as refused:
        _coupling(torsional)
    numeric = [e for e in refused.value.errors() if e["loc"][-1] != "literal['rigid']"]
    assert [(e["loc"][0], e["type"]) for e in numeric] == [("torsional_stiffness", error)]


@pytest.mark.parametrize("value", ["3", True])
def test_a_float_field_refuses_text_and_booleans(value):
    with pytest.raises(pydantic.ValidationError):
        pydantic.TypeAdapter(Finite).validate_python(value)


def test_a_float_field_accepts_an_integer():
    assert pydantic.TypeAdapter(Finite).validate_python(3) == 3.0
