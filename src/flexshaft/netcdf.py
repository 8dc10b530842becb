"""Atomic netCDF writing for every dataset the package saves.

netCDF4 (HDF5) when the optional ``netCDF4`` package is installed, otherwise netCDF3 through
scipy, xarray's default engines; the file appears only once complete (temporary file, then
``os.replace``, :mod:`flexshaft.files`).

:func:`write_labelled_netcdf` writes plain labelled arrays (a
:class:`~flexshaft.analyses.labelled.LabelledArrays`) without building their Dataset: where
xarray would write netCDF3 through scipy, it writes the same file content through
:class:`scipy.io.netcdf_file` directly, with xarray's CF encoding of the types study results
hold, and so skips importing xarray, pandas and (when installed) dask and distributed, which
xarray imports to build and write a Dataset: 0.55 s of CPU against 0.02 s of writing
(``flexshaft run``'s ten study files, benchmarks/studies_timing.py). Anything else goes
through xarray.
"""

from __future__ import annotations

import importlib.util
import numbers
import os
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft.files import writing

__all__ = ["write_labelled_netcdf", "write_netcdf"]

#: Modules that make xarray write netCDF4 instead of netCDF3 through scipy (its default engine
#: order: netcdf4, h5netcdf, scipy).
_NETCDF4_ENGINES = ("netCDF4", "h5netcdf")
#: netCDF3 (CDF-2, "64-bit offset"): xarray's scipy engine's default format.
_NC3_VERSION = 2
#: String encoding of xarray's netCDF3 text (attributes and character arrays).
_ENCODING = "utf-8"


def write_netcdf(ds, path: str | os.PathLike) -> Path:
    """Write the :class:`xarray.Dataset` ``ds`` to ``path`` atomically (a symbolic link at
    ``path`` is replaced, never followed; an error names ``path``,
    :func:`flexshaft.files.writing`); returns the path."""
    path = Path(path)
    with writing(path, suffix=".nc") as tmp:
        ds.to_netcdf(tmp)
    return path


def write_labelled_netcdf(arrays, path: str | os.PathLike) -> Path:
    """Write ``arrays`` (a :class:`~flexshaft.analyses.labelled.LabelledArrays`: ``data_vars``,
    ``coords`` and ``attrs``) to ``path`` as :func:`write_netcdf` writes ``arrays.to_dataset()``:
    the same variables, coordinates, attributes and encoding (xarray reads back the same
    Dataset), without xarray when the file is netCDF3 and every variable and attribute is of a
    type :func:`_nc3_variables` encodes; otherwise through the Dataset."""
    path = Path(path)
    encoded = None if _netcdf4_available() else _nc3_variables(arrays)
    if encoded is None:
        return write_netcdf(arrays.to_dataset(), path)
    dims, variables, attrs = encoded
    from scipy.io import netcdf_file

    with writing(path, suffix=".nc") as tmp:
        f = netcdf_file(tmp, "w", version=_NC3_VERSION)
        try:
            for name, size in dims.items():
                f.createDimension(name, size)
            for name, (var_dims, values, var_attrs) in variables.items():
                v = f.createVariable(name, values.dtype, var_dims)
                v[...] = values
                for key, value in var_attrs.items():
                    setattr(v, key, value)
            for key, value in attrs.items():
                setattr(f, key, value)
        finally:
            f.close()
    return path


def _netcdf4_available() -> bool:
    return any(importlib.util.find_spec(name) is not None for name in _NETCDF4_ENGINES)


def _nc3_attr(value) -> Any:
    """An attribute as xarray's netCDF3 encoding writes it (text as UTF-8 bytes, a number as a
    one-element array, int64 as int32); None for any other type."""
    if isinstance(value, str):
        return value.encode(_ENCODING)
    if isinstance(value, (bool, np.bool_)):
        return None
    if isinstance(value, numbers.Integral):
        if not np.iinfo(np.int32).min <= int(value) <= np.iinfo(np.int32).max:
            return None
        return np.atleast_1d(np.int32(value))
    if isinstance(value, (float, np.floating)):
        return np.atleast_1d(np.float64(value))
    return None


def _nc3_attrs(attrs) -> dict | None:
    out = {}
    for key, value in attrs.items():
        encoded = _nc3_attr(value)
        if encoded is None or not isinstance(key, str) or key.startswith("_"):
            return None
        out[key] = encoded
    return out


def _nc3_variables(arrays) -> tuple[dict, dict, dict] | None:
    """``(dims, variables, attrs)`` of the netCDF3 file xarray writes for ``arrays``: float
    variables with ``_FillValue`` NaN, text coordinates as character arrays over a
    ``stringN`` dimension with ``_Encoding`` UTF-8, non-dimension coordinates named in the
    ``coordinates`` attribute of the data variables over their dimensions; None when
    something else is there (xarray then writes it)."""
    attrs = _nc3_attrs(arrays.attrs)
    if attrs is None:
        return None
    coords, data_vars = dict(arrays.coords), dict(arrays.data_vars)
    if set(coords) & set(data_vars):
        return None
    dims: dict[str, int] = {}
    variables: dict[str, tuple] = {}
    aux = {name: c for name, c in coords.items() if c.dims != (name,)}
    for name, item in (*data_vars.items(), *coords.items()):
        values = np.asarray(item.values)
        for dim, size in zip(item.dims, values.shape):
            if dims.setdefault(dim, size) != size:
                return None
        var_attrs = _nc3_attrs(item.attrs)
        if var_attrs is None or any(k in var_attrs for k in ("coordinates", "_FillValue", "_Encoding")):
            return None
        if name in data_vars:
            names = sorted(c for c, v in aux.items() if set(v.dims) <= set(item.dims))
            if names:
                var_attrs["coordinates"] = " ".join(names).encode(_ENCODING)
        if values.dtype.kind == "f":
            variables[name] = (item.dims, values, {**var_attrs, "_FillValue": np.atleast_1d(values.dtype.type(np.nan))})
        elif values.dtype.kind == "U" and name in coords and values.ndim == 1 and values.size:
            text = np.char.encode(values, _ENCODING)
            width = text.dtype.itemsize
            if width == 0:
                return None
            string_dim = f"string{width}"
            if dims.setdefault(string_dim, width) != width:
                return None
            chars = text.view("S1").reshape(values.size, width)
            variables[name] = ((*item.dims, string_dim), chars, {**var_attrs, "_Encoding": _ENCODING.encode()})
        else:
            return None
    if any(not any(set(c.dims) <= set(v.dims) for v in data_vars.values()) for c in aux.values()):
        return None  # xarray names it in a global "coordinates" attribute
    return dims, variables, attrs
