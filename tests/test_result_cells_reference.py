"""Result tables' integer cells and the netCDF file name (flexshaft.analyses.results; mutation
hunt h41b).

* ``cell_text``, its docstring: "a float with ``digits`` significant figures (``g`` format), an
  integer (Python or NumPy) whole (12345 stays "12345")": a node number, a count, a 12345
  rev/min speed given as an int is not the four-figure "1.234e+04".
* ``netcdf_path``: "``path`` with ``.nc`` added when it has no suffix (``"campbell"`` →
  ``campbell.nc``)": a path that has a suffix is kept, so ``save("modes.nc")`` writes
  ``modes.nc``, not ``modes.nc.nc``.

No model: microseconds of CPU.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from flexshaft.analyses.results import cell_text, netcdf_path, text_table


def test_integers_are_shown_whole():
    assert cell_text(12345) == "12345"
    assert cell_text(np.int64(1234567)) == "1234567"
    assert cell_text(12345.678) == "1.235e+04"  # a float: four significant figures
    table = text_table(["node", "f [Hz]"], [[12345, 81.2076]])
    assert table.splitlines()[-1].split() == ["12345", "81.21"]


def test_nc_is_added_only_without_a_suffix(tmp_path):
    assert netcdf_path(tmp_path / "campbell") == tmp_path / "campbell.nc"
    assert netcdf_path(tmp_path / "modes.nc") == tmp_path / "modes.nc"
    assert netcdf_path("run.cdf") == Path("run.cdf")
