"""Atomic netCDF writing for every dataset the package saves.

netCDF4 (HDF5) when the optional ``netCDF4`` package is installed, otherwise netCDF3 through
scipy, xarray's default engines; the file appears only once complete (temporary file, then
``os.replace``).
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

__all__ = ["write_netcdf"]


def write_netcdf(ds, path: str | os.PathLike) -> Path:
    """Write the :class:`xarray.Dataset` ``ds`` to ``path`` atomically; returns the path."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".tmp-", suffix=".nc")
    os.close(fd)
    try:
        ds.to_netcdf(tmp)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return path
