"""The optimizer's Pareto front, read from a ``flexshaft optimize`` run folder, for the explorer.

A run folder holds ``problem.json`` (the search: its base design, variables and objectives),
``evaluations.nc`` (every candidate: objectives, feasibility, the overrides of the base as JSON)
and ``pareto.nc`` (the feasible non-dominated ones), see :mod:`flexshaft.optimize.store`.
:func:`read_front` turns them into JSON for the page's figure; a point's design is the base with
its overrides (:func:`front_design`), validated by the schema like every other design.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft.design import Design, DesignError, Problem, design_from_dict, with_overrides
from flexshaft.optimize.nsga import MANIFEST
from flexshaft.optimize.variables import DESIGN_OBJECTIVES

__all__ = ["Front", "front_design", "read_front"]

_EVALUATIONS = "evaluations.nc"
_PARETO = "pareto.nc"


@dataclass(frozen=True)
class Front:
    """An optimizer run read for the page: its base design and the figure's data."""

    folder: Path
    base: Design
    data: dict[str, Any]


def _problem(folder: Path, message: str) -> DesignError:
    return DesignError([Problem(str(folder), message)], str(folder))


def _floats(values) -> list[float | None]:
    return [float(v) if math.isfinite(float(v)) else None for v in np.asarray(values, dtype=float)]


def read_front(folder: str | Path) -> Front:
    """The Pareto front and every evaluation of the optimizer run in ``folder``.

    Raises
    ------
    DesignError
        When the folder is not a finished optimizer run (naming the file missing or unreadable),
        or its base design is invalid.
    """
    import xarray  # heavy (about 0.5 s): only a page that loads a front needs it

    folder = Path(folder)
    for name in (MANIFEST, _EVALUATIONS, _PARETO):
        if not (folder / name).is_file():
            raise _problem(folder, f"not a finished `flexshaft optimize` run folder: {name} is missing")
    try:
        spec = json.loads((folder / MANIFEST).read_text(encoding="utf-8"))
        base = design_from_dict(spec["base"], f"{folder / MANIFEST} (base design)")
        objectives = [str(o[0]) for o in spec["objectives"]]
        with xarray.open_dataset(folder / _EVALUATIONS) as ev, xarray.open_dataset(folder / _PARETO) as pa:
            ev, pa = ev.load(), pa.load()
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise _problem(folder, f"cannot read the optimizer run ({exc})") from None
    x, y = (objectives + objectives)[:2]

    def label(name: str) -> str:
        objective = DESIGN_OBJECTIVES.get(name)
        return objective.label if objective is not None and objective.label else name

    data = {
        "folder": str(folder),
        "name": str(spec.get("name", folder.name)),
        "x": x,
        "y": y,
        "x_label": label(x),
        "y_label": label(y),
        "evaluations": {
            "x": _floats(ev[x].values),
            "y": _floats(ev[y].values),
            "feasible": [bool(v) for v in np.asarray(ev["feasible"].values)],
        },
        "pareto": {
            "x": _floats(pa[x].values),
            "y": _floats(pa[y].values),
            "overrides": [json.loads(str(v)) for v in pa["overrides"].values],
        },
    }
    return Front(folder, base, data)


def front_design(front: Front, index: object) -> tuple[Design, dict[str, Any]]:
    """The design of Pareto point ``index`` (any JSON value: checked here) and its overrides of the base.

    Raises
    ------
    DesignError
        For an index off the front, or overrides the schema refuses.
    """
    points = front.data["pareto"]["overrides"]
    if type(index) is not int or not 0 <= index < len(points):  # bool is an int subclass: JSON's true is no index
        raise _problem(front.folder, f"no Pareto point {index!r} (the front has {len(points)})")
    overrides = dict(points[index])
    return with_overrides(front.base, overrides), overrides
