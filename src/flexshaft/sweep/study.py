"""What a sweep is: design variables and special axes × named outputs.

A :class:`Study` is the full-factorial grid of its :class:`Variable` values. A variable is a
**design variable** when it names a design-file field (``path="shaft.wall_thickness"``) or maps
its value to overrides (``overrides=ply_angle_layup``); otherwise it is a **special axis**
(speed, a load case, an analysis option) whose value is handed to the output function. The
output function takes a :class:`Point` and returns a mapping of the declared output names to
floats. Everything in a study must be picklable (module-level functions) to run in worker
processes or on a Dask cluster.
"""

from __future__ import annotations

import functools
import hashlib
import json
import math
import pickle
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, baseline_design, with_overrides
from flexshaft.design.io import path_replaces
from flexshaft.parallel.point_label import at_point
from flexshaft.parallel.threads import one_blas_thread

__all__ = ["DesignModel", "Output", "Point", "Study", "SweepError", "SweepWarning", "Variable"]

# Validate every combination of design values up front when there are at most this many.
_VALIDATE_ALL_LIMIT = 20_000


class SweepError(ValueError):
    """A study that cannot run: bad variable, value, output or run folder."""


class DifferentStudyError(SweepError):
    """The run folder holds the chunks of another study (other options, values or outputs):
    they are never mixed with this one's (:func:`flexshaft.sweep.store.start_afresh` moves them
    aside). ``held`` names the stored study (its name and fingerprint)."""

    def __init__(self, message: str, held: str = "") -> None:
        super().__init__(message)
        self.held = held


class SweepWarning(UserWarning):
    """Stored results that were not reused (named, with the reason) and are recomputed."""


def _plain(value: Any) -> Any:
    """numpy scalars to Python scalars (for JSON, overrides and netCDF coordinates)."""
    if isinstance(value, np.generic):
        return value.item()
    return value


def _qualname(func: Callable | None) -> str | None:
    """The callable's name for the study's fingerprint: ``module.qualname``; a
    :func:`functools.partial` by its function's name and its bound arguments (its own repr
    holds its memory address, which would make every run's fingerprint another): their reprs
    when every one is plain (:func:`_is_plain`: the repr is then the value), else the SHA-256 of
    their pickle (an array's repr elides its middle above 1000 numbers: two partials of
    different arrays would fingerprint alike and share a run folder's chunks)."""
    if func is None:
        return None
    if isinstance(func, functools.partial):
        keywords = sorted(func.keywords.items())
        if all(map(_is_plain, (*func.args, *(v for _, v in keywords)))):
            bound = ", ".join([*map(repr, func.args), *(f"{k}={v!r}" for k, v in keywords)])
        else:
            bound = "pickle sha256 " + hashlib.sha256(pickle.dumps((func.args, keywords), protocol=4)).hexdigest()
        return f"functools.partial({_qualname(func.func)}, {bound})"
    return f"{getattr(func, '__module__', '?')}.{getattr(func, '__qualname__', repr(func))}"


def _is_plain(value: Any) -> bool:
    """Whether ``value``'s repr is the whole value: None, a bool, int, float or str, or a tuple
    or list of such values."""
    if isinstance(value, (tuple, list)):
        return all(map(_is_plain, value))
    return value is None or isinstance(value, (bool, int, float, str))


@dataclass(frozen=True)
class Variable:
    """One axis of a sweep.

    Parameters
    ----------
    name : str
        Dimension name in the results (defaults to ``path``); a valid identifier is advised.
    values : sequence
        The values swept (numbers or strings), in order.
    path : str, optional
        Design-file field set to each value, e.g. ``"bearings[1].kp"`` (see
        :func:`flexshaft.design.with_overrides`).
    overrides : callable, optional
        ``value -> {path: value, ...}`` for a variable that sets several fields or a derived
        one (e.g. a ply angle into a layup string). Must be a module-level function, or a
        :func:`functools.partial` of one with plain arguments (numbers, strings, tuples of
        them): the study's fingerprint names it by its function and its arguments.
    units : str
        Units of the values, stored in the results' attributes (SI).
    long_name : str
        Human-readable description.
    """

    name: str = ""  # "": the path (set in __post_init__)
    values: Sequence[Any] = ()
    path: str | None = None
    overrides: Callable[[Any], Mapping[str, Any]] | None = None
    units: str = ""
    long_name: str = ""

    def __post_init__(self) -> None:
        name = self.name or self.path
        if not name or not isinstance(name, str):
            raise SweepError("a sweep variable needs a name or a design path")
        object.__setattr__(self, "name", name)
        values = tuple(_plain(v) for v in np.atleast_1d(np.asarray(self.values, dtype=object)).tolist())
        if not values:
            raise SweepError(f"variable {name!r}: no values to sweep")
        for v in values:
            if isinstance(v, float) and not math.isfinite(v):
                raise SweepError(f"variable {name!r}: values must be finite (got {v!r})")
        object.__setattr__(self, "values", values)
        if self.path is not None and self.overrides is not None:
            raise SweepError(f"variable {name!r}: give either a design path or an overrides function, not both")

    @property
    def is_design(self) -> bool:
        """True when the variable changes the design (and so the model)."""
        return self.path is not None or self.overrides is not None

    def design_overrides(self, value: Any) -> dict[str, Any]:
        """Design-file overrides for one value (empty for a special axis)."""
        if self.path is not None:
            return {self.path: value}
        if self.overrides is not None:
            return dict(self.overrides(value))
        return {}

    def spec(self) -> dict:
        return {
            "name": self.name,
            "values": list(self.values),
            "path": self.path,
            "overrides": _qualname(self.overrides),
            "units": self.units,
            "long_name": self.long_name,
        }


@dataclass(frozen=True)
class Output:
    """A named float result of every point, with its unit (SI)."""

    name: str
    units: str = ""
    long_name: str = ""


@dataclass
class Point:
    """One grid point as seen by the output function.

    Attributes
    ----------
    index : int
        Flat (C-order) index in the grid.
    values : dict
        Every variable's value by name.
    axes : dict
        The special (non-design) variables' values by name, e.g. ``{"speed": 300.0}``.
    design : Design
        The validated design of this point.
    """

    index: int
    values: dict[str, Any]
    axes: dict[str, Any]
    design: Any
    shared: DesignModel | None = field(default=None, repr=False)

    @property
    def model(self):
        """The assembled model of ``design`` (built once per design within a chunk: the points
        of a chunk with one design share its :class:`DesignModel`)."""
        if self.shared is None:
            self.shared = DesignModel(self.design)
        return self.shared.model


class DesignModel:
    """A design and its model, built on first use (:func:`functools.cached_property`)."""

    def __init__(self, design) -> None:
        self.design = design

    @functools.cached_property
    def model(self):
        return build_model(self.design)


@dataclass(frozen=True)
class Study:
    """A full-factorial sweep: ``variables`` × ``outputs`` computed by ``evaluate``.

    Parameters
    ----------
    name : str
        Title stored in the results.
    variables : sequence of Variable
        Grid axes, outermost first.
    outputs : sequence of Output
        Names (and units) that ``evaluate`` returns.
    evaluate : callable
        ``evaluate(point: Point) -> Mapping[str, float]``; module-level for parallel runs.
    base : Design, optional
        Design every point starts from (default: the embedded thesis baseline).
    fixed : mapping, optional
        Overrides applied to ``base`` at every point, before the variables'; a path a variable
        would replace (:func:`~flexshaft.design.io.path_replaces`) is refused by :meth:`validate`.
    """

    name: str
    variables: tuple[Variable, ...]
    outputs: tuple[Output, ...]
    evaluate: Callable[[Point], Mapping[str, float]]
    base: Any = None
    fixed: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "variables", tuple(self.variables))
        object.__setattr__(self, "outputs", tuple(Output(o) if isinstance(o, str) else o for o in self.outputs))
        object.__setattr__(self, "fixed", dict(self.fixed))
        if self.base is None:
            object.__setattr__(self, "base", baseline_design())
        names = [v.name for v in self.variables]
        if len(set(names)) != len(names):
            raise SweepError(f"variable names must be unique, got {names}")
        outs = [o.name for o in self.outputs]
        if not outs:
            raise SweepError("a study needs at least one output")
        if len(set(outs)) != len(outs) or set(outs) & set(names):
            raise SweepError(f"output names must be unique and differ from the variables, got {outs}")
        if not callable(self.evaluate):
            raise SweepError("evaluate must be callable: evaluate(point) -> {output: float}")

    # -- grid -------------------------------------------------------------------------------
    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(v.values) for v in self.variables)

    @property
    def size(self) -> int:
        return int(np.prod(self.shape, dtype=np.int64))

    def values_at(self, index: int) -> dict[str, Any]:
        """Every variable's value at flat grid index ``index``."""
        idx = np.unravel_index(index, self.shape) if self.shape else ()
        return {v.name: v.values[int(i)] for v, i in zip(self.variables, idx)}

    def overrides_at(self, values: Mapping[str, Any]) -> dict[str, Any]:
        out = dict(self.fixed)
        for v in self.variables:
            if v.name in values:
                out.update(v.design_overrides(values[v.name]))
        return out

    def design_at(self, values: Mapping[str, Any]):
        """The validated design of a point (raises :class:`SweepError` naming the field)."""

        overrides = self.overrides_at(values)
        if not overrides:
            return self.base
        try:
            return with_overrides(self.base, overrides)
        except DesignError as exc:
            shown = ", ".join(f"{k} = {v!r}" for k, v in values.items() if k in self._design_names)
            raise SweepError(
                f"study {self.name!r}: invalid design at {shown or 'the fixed overrides'}:\n{exc}"
            ) from exc

    @functools.cached_property
    def _design_names(self) -> frozenset[str]:
        return frozenset(v.name for v in self.variables if v.is_design)

    # -- checks -----------------------------------------------------------------------------
    def validate(self) -> None:
        """Check every variable path and value against the design schema, before computing.

        Every combination of the design variables is validated when there are at most
        20 000 of them (about 0.2 ms each); otherwise each variable's values one at a time.
        """
        design_vars = [v for v in self.variables if v.is_design]
        self.design_at({})  # the fixed overrides alone
        setter = dict.fromkeys(self.fixed, "the fixed overrides")  # who sets each design path
        for v in design_vars:
            for value in v.values:
                try:
                    overrides = v.design_overrides(value)
                except Exception as exc:  # the user's mapping function failed on a value
                    raise SweepError(f"variable {v.name!r}: cannot map value {value!r} to overrides: {exc}") from exc
                if not isinstance(overrides, Mapping):
                    raise SweepError(
                        f"variable {v.name!r}: overrides({value!r}) must return a mapping of path to value"
                    )
                _claim_paths(setter, overrides, f"variable {v.name!r}")
                self.design_at({v.name: value})
        n_combos = int(np.prod([len(v.values) for v in design_vars], dtype=np.int64)) if design_vars else 1
        if 1 < n_combos <= _VALIDATE_ALL_LIMIT and len(design_vars) > 1:
            for combo in np.ndindex(*[len(v.values) for v in design_vars]):
                self.design_at({v.name: v.values[i] for v, i in zip(design_vars, combo)})

    # -- identity ---------------------------------------------------------------------------
    def spec(self) -> dict:
        """JSON-able description; equal specs compute equal results."""
        return {
            "name": self.name,
            "variables": [v.spec() for v in self.variables],
            "outputs": [[o.name, o.units, o.long_name] for o in self.outputs],
            "evaluate": _qualname(self.evaluate),
            "fixed": {k: _plain(v) for k, v in self.fixed.items()},
            "base": json.loads(self.base.model_dump_json()),
        }

    def fingerprint(self) -> str:
        text = json.dumps(self.spec(), sort_keys=True, default=repr)
        return hashlib.sha256(text.encode()).hexdigest()


def _claim_paths(setter: dict[str, str], overrides: Mapping[str, Any], who: str) -> None:
    """Record that ``who`` sets ``overrides``' design paths; refuse one that replaces what
    another set before (:func:`~flexshaft.design.io.path_replaces`: the same field however
    written, or a table holding it; a key inside a table set before refines it).

    Overrides are applied fixed first, then the variables in order, so a path set twice takes
    the last value: a fixed value would be shown in the results but never used, a variable
    would be a grid axis that changes nothing.
    """
    for path in overrides:
        for known, other in setter.items():
            if other != who and path_replaces(path, known):
                same = "" if path == known else f" (over {known!r})"
                raise SweepError(
                    f"design path {path!r}{same} is set by both {other} and {who}: the last would "
                    "silently override the other at every point; set each path in one place"
                )
        setter.setdefault(path, who)


def evaluate_chunk(study: Study, start: int, stop: int, on_error: str = "raise") -> np.ndarray:
    """Outputs of grid points ``start..stop-1``: float64 (stop − start, n_outputs).

    Runs with one BLAS thread; the model is built once per distinct design (consecutive
    points differing only in special axes share it). flexshaft's warnings raised while a point
    is evaluated (a response near an undamped resonance, a problem size) name the point
    (:mod:`flexshaft.parallel.point_label`, :func:`_point_label`).
    """

    names = [o.name for o in study.outputs]
    out = np.full((stop - start, len(names)), np.nan)
    last_key, shared = None, None
    with one_blas_thread():
        for row, index in enumerate(range(start, stop)):
            values = study.values_at(index)
            key = tuple(values[v.name] for v in study.variables if v.is_design)
            if key != last_key:
                last_key, shared = key, DesignModel(study.design_at(values))
            assert shared is not None  # built at the first point: its key differs from None
            point = Point(
                index=index,
                values=values,
                axes={v.name: values[v.name] for v in study.variables if not v.is_design},
                design=shared.design,
                shared=shared,
            )
            try:
                with at_point(_point_label(study, values)):
                    result = study.evaluate(point)
            except Exception:
                if on_error == "nan":
                    continue
                raise
            missing = [n for n in names if n not in result]
            extra = [n for n in result if n not in names]
            if missing or extra:
                raise SweepError(
                    f"study {study.name!r}: evaluate returned outputs {sorted(result)}; "
                    f"missing {missing}, undeclared {extra}"
                )
            out[row] = [float(result[n]) for n in names]
    return out


def _point_label(study: Study, values: Mapping[str, Any]) -> str:
    """A point as its warnings name it: ``name = value`` of the variables that take more than one
    value in ``study`` (all of them if none does); an optimizer's candidate is its JSON overrides."""
    varying = [v.name for v in study.variables if len(v.values) > 1] or [v.name for v in study.variables]
    return ", ".join(f"{name} = {values[name]}" for name in varying)
