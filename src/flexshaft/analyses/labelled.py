"""Labelled plain arrays: the part of an :class:`xarray.Dataset` that study results travel in.

Importing xarray and building a first Dataset costs 0.5-0.6 s of CPU (pandas, and the optional
array back-ends such as dask when installed). The studies of ``flexshaft run`` compute in worker
processes, send their results to the report and read them with ``ds["name"].values``,
``ds.coord.values`` and a nearest-point ``sel``: none of that needs xarray. A
:class:`LabelledArrays` holds the same variables, coordinates and attributes as the Dataset it
stands for (built from the same ``(dims, values, attrs)`` tuples), pickles without xarray, and
becomes that Dataset with :meth:`LabelledArrays.to_dataset` (xarray imported then, where a
Dataset is written or asked for). Any other Dataset attribute (``to_netcdf``, ``isel``,
``to_dataframe``...) is looked up on that Dataset, built once.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from typing import Any

import numpy as np

__all__ = ["LabelledArray", "LabelledArrays"]


def _nearest(coord: np.ndarray, value: Any) -> int:
    """Index of the coordinate value nearest ``value`` (xarray's ``method="nearest"``)."""
    return int(np.argmin(np.abs(np.asarray(coord, dtype=float) - float(value))))


class LabelledArray:
    """One variable or coordinate: ``values`` over named ``dims``, with ``attrs``.

    ``coords`` maps each dimension that has a coordinate to its values (for :meth:`sel`).
    """

    __slots__ = ("attrs", "coords", "dims", "values")

    def __init__(
        self, dims: tuple[str, ...], values: Any, attrs: Mapping[str, Any] | None = None, coords: Mapping | None = None
    ) -> None:
        self.values: np.ndarray = np.asarray(values)
        self.dims: tuple[str, ...] = tuple(dims)
        if len(self.dims) != self.values.ndim:
            raise ValueError(f"dims {self.dims} do not match values of shape {self.values.shape}")
        self.attrs: dict[str, Any] = dict(attrs or {})
        self.coords: dict[str, np.ndarray] = dict(coords or {})

    @property
    def ndim(self) -> int:
        return self.values.ndim

    @property
    def shape(self) -> tuple[int, ...]:
        return self.values.shape

    @property
    def sizes(self) -> dict[str, int]:
        return dict(zip(self.dims, self.values.shape))

    def __len__(self) -> int:
        return len(self.values)

    def __array__(self, dtype: Any = None, copy: bool | None = None) -> np.ndarray:
        return self.values if dtype is None else self.values.astype(dtype)

    def __float__(self) -> float:
        return float(self.values)

    def __int__(self) -> int:
        return int(self.values)

    def __bool__(self) -> bool:
        return bool(self.values)

    def __getitem__(self, key: Any) -> Any:
        """Positional indexing of the values (plain numpy)."""
        return self.values[key]

    def sel(self, indexers: Mapping[str, Any] | None = None, method: str = "nearest", **kw: Any) -> LabelledArray:
        """The values at the coordinate values nearest those given, the selected dimensions
        dropped (xarray's ``sel(..., method="nearest")``; no other method)."""
        if method != "nearest":
            raise ValueError(f"method: only 'nearest' is supported here, got {method!r} (use .to_dataset())")
        picks = {**(indexers or {}), **kw}
        index: list[Any] = []
        for dim in self.dims:
            index.append(_nearest(self.coords[dim], picks.pop(dim)) if dim in picks else slice(None))
        if picks:
            raise KeyError(f"no dimension {sorted(picks)} among {self.dims}")
        kept = tuple(d for d in self.dims if not isinstance(index[self.dims.index(d)], int))
        return LabelledArray(
            kept, self.values[tuple(index)], self.attrs, {d: self.coords[d] for d in kept if d in self.coords}
        )

    def __repr__(self) -> str:
        return f"LabelledArray(dims={self.dims}, shape={self.shape}, attrs={sorted(self.attrs)})"


class LabelledArrays(Mapping[str, LabelledArray]):
    """Variables and coordinates as plain arrays, with attributes: an :class:`xarray.Dataset`'s
    content without xarray.

    Parameters
    ----------
    data_vars : mapping
        ``name -> (dims, values[, attrs])``, as for ``xarray.Dataset``.
    coords : mapping
        ``name -> (dim, values[, attrs])``, or ``name -> values`` (the dimension of that name).
    attrs : mapping, optional
        Global attributes.
    """

    def __init__(
        self, data_vars: Mapping[str, tuple], coords: Mapping[str, Any] | None = None, attrs: Mapping | None = None
    ) -> None:
        self._spec = (dict(data_vars), dict(coords or {}))
        self.attrs: dict[str, Any] = dict(attrs or {})
        self._coords: dict[str, LabelledArray] = {}
        for name, spec in (coords or {}).items():
            dims, values, *extra = spec if isinstance(spec, tuple) else (name, spec)
            dims = (dims,) if isinstance(dims, str) else tuple(dims)
            cattrs = extra[0] if extra else {}
            coord = LabelledArray(dims, values, cattrs)
            self._coords[name] = coord
        axes = {name: c.values for name, c in self._coords.items() if c.dims == (name,)}
        for coord in self._coords.values():  # every coordinate selects on its dimensions' axes
            coord.coords.update({d: axes[d] for d in coord.dims if d in axes})
        self._vars: dict[str, LabelledArray] = {}
        for name, spec in data_vars.items():
            dims, values, *rest = spec
            dims = (dims,) if isinstance(dims, str) else tuple(dims)
            self._vars[name] = LabelledArray(
                dims, values, rest[0] if rest else {}, {d: axes[d] for d in dims if d in axes}
            )
        self._dataset: Any = None

    # the Mapping of the data variables (as a Dataset's)
    def __getitem__(self, name: str) -> LabelledArray:
        if name in self._vars:
            return self._vars[name]
        if name in self._coords:
            return self._coords[name]
        raise KeyError(f"no variable or coordinate {name!r}; variables: {sorted(self._vars)}")

    def __iter__(self) -> Iterator[str]:
        return iter(self._vars)

    def __len__(self) -> int:
        return len(self._vars)

    @property
    def data_vars(self) -> dict[str, LabelledArray]:
        return dict(self._vars)

    @property
    def coords(self) -> dict[str, LabelledArray]:
        return dict(self._coords)

    @property
    def sizes(self) -> dict[str, int]:
        out: dict[str, int] = {}
        for v in (*self._coords.values(), *self._vars.values()):
            out.update(v.sizes)
        return out

    dims = sizes

    def sel(self, indexers: Mapping[str, Any] | None = None, method: str = "nearest", **kw: Any) -> LabelledArrays:
        """Every variable at the nearest coordinate values (see :meth:`LabelledArray.sel`)."""
        picks = {**(indexers or {}), **kw}
        unknown = sorted(set(picks) - set(self.sizes))
        if unknown:
            raise KeyError(f"no dimension {unknown} among {sorted(self.sizes)}")
        data = {}
        for name, v in self._vars.items():
            s = v.sel({d: x for d, x in picks.items() if d in v.dims}, method=method)
            data[name] = (s.dims, s.values, s.attrs)
        coords = {}
        for name, c in self._coords.items():
            s = c.sel({d: x for d, x in picks.items() if d in c.dims}, method=method)
            coords[name] = (s.dims, s.values, s.attrs)
        return LabelledArrays(data, coords, self.attrs)

    def to_dataset(self) -> Any:
        """The :class:`xarray.Dataset` these arrays stand for (imports xarray; built once)."""
        if self._dataset is None:
            import xarray as xr  # here, not above: xarray costs 0.5-0.6 s to import

            data_vars, coords = self._spec
            self._dataset = xr.Dataset(data_vars, coords=coords, attrs=self.attrs)
        return self._dataset

    def __getattr__(self, name: str) -> Any:
        # coordinates and variables by name, as a Dataset's; then any other Dataset attribute
        if name.startswith("_"):  # pickling, copying and numpy probe dunders: never the Dataset
            raise AttributeError(name)
        for table in ("_vars", "_coords"):
            found = self.__dict__.get(table, {})
            if name in found:
                return found[name]
        return getattr(self.to_dataset(), name)

    def __getstate__(self) -> dict[str, Any]:
        return {**self.__dict__, "_dataset": None}  # plain arrays only: no xarray needed to unpickle

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.__dict__.update(state)

    def __repr__(self) -> str:
        dims = ", ".join(f"{d}: {n}" for d, n in self.sizes.items())
        return f"LabelledArrays({dims}; variables {list(self._vars)}; title {self.attrs.get('title', '')!r})"
