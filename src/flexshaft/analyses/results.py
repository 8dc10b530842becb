"""What every result object shares: ``.plot()``, ``.to_dataset()``, ``.save()``.

A result (modes, Campbell diagram, stability, response, strength, thermal, spin-up map,
verdict) keeps its data in SI units. ``.to_dataset()`` gives an :class:`xarray.Dataset` with
CF-style attributes (``units``, ``long_name``; coded labels as integers with ``flag_values``
and ``flag_meanings``; a ``Conventions`` attribute), ``.save(path)`` writes it to netCDF
(netCDF3 through scipy unless netCDF4 is installed), and ``.plot(ax=None, **kw)`` converts the
data to engineering units and hands them to a figure function of :mod:`flexshaft.plot`
(imported only then), returning the matplotlib figure. xarray and matplotlib are imported
lazily.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft import __version__
from flexshaft.netcdf import write_netcdf

__all__ = ["CONVENTIONS", "ResultMixin", "coded", "new_dataset"]

#: The ``Conventions`` attribute of every dataset the package writes.
CONVENTIONS = "CF-1.10"


def coded(labels, meanings: Sequence[str], long_name: str) -> tuple[np.ndarray, dict]:
    """Integer codes of string ``labels`` with CF ``flag_values``/``flag_meanings`` attributes.

    Unknown labels raise ``ValueError``; meanings must not contain spaces (CF).
    """
    labels = np.asarray(labels, dtype=str)
    lookup = {m: k for k, m in enumerate(meanings)}
    unknown = sorted(set(np.unique(labels)) - set(lookup))
    if unknown:
        raise ValueError(f"labels {unknown} are not among {list(meanings)}")
    codes = np.vectorize(lookup.__getitem__, otypes=[np.int8])(labels) if labels.size else labels.astype(np.int8)
    attrs = {
        "long_name": long_name,
        "flag_values": np.arange(len(meanings), dtype=np.int8),
        "flag_meanings": " ".join(meanings),
    }
    return codes, attrs


def new_dataset(variables: dict, coords: dict, title: str, **attrs: Any):
    """An :class:`xarray.Dataset` with the package's global attributes."""
    import xarray as xr

    return xr.Dataset(
        variables,
        coords=coords,
        attrs={"Conventions": CONVENTIONS, "title": title, "source": f"flexshaft {__version__}", **attrs},
    )


class ResultMixin:
    """``.plot()`` through :mod:`flexshaft.plot`, ``.save()`` through ``.to_dataset()``."""

    #: ``kind -> name of the method that draws it``; the first entry is the default.
    plots: dict[str, str] = {}

    def to_dataset(self):  # pragma: no cover - every result defines it
        raise NotImplementedError

    def save(self, path: str | Path) -> Path:
        """Write :meth:`to_dataset` to a netCDF file at ``path``; returns the path."""

        path = Path(path)
        write_netcdf(self.to_dataset(), path)
        return path

    def plot(self, kind: str | None = None, ax=None, **kwargs):
        """Draw the result (``kind`` selects the figure when it has several); returns the figure.

        ``ax`` draws into an existing matplotlib axes (its figure is returned); keyword
        arguments go to the plotting function of :mod:`flexshaft.plot`.
        """
        if not self.plots:
            raise TypeError(f"{type(self).__name__} has no plot")
        kind = kind or next(iter(self.plots))
        if kind not in self.plots:
            raise ValueError(f"kind must be one of {sorted(self.plots)} (got {kind!r})")
        return getattr(self, self.plots[kind])(ax=ax, **kwargs)
