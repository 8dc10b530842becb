"""The netCDF files flexshaft writes are written atomically, against README ("Output folders"):
"Files are written under a temporary name and renamed into place, so a crash or a full disk
never leaves half a file, an error names the file, and a symbolic link inside the folder is
replaced, never followed" (also docs/architecture.md, layer 0: "a symbolic link is replaced,
never followed").

References: the bytes of a file written by hand before the call (they must survive a failed
write and a write through a link), and the data written, read back with scipy's netCDF3 reader
(independent of flexshaft's writer) and compared exactly (float64 round trip of the same
numbers). Three values: well under 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.io

import flexshaft.netcdf as nc
from flexshaft.analyses.labelled import LabelledArrays


@pytest.fixture(autouse=True)
def _netcdf3_writer(monkeypatch: pytest.MonkeyPatch) -> None:
    """The package's own netCDF3 writer, also where netCDF4 is installed (xarray would write)."""
    monkeypatch.setattr(nc, "_netcdf4_available", lambda: False)


USER = b"the user's own notes, not a netCDF file\n"


def _arrays() -> LabelledArrays:
    return LabelledArrays({"peak": ("case", np.array([1.5, 2.25, 3.125]), {"units": "m"})}, attrs={"title": "t"})


def test_a_link_at_the_path_is_replaced_and_its_target_left_alone(tmp_path):
    """The link is replaced by the file written; the file it pointed to keeps its bytes."""
    target = tmp_path / "notes.txt"
    target.write_bytes(USER)
    link = tmp_path / "results.nc"
    link.symlink_to(target)
    nc.write_labelled_netcdf(_arrays(), link)
    assert target.read_bytes() == USER
    assert not link.is_symlink()
    with scipy.io.netcdf_file(link, "r", mmap=False) as f:
        np.testing.assert_array_equal(f.variables["peak"][:], [1.5, 2.25, 3.125])


def test_a_failed_write_leaves_the_previous_file_and_no_temporary_file(tmp_path, monkeypatch):
    """A write that fails after the file was opened (a stand-in for a full disk) raises and
    leaves the earlier file byte for byte, and no temporary file beside it."""
    path = tmp_path / "results.nc"
    path.write_bytes(USER)

    class Failing(scipy.io.netcdf_file):
        def createVariable(self, *args, **kwargs):
            raise OSError(28, "No space left on device")

    monkeypatch.setattr(scipy.io, "netcdf_file", Failing)
    with pytest.raises(OSError):
        nc.write_labelled_netcdf(_arrays(), path)
    assert path.read_bytes() == USER
    assert sorted(p.name for p in tmp_path.iterdir()) == ["results.nc"]
