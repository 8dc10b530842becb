"""A candidate whose evaluation raises is infeasible, even in a search without constraints.

Reference: docs/optimizer.md, "Constraints": "A candidate the schema refuses (...) is recorded
with the schema's message and is infeasible; so is one whose evaluation raises (its outputs are
NaN)"; and "pareto.nc  the feasible non-dominated designs".

Hand-built case (derived here): a stand-in evaluation of the wall w gives mass = 1000 w and
stiffness = 1000 w, and raises for w < 2 mm (a model that cannot be built). The search has no
constraint at all, so only the evaluation's failure can make a design infeasible. Mass
minimised and stiffness maximised conflict along w, so no valid design dominates another: the
feasible set is exactly the samples with w >= 2 mm and the Pareto set is all of them, by
increasing mass; the failed ones (NaN outputs) are in neither.

Cheap: analytic output function, 8 random candidates.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.optimize import DesignProblem, DesignVariable
from flexshaft.optimize.variables import Objective


def fails_below_two_mm(point):
    w = point.design.shaft.wall_thickness
    if w < 0.002:
        raise RuntimeError("stand-in: no model below a 2 mm wall")
    return {"mass": 1e3 * w, "stiffness": 1e3 * w}


def test_a_raising_evaluation_is_infeasible_without_constraints():
    pytest.importorskip("xarray")
    from flexshaft.optimize import optimize

    problem = DesignProblem(
        (DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall", units="m"),),
        objectives=(Objective("mass", "min", "mass"), Objective("stiffness", "max", "stiffness")),
        constraints=(),
        evaluate=fails_below_two_mm,
        outputs=(("mass", "kg", "1000 w"), ("stiffness", "1", "1000 w")),
        name="a failing stand-in",
    )
    result = optimize(problem, 8, None, seed=3, method="random")
    ev = result.evaluations
    walls = ev["wall"].values
    failed = walls < 0.002
    assert 0 < failed.sum() < walls.size  # both kinds among the samples (seed 3)
    assert np.all(np.isnan(ev["mass"].values[failed]))  # recorded with NaN outputs
    np.testing.assert_array_equal(ev["feasible"].values, (~failed).astype(np.int8))
    np.testing.assert_array_equal(result.pareto["wall"].values, np.sort(walls[~failed]))
