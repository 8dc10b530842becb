"""The explorer's Pareto front, read from a run folder written here by hand.

References (documented rules, not code output):

* docs/explorer.md (`--pareto FOLDER`): "a click loads a point's design", "the run's base with the
  point's overrides"; docs/optimizer.md: ``evaluations.nc`` holds every evaluation with its
  ``feasible`` flag, ``pareto.nc`` the feasible non-dominated designs.
* The fields the run folder's datasets hold beyond those, which docs/optimizer.md does not list,
  are those of the ``OptimizationResult`` docstring (src/flexshaft/optimize/result.py), whose
  ``evaluations`` and ``pareto`` are the datasets written as ``evaluations.nc`` and ``pareto.nc``:
  evaluations "Every candidate evaluated (dimension ``evaluation``): variable values, outputs,
  ``feasible``, ``constraint_violation``, ``generation``, ``overrides`` (JSON), ``error``";
  pareto "The feasible non-dominated candidates (dimension ``design``, sorted by the first
  objective), the same variables, and ``evaluation`` (index into ``evaluations``)". So Pareto
  point k's design is the base changed by exactly the overrides stored with point k of
  ``pareto.nc`` (not those of evaluation k), and the figure's feasibility flags are the run's own.
* The page receives the data as JSON through Starlette's ``JSONResponse``, which serialises with
  ``allow_nan=False`` (read in starlette/responses.py): a failed evaluation's NaN objective must
  reach the page as null, never as NaN.

The run folder is tiny (four evaluations, two on the front) and written without running the
optimizer. It holds only the fields :func:`read_front` reads (problem.json's name, objectives and
base; each dataset's two objectives; the evaluations' ``feasible``; the front's ``overrides``)
plus the evaluations' ``overrides`` and the front's ``evaluation`` index, so that a point read
from the wrong dataset shows; the other documented fields (min_margin, limiting_check,
constraint_violation, generation; problem.json's variables, constraints and seed) are left out.
The front is in the order the optimizer writes it, ascending in the first objective (shaft mass
5.5 kg then 6.0 kg, forces 120 N then 100 N: neither dominates the other), which is not the
evaluations' order (evaluation 2, then evaluation 0). Values are compared exactly: they are
copied, not computed (a float64 round trip through netCDF is exact).

Which objective the page puts on the horizontal axis is not a documented rule: the tests below
read each axis's values under the objective name the data gives that axis.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr

from flexshaft.design import baseline_design
from flexshaft.explore.pareto import front_design, read_front
from flexshaft.netcdf import write_netcdf

#: overrides of the four evaluations; evaluation 1 is infeasible, evaluation 3 failed (NaN)
_OVERRIDES = [
    {"bearings[1].kp": 3.0e5, "shaft.wall_thickness": 0.0021},
    {"bearings[1].kp": 4.0e5, "shaft.wall_thickness": 0.0022},
    {"bearings[1].kp": 5.0e5, "shaft.wall_thickness": 0.0023},
    {"bearings[1].kp": 6.0e5, "shaft.wall_thickness": 0.0024},
]
_MASS = [6.0, 5.0, 5.5, np.nan]
_FORCE = [100.0, 90.0, 120.0, np.nan]
_FEASIBLE = [1, 0, 1, 0]
#: the front: evaluation 2 (5.5 kg, 120 N), then evaluation 0 (6.0 kg, 100 N), ascending in
#: mass as the optimizer writes it; evaluation 1 (5.0 kg, 90 N) dominates both but is infeasible
_FRONT = [2, 0]


def _run_folder(folder):
    base = baseline_design()
    folder.mkdir()
    spec = {
        "name": "hand-written run",
        "objectives": [["shaft_mass", "min"], ["actuator_force", "min"]],
        "base": json.loads(base.model_dump_json()),
    }
    (folder / "problem.json").write_text(json.dumps(spec), encoding="utf-8")
    ev = xr.Dataset(
        {
            "shaft_mass": ("evaluation", np.array(_MASS)),
            "actuator_force": ("evaluation", np.array(_FORCE)),
            "feasible": ("evaluation", np.array(_FEASIBLE, dtype=np.int8)),
            "overrides": ("evaluation", np.array([json.dumps(o, sort_keys=True) for o in _OVERRIDES], dtype=str)),
        },
        coords={"evaluation": np.arange(4)},
    )
    pa = xr.Dataset(
        {
            "shaft_mass": ("design", np.array([_MASS[k] for k in _FRONT])),
            "actuator_force": ("design", np.array([_FORCE[k] for k in _FRONT])),
            "overrides": ("design", np.array([json.dumps(_OVERRIDES[k], sort_keys=True) for k in _FRONT], dtype=str)),
            "evaluation": ("design", np.array(_FRONT)),
        },
        coords={"design": np.arange(len(_FRONT))},
    )
    write_netcdf(ev, folder / "evaluations.nc")
    write_netcdf(pa, folder / "pareto.nc")
    return base


def test_a_front_point_is_the_base_with_that_points_overrides(tmp_path):
    """Point 0 of the front is evaluation 2: its design has evaluation 2's K_p and wall (not
    evaluation 0's, nor the base's 1e7 N/m and 3 mm), and every field not overridden is the base's;
    the front is plotted as (5.5 kg, 120 N), (6.0 kg, 100 N), the order of pareto.nc."""
    base = _run_folder(tmp_path / "run")
    front = read_front(tmp_path / "run")
    for point, k in enumerate(_FRONT):
        design, overrides = front_design(front, point)
        assert overrides == _OVERRIDES[k]
        assert design.bearings[1].kp == _OVERRIDES[k]["bearings[1].kp"]
        assert design.shaft.wall_thickness == _OVERRIDES[k]["shaft.wall_thickness"]
        assert design.bearings[2].kp == base.bearings[2].kp
        assert design.shaft.layup == base.shaft.layup
    pareto = front.data["pareto"]
    by_name = {"shaft_mass": [5.5, 6.0], "actuator_force": [120.0, 100.0]}
    assert (pareto["x"], pareto["y"]) == (by_name[front.data["x"]], by_name[front.data["y"]])


def test_the_figure_keeps_feasibility_and_sends_no_nan(tmp_path):
    """The evaluations' feasibility flags are the run's (1, 0, 1, 0: the infeasible and the failed
    evaluation are not drawn as feasible); the failed evaluation's NaN objectives become null, and
    the whole page data serialises as strict JSON (no NaN), as Starlette sends it."""
    _run_folder(tmp_path / "run")
    data = read_front(tmp_path / "run").data
    assert data["evaluations"]["feasible"] == [True, False, True, False]
    by_name = {"shaft_mass": [6.0, 5.0, 5.5, None], "actuator_force": [100.0, 90.0, 120.0, None]}
    assert {data["x"], data["y"]} == set(by_name)
    assert data["evaluations"]["x"] == by_name[data["x"]]
    assert data["evaluations"]["y"] == by_name[data["y"]]
    text = json.dumps(data, allow_nan=False)  # raises ValueError on a NaN
    assert json.loads(text)["evaluations"]["x"][3] is None


@pytest.mark.parametrize("index", [2, -1, "0", None, True, False, 1.0])
def test_an_index_off_the_front_is_refused(tmp_path, index):
    """The front has two points: 0 and 1 are the only indices (a JSON string, null, a negative
    index or 2 is named in the refusal, never read from the end of the list; JSON's true and
    false, which Python's bool makes the integers 1 and 0, and a number 1.0 are no index
    either: a hand-made request {"index": true} loaded point 1, review h107c)."""
    from flexshaft.design import DesignError

    _run_folder(tmp_path / "run")
    front = read_front(tmp_path / "run")
    with pytest.raises(DesignError, match="no Pareto point"):
        front_design(front, index)
