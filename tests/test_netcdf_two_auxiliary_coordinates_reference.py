"""Two auxiliary coordinates over one dimension, written by
:func:`flexshaft.netcdf.write_labelled_netcdf` (the spin-up surfaces' ``kp`` and ``kd`` over
``case``, flexshaft.thesis.spinup_maps).

Reference: the CF conventions, section 5 "Coordinate Systems": "The value of the
``coordinates`` attribute is a blank separated list of the names of auxiliary coordinate
variables. There is no restriction on the order in which the auxiliary coordinate variables
appear" (read by review r127 in cf-conventions' ch05.adoc; hence the sorted comparison); xarray, an independent
writer, joins them with one blank (``" ".join``) and attaches each named variable as a
coordinate when it reads the file. Every value below is a chosen input, so the comparisons are
exact (no tolerance).
"""

from __future__ import annotations

import numpy as np
import pytest

xr = pytest.importorskip("xarray")
netcdf_file = pytest.importorskip("scipy.io").netcdf_file

import flexshaft.netcdf as nc
from flexshaft.analyses.labelled import LabelledArrays

KP = [5e5, 2e6]  # [N/m], chosen
KD = [150.0, 600.0]  # [N s/m], chosen


def _surfaces() -> LabelledArrays:
    orbit = np.arange(12.0).reshape(2, 6) * 1e-6  # [m], chosen
    return LabelledArrays(
        {"shaft_orbit": (("case", "speed"), orbit, {"units": "m"})},
        coords={
            "case": ["design gains", "tuned gains"],
            "kp": ("case", KP, {"units": "N/m"}),
            "kd": ("case", KD, {"units": "N s/m"}),
            "speed": ("speed", np.linspace(100.0, 600.0, 6), {"units": "rad/s"}),
        },
        attrs={"title": "two auxiliary coordinates"},
    )


def test_both_auxiliary_coordinates_are_named_blank_separated(tmp_path):
    if nc._netcdf4_available():
        pytest.skip("netCDF4 or h5netcdf installed: xarray writes the file, not the netCDF3 path")
    path = nc.write_labelled_netcdf(_surfaces(), tmp_path / "surfaces.nc")
    f = netcdf_file(path, "r", mmap=False)
    try:
        names = f.variables["shaft_orbit"].coordinates.decode()
    finally:
        f.close()
    assert sorted(names.split(" ")) == ["kd", "kp"]  # CF: a blank-separated list of names
    back = xr.load_dataset(path)
    assert {"kp", "kd"} <= set(back.coords) and not {"kp", "kd"} & set(back.data_vars)
    assert back["kp"].values.tolist() == KP and back["kd"].values.tolist() == KD
    assert back["kd"].attrs["units"] == "N s/m"
    # and the whole file is the one xarray writes for the same Dataset
    theirs = nc.write_netcdf(_surfaces().to_dataset(), tmp_path / "xarray.nc")
    assert path.read_bytes() == theirs.read_bytes()
