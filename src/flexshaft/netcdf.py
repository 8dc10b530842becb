"""Atomic netCDF writing for every dataset the package saves.

netCDF4 (HDF5) when the optional ``netCDF4`` package is installed, otherwise netCDF3 through
scipy, xarray's default engines; the file appears only once complete (temporary file, then
``os.replace``, :mod:`flexshaft.files`).
"""

from __future__ import annotations

import os
from pathlib import Path

from flexshaft.files import writing

__all__ = ["write_netcdf"]


def write_netcdf(ds, path: str | os.PathLike) -> Path:
    """Write the :class:`xarray.Dataset` ``ds`` to ``path`` atomically (a symbolic link at
    ``path`` is replaced, never followed; an error names ``path``,
    :func:`flexshaft.files.writing`); returns the path."""
    path = Path(path)
    with writing(path, suffix=".nc") as tmp:
        ds.to_netcdf(tmp)
    return path
