"""The numbers a result's table and its plain-array stand-in hand a user
(flexshaft.analyses.results, flexshaft.analyses.labelled).

* **Four significant figures.** The per-mode table (``print(modes)``, README: "f [Hz] and
  [rpm]") is read against speeds published to four figures: docs/thesis-reproduction.md gives
  the baseline's modes at 3955 rpm and 5611 rpm. A table cell must show them as ``3955`` and
  ``5611`` (``format(3955.4, ".4g")``, Python's format specification: four significant
  figures), not ``3.96e+03``; ζ = 0.012345 (binary value 0.01234500000000000007) shows as
  ``0.01235``, not ``0.0123``.
* **A scalar only from a scalar.** ``float()`` of a variable that still has a dimension is an
  error in xarray (``TypeError: only 0-dimensional arrays can be converted to Python
  scalars``, xarray with numpy 2, checked by hand); the plain-array stand-in must refuse it too,
  not pick a value, and give the nearest point's value after a ``sel``.

Pure Python and numpy: milliseconds.

Written for the mutations h50b-results-cell-default-three-digits and
h50b-labelled-float-of-first of scripts/mutations.toml.
"""

from __future__ import annotations

import pytest

from flexshaft.analyses.labelled import LabelledArrays
from flexshaft.analyses.results import cell_text, text_table


def test_table_cells_carry_four_significant_figures():
    assert format(3955.4, ".4g") == "3955"  # the reference: Python's own format
    assert cell_text(3955.4) == "3955"
    assert cell_text(0.012345) == "0.01235"
    table = text_table(["mode", "f [rpm]"], [[1, 3955.4], [2, 5611.2]])
    assert table.splitlines()[2:] == ["   1     3955", "   2     5611"]


def test_a_variable_with_a_dimension_is_not_a_scalar():
    arrays = LabelledArrays({"peak": ("speed", [1.0e-3, 4.0e-3])}, {"speed": [100.0, 300.0]})
    with pytest.raises(TypeError):
        float(arrays["peak"])
    assert float(arrays["peak"].sel(speed=290.0)) == 4.0e-3
