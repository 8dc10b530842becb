"""The plain-array stand-in of a Dataset (flexshaft.analyses.labelled) against xarray itself:
the same spec gives the same values, coordinates, attributes and nearest-point selections, and
it crosses a process boundary without importing xarray."""

from __future__ import annotations

import pickle
import subprocess
import sys

import numpy as np
import pytest
import xarray as xr

from flexshaft.analyses.labelled import LabelledArrays


def _spec():
    rng = np.random.default_rng(3)
    data = {
        "safety_factor": (("alpha", "beta"), rng.random((4, 3)), {"units": "1", "long_name": "Tsai-Wu"}),
        "peak": ("alpha", rng.random(4), {"units": "m"}),
        "names": ("case", np.array(["a", "b"])),
    }
    coords = {
        "alpha": ("alpha", np.array([0.0, 15.0, 55.0, 90.0]), {"units": "deg"}),
        "beta": [0.0, 30.0, 60.0],
        "case": ["first", "second"],
        "kp": ("case", [1e5, 2e6], {"units": "N/m"}),
    }
    return data, coords, {"title": "a study", "n": 3}


def test_same_content_as_the_dataset_built_from_the_same_spec():
    data, coords, attrs = _spec()
    arrays = LabelledArrays(data, coords, attrs)
    ds = xr.Dataset(data, coords=coords, attrs=attrs)
    assert arrays.to_dataset().identical(ds)
    for name in ("safety_factor", "peak", "names", "alpha", "beta", "kp"):
        np.testing.assert_array_equal(arrays[name].values, ds[name].values)
        assert arrays[name].dims == ds[name].dims
        assert arrays[name].attrs == ds[name].attrs
    np.testing.assert_array_equal(arrays.alpha.values, ds.alpha.values)  # attribute access
    assert float(arrays.kp[1]) == float(ds.kp[1])
    assert arrays.attrs == ds.attrs and set(arrays) == set(ds.data_vars)
    assert arrays.sizes == dict(ds.sizes)


@pytest.mark.parametrize("alpha, beta", [(54.0, 1.0), (-10.0, 100.0), (20.0, 44.0), (90.0, 30.0)])
def test_nearest_selection_is_xarrays(alpha, beta):
    data, coords, attrs = _spec()
    arrays, ds = LabelledArrays(data, coords, attrs), xr.Dataset(data, coords=coords, attrs=attrs)
    got = arrays["safety_factor"].sel(alpha=alpha, beta=beta, method="nearest")
    assert float(got) == float(ds["safety_factor"].sel(alpha=alpha, beta=beta, method="nearest"))
    row = arrays.sel({"alpha": alpha}, method="nearest")
    want = ds.sel({"alpha": alpha}, method="nearest")
    assert row.to_dataset().identical(want)


@pytest.mark.parametrize("speed", [2.1, -5.0, 2.6])
def test_selection_reduces_every_coordinate_on_the_selected_dimension(speed):
    """A coordinate that is not its dimension's own (``rpm`` on ``speed``) is selected with it,
    as xarray's ``sel(..., method="nearest")`` does (the reference: the Dataset built from the
    same spec); coordinates given as ``(dim, values)`` without attributes, the form the class
    docstring allows, are accepted. Speeds 2.1, -5 and 2.6 lie nearest 2, 1 and 3: no ties."""
    data = {"y": ("speed", np.arange(3.0), {"units": "m"})}
    coords = {"speed": ("speed", [1.0, 2.0, 3.0]), "rpm": ("speed", [10.0, 20.0, 30.0], {"units": "rpm"})}
    arrays, ds = LabelledArrays(data, coords), xr.Dataset(data, coords=coords)
    assert arrays.to_dataset().identical(ds)
    got, want = arrays.sel(speed=speed), ds.sel(speed=speed, method="nearest")
    assert got.to_dataset().identical(want)
    assert float(got.rpm) == float(want.rpm) and got.sizes == dict(want.sizes) == {}


def test_other_dataset_attributes_come_from_the_dataset(tmp_path):
    data, coords, attrs = _spec()
    arrays = LabelledArrays(data, coords, attrs)
    arrays.to_netcdf(tmp_path / "a.nc")  # not defined here: looked up on the Dataset
    assert xr.load_dataset(tmp_path / "a.nc").identical(xr.Dataset(data, coords=coords, attrs=attrs))
    with pytest.raises(KeyError, match="no variable or coordinate"):
        arrays["nothing"]
    with pytest.raises(ValueError, match="only 'nearest'"):
        arrays["peak"].sel(alpha=1.0, method="pad")


def test_unpickles_without_xarray():
    data, coords, attrs = _spec()
    arrays = LabelledArrays(data, coords, attrs)
    arrays.to_dataset()  # a built Dataset is not pickled with it
    code = (
        "import pickle, sys; a = pickle.loads(sys.stdin.buffer.read()); "
        "print(float(a['safety_factor'].sel(alpha=55.0, beta=0.0)), 'xarray' in sys.modules)"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], input=pickle.dumps(arrays), capture_output=True, check=True
    ).stdout.split()
    assert float(out[0]) == data["safety_factor"][1][2, 0] and out[1] == b"False"
