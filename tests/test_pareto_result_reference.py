"""The optimizer's result (optimize/result.py) on hand-made objective and margin tables.

References, worked by hand from the definitions (derived):

* Pareto dominance (minimised objectives): row j dominates row i when it is no worse in every
  objective and better in at least one; the front is the rows nothing dominates, duplicates of
  a front row all kept.
* The hypervolume of a two-objective front up to a reference point is the area of the union of
  the rectangles [f1, r1] × [f2, r2] of its points, a staircase summed by hand; a maximised
  objective enters negated (its "min" is −value).
* The blocking-checks table counts, over the valid candidates, those each constraint rejects
  (margin < 0 or not evaluated, NaN), those it alone rejects, the unevaluated ones and the best
  margin with its evaluation index; rows sorted by rejections, most first, and the invalid
  candidates (an error text) as a last "valid design" row.

No optimization runs: a stand-in problem (objectives and constraint names) and xarray datasets
built here. CPU about 0.2 s, nearly all of it xarray's first use in the process.
"""

from __future__ import annotations

import math
from types import SimpleNamespace as NS

import numpy as np
import pytest
import xarray as xr

from flexshaft.optimize.result import OptimizationResult, pareto_mask


def test_a_tie_in_one_objective_is_dominated_and_duplicates_are_kept():
    """(1, 3) ties (1, 2) in f1 and is worse in f2: dominated. (3, 3) is dominated by both
    front points. (2, 1) appears twice: both copies stay."""
    F = np.array([[1.0, 2.0], [1.0, 3.0], [2.0, 1.0], [3.0, 3.0], [2.0, 1.0]])
    assert pareto_mask(F).tolist() == [True, False, True, False, True]


def _problem(objectives, constraints=()):
    return NS(objectives=[NS(output=o, sense=s, label="") for o, s in objectives], constraints=list(constraints))


def test_a_maximised_objective_enters_the_hypervolume_negated():
    """Front: mass 2 kg with margin 0.5, mass 3 kg with margin 0.8 (min mass, max margin).

    Minimised: (2, −0.5), (3, −0.8). Reference (5, 0): the rectangles [2, 5] × [−0.5, 0]
    (area 3 · 0.5 = 1.5) and [3, 5] × [−0.8, 0] (area 2 · 0.8 = 1.6) overlap in
    [3, 5] × [−0.5, 0] (area 1.0): union 1.5 + 1.6 − 1.0 = 2.1.
    """
    pareto = xr.Dataset({"mass": ("design", [2.0, 3.0]), "margin": ("design", [0.5, 0.8])})
    result = OptimizationResult(_problem([("mass", "min"), ("margin", "max")]), evaluations=None, pareto=pareto)
    np.testing.assert_array_equal(result.minimised(), [[2.0, -0.5], [3.0, -0.8]])
    assert result.hypervolume((5.0, 0.0)) == pytest.approx(2.1, rel=1e-14)


def _evaluations():
    """Six candidates, margins (strength, buckling); NaN: not evaluated.

    e0  0.6, −0.1   buckling rejects (alone)
    e1 −0.3,  NaN   both reject (buckling: not evaluated)
    e2  0.5,  0.4   feasible
    e3  NaN,  NaN   schema refused it (error text): the "valid design" row
    e4 −0.1,  0.3   strength rejects (alone)
    e5  0.9, −0.2   buckling rejects (alone)
    """
    nan = math.nan
    return xr.Dataset(
        {
            "margin_strength": ("evaluation", [0.6, -0.3, 0.5, nan, -0.1, 0.9]),
            "margin_buckling": ("evaluation", [-0.1, nan, 0.4, nan, 0.3, -0.2]),
            "error": ("evaluation", ["", "", "", "shaft.wall_thickness: too thin", "", ""]),
        }
    )


def test_blocking_checks_counted_by_hand():
    """buckling rejects e0, e1 (NaN), e5: 3, alone e0 and e5: 2, not evaluated 1 (e1), best
    0.4 at e2. strength rejects e1, e4: 2, alone e4: 1, best 0.9 at e5 (the fifth valid one: the
    index counts the invalid e3). Then e3, invalid."""
    problem = _problem([("mass", "min")], ["margin_strength", "margin_buckling"])
    rows = OptimizationResult(problem, evaluations=_evaluations(), pareto=None).blocking_checks()
    assert [r["check"] for r in rows] == ["buckling", "strength", "valid design"]
    buckling, strength, invalid = rows
    assert (buckling["rejected"], buckling["alone"], buckling["not_evaluated"]) == (3, 2, 1)
    assert (buckling["best_margin"], buckling["best_evaluation"]) == (0.4, 2)
    assert (strength["rejected"], strength["alone"], strength["not_evaluated"]) == (2, 1, 0)
    assert (strength["best_margin"], strength["best_evaluation"]) == (0.9, 5)
    assert (invalid["rejected"], invalid["best_evaluation"]) == (1, -1) and math.isnan(invalid["best_margin"])


def test_an_infinite_margin_is_an_evaluated_pass():
    """A check "passed with nothing to measure" (docs/requirements.md, "The checks") has the
    normalised margin +inf: docs/magnetic-bearings.md's loop that "never crosses −180° (no gain
    margin limits it)". It is evaluated and passes: it rejects nothing, is not counted "not
    evaluated" (NaN only) and is the best margin. Hand count over e0 +inf, e1 NaN, e2 0.2:
    rejects 1 (e1, alone), not evaluated 1, best +inf at e0."""
    problem = _problem([("mass", "min")], ["margin_gain"])
    evaluations = xr.Dataset(
        {"margin_gain": ("evaluation", [math.inf, math.nan, 0.2]), "error": ("evaluation", ["", "", ""])}
    )
    (row,) = OptimizationResult(problem, evaluations=evaluations, pareto=None).blocking_checks()
    assert (row["rejected"], row["alone"], row["not_evaluated"]) == (1, 1, 1)
    assert row["best_margin"] == math.inf and row["best_evaluation"] == 0
