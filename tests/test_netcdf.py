"""netCDF writing of plain labelled arrays (flexshaft.netcdf.write_labelled_netcdf) against
xarray's own writer: the same file, byte for byte, where it writes netCDF3 itself; xarray
writes whatever it does not encode."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import flexshaft.netcdf as nc
from flexshaft.analyses.labelled import LabelledArrays


def _arrays(**attrs) -> LabelledArrays:
    """The kinds of content flexshaft's study results hold: float variables over dimensions with
    and without coordinates, NaN, text coordinates (one of them not ASCII), a non-dimension
    coordinate, text, integer and float attributes."""
    rng = np.random.default_rng(7)
    orbit = rng.random((2, 3, 5))
    orbit[0, 1, 2] = np.nan
    return LabelledArrays(
        {
            "orbit": (("case", "x", "speed"), orbit, {"units": "m", "long_name": "shaft orbit – major semi-axis"}),
            "force": (("case", "actuator", "speed"), rng.random((2, 2, 5)), {"units": "N"}),
            "peak": ("case", rng.random(2)),
            "free": ("station", rng.random(4), {"units": "m"}),  # a dimension without coordinate
        },
        coords={
            "case": ["design gains", "tuned gains (K_d ≥ 0)"],
            "kp": ("case", [5e5, 2e6], {"units": "N/m"}),
            "actuator": ("actuator", np.array(["AMB 1", "AMB 2"]), {"long_name": "active bearing"}),
            "x": ("x", np.linspace(0.0, 2.0, 3), {"units": "m"}),
            "speed": ("speed", np.linspace(10.0, 500.0, 5), {"units": "rad/s"}),
        },
        attrs={"title": "spin-up – tuned gains", "n_speeds": 392, "speed_max": 502.65, **attrs},
    )


def _both(arrays, tmp_path):
    ours = nc.write_labelled_netcdf(arrays, tmp_path / "ours.nc")
    theirs = nc.write_netcdf(arrays.to_dataset(), tmp_path / "xarray.nc")
    return ours, theirs


def test_the_file_is_xarrays_byte_for_byte_without_building_the_dataset(tmp_path, monkeypatch):
    if nc._netcdf4_available():
        pytest.skip("netCDF4 or h5netcdf installed: xarray writes netCDF4, and so does write_labelled_netcdf")
    arrays = _arrays()
    assert nc._nc3_variables(arrays) is not None  # written directly
    with monkeypatch.context() as m:  # proof that no Dataset is built on the direct path
        m.setattr(LabelledArrays, "to_dataset", lambda self: pytest.fail("the Dataset was built"))
        ours = nc.write_labelled_netcdf(arrays, tmp_path / "ours.nc")
    theirs = nc.write_netcdf(arrays.to_dataset(), tmp_path / "xarray.nc")
    assert ours.read_bytes() == theirs.read_bytes()
    back = xr.load_dataset(ours)
    assert back.identical(xr.load_dataset(theirs)) and back.identical(arrays.to_dataset())
    assert back["orbit"].encoding["_FillValue"] != back["orbit"].encoding["_FillValue"]  # NaN, as xarray's


@pytest.mark.parametrize(
    "attrs",
    [
        {"flag": True},  # netCDF3 has no boolean: xarray's coercion decides
        {"raw": b"bytes"},
        {"list": [1.0, 2.0]},
    ],
)
def test_what_it_does_not_encode_goes_through_xarray(attrs, tmp_path):
    arrays = _arrays(**attrs)
    assert nc._nc3_variables(arrays) is None
    ours, theirs = _both(arrays, tmp_path)
    assert xr.load_dataset(ours).identical(xr.load_dataset(theirs))


def test_an_integer_beyond_int32_is_refused_as_xarray_refuses_it(tmp_path):
    arrays = _arrays(big=2**40)  # netCDF3 has no int64
    assert nc._nc3_variables(arrays) is None
    with pytest.raises(ValueError, match="int64 to int32"):
        nc.write_labelled_netcdf(arrays, tmp_path / "a.nc")


def test_with_a_netcdf4_engine_installed_xarray_writes_it(tmp_path, monkeypatch):
    arrays = _arrays()
    monkeypatch.setattr(nc, "_netcdf4_available", lambda: True)
    built = []
    original = LabelledArrays.to_dataset
    monkeypatch.setattr(LabelledArrays, "to_dataset", lambda self: built.append(1) or original(self))
    nc.write_labelled_netcdf(arrays, tmp_path / "a.nc")
    assert built  # the Dataset's own writer, whatever engine xarray picks
    assert xr.load_dataset(tmp_path / "a.nc").identical(original(arrays))
