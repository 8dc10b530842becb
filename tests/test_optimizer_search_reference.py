"""The optimizer's search space, Pareto indicators and layup text on hand-made cases.

References, worked by hand from the definitions (derived):

* Integer variables (ply counts) are rounded to the NEAREST whole number (the module docstring
  of optimize/nsga.py: "integer variables are rounded"): 2.6 -> 3, 1.4 -> 1; a continuous
  variable is left as it is.
* A population equal to the budget is one whole generation: it must be accepted (the refusal
  is for a population larger than the budget, whose first generation cannot finish).
* The hypervolume of minimised points up to a reference point r counts only points strictly
  better than r in EVERY objective. Two objectives: the union of the rectangles
  [f1, r1] x [f2, r2] of the non-dominated points, a staircase summed by hand. One objective:
  r - (best value), the length of the dominated interval.
* A layup template's placeholder is filled with the variable's decoded value as is (it holds 4
  significant digits by default): 52.75 deg is written 52.75, not 52.8.
* A decoded value never leaves its bounds, also after the rounding to significant digits.
* A log-scale variable searches log10 of its value: K_p in [1e5, 1e7] N/m is searched on
  [5, 7] (the decades the module docstring names).
* A derived template's ply angle stays within [0, 90] deg: 85 deg +- 15 gives [70, 90].

No physics is evaluated (the searches stop at their first evaluation, or run a hand mass and
margin law); about 0.8 s of CPU, most of it importing pymoo and xarray on first use.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("pymoo")  # the optimizer's search (the `optimize` and `test` extras)

from flexshaft.design import load_design, with_overrides
from flexshaft.optimize import DesignProblem, DesignVariable, optimize
from flexshaft.optimize.result import OptimizationResult, hypervolume
from flexshaft.optimize.variables import Objective, layup_template


def interrupted_at_once(point):
    """Ctrl-C at the first evaluation: the search stops before evaluating anything."""
    raise KeyboardInterrupt


def _ply_count_problem() -> DesignProblem:
    """A wall thickness and an integer ply count n in (55/-55/0_n)s (1 to 3 plies of 0 deg)."""
    return DesignProblem(
        (
            DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall", units="m"),
            DesignVariable("layup.n", 1, 3, integer=True, name="n"),
        ),
        objectives=(Objective("mass", "min", "mass"),),
        constraints=(),
        layup="(55/-55/0_{n})s",
        evaluate=interrupted_at_once,
        outputs=(("mass", "kg", "mass"),),
        name="ply count",
    )


def test_ply_counts_are_rounded_to_the_nearest_in_both_the_first_generation_and_the_repair(monkeypatch):
    import pymoo.algorithms.moo.nsga2 as nsga2

    import flexshaft.optimize.nsga as nsga

    captured: dict = {}
    real = nsga2.NSGA2

    def spy(**kwargs):
        captured.update(kwargs)
        return real(**kwargs)

    monkeypatch.setattr(nsga2, "NSGA2", spy)
    problem = _ply_count_problem()
    X = np.array([[0.0017, 2.6], [0.0023, 1.4], [0.0031, 2.5001]])
    expected = [[0.0017, 3.0], [0.0023, 1.0], [0.0031, 3.0]]
    np.testing.assert_array_equal(nsga._round_integers(problem, X), expected)
    with pytest.raises(KeyboardInterrupt):
        optimize(problem, 8, None, pop_size=8, seed=2)  # also: a population equal to the budget runs
    np.testing.assert_array_equal(captured["repair"]._do(None, X), expected)
    first = captured["sampling"]  # the first generation: whole ply counts, its strata by n
    assert np.all(first[:, 1] == np.round(first[:, 1])) and set(first[:, 1].tolist()) == {1.0, 2.0, 3.0}


def test_the_hypervolume_of_a_staircase_by_hand():
    """Reference (4, 4). Front (1, 3), (2, 2), (3, 1): strips of width 1 and heights 1, 2, 3:
    area 6. (2.5, 2.5) is dominated by (2, 2) and adds nothing; (0.5, 5) lies beyond the
    reference in f2 and adds nothing."""
    F = np.array([[1.0, 3.0], [2.5, 2.5], [2.0, 2.0], [0.5, 5.0], [3.0, 1.0]])
    assert hypervolume(F, (4.0, 4.0)) == pytest.approx(6.0, rel=1e-15)
    # one objective: 1, 3, 5 against 4: the interval [1, 4]
    assert hypervolume(np.array([[1.0], [3.0], [5.0]]), (4.0,)) == pytest.approx(3.0, rel=1e-15)


def test_a_ply_angle_is_written_with_its_decoded_digits():
    problem = DesignProblem(
        (
            DesignVariable("layup.a", 30.0, 75.0, name="a", units="degree"),
            DesignVariable("layup.b", 0.0, 30.0, name="b", units="degree"),
        ),
        objectives=(Objective("mass", "min", "mass"),),
        constraints=(),
        layup="({a}/{-a}/{b}/{-b})s",
        evaluate=interrupted_at_once,
        outputs=(("mass", "kg", "mass"),),
    )
    values = problem.values([52.75, 12.25])  # 4 significant digits, exact in binary
    assert values == {"a": 52.75, "b": 12.25}
    assert problem.layup_of(values) == "(52.75/-52.75/12.25/-12.25)s"


def test_a_rounded_value_stays_within_its_bounds():
    """Upper bound 0.0012346: 4 significant digits round it up to 0.001235, past the bound."""
    v = DesignVariable("shaft.wall_thickness", 0.001, 0.0012346)
    assert v.decode(0.0012346) <= 0.0012346
    assert v.decode(0.0012346) == pytest.approx(0.0012346, rel=1e-4)


def test_a_log_gain_is_searched_over_its_decades():
    v = DesignVariable("bearings[0].kp", 1e5, 1e7, log=True)
    assert v.search_bounds == pytest.approx((5.0, 7.0), rel=1e-15)
    assert v.decode(6.0) == pytest.approx(1e6, rel=1e-12)


def test_a_derived_ply_angle_stays_below_90_degrees():
    template, (a, b) = layup_template("(85/-85/0/0)s")
    assert (a.lower, a.upper) == (70.0, 90.0) and (b.lower, b.upper) == (0.0, 15.0)


def mass_and_margin(point):
    """Mass 1000 w and margin 1000 w - 2 of a wall w [m]: feasible from w = 2 mm."""
    w = point.design.shaft.wall_thickness
    return {"mass": 1e3 * w, "margin": 1e3 * w - 2.0}


def test_reference_designs_are_feasible_by_their_own_margin():
    """The base (Table 3.1 baseline, wall 3 mm): margin 3 - 2 = 1 >= 0, feasible; a 1.5 mm
    reference: margin -0.5, infeasible; a 2 mm one: margin 0, at the limit, feasible."""
    problem = DesignProblem(
        (DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall", units="m"),),
        objectives=(Objective("mass", "min", "mass"),),
        constraints=("margin",),
        evaluate=mass_and_margin,
        outputs=(("mass", "kg", "1000 w"), ("margin", "1", "1000 w - 2")),
    )
    refs = {
        k: with_overrides(problem.base, {"shaft.wall_thickness": w}) for k, w in (("thin", 0.0015), ("edge", 0.002))
    }
    result = optimize(problem, 1, None, seed=1, method="random", references=refs)
    found = result.references
    assert problem.base.shaft.wall_thickness == 0.003 and found["base"]["margin"] == pytest.approx(1.0, rel=1e-12)
    assert (found["base"]["feasible"], found["thin"]["feasible"], found["edge"]["feasible"]) == (True, False, True)


def _front(walls) -> OptimizationResult:
    """A Pareto set of walls (the first objective, sorted) from the baseline, by hand."""
    import json

    import xarray as xr

    problem = DesignProblem(
        (DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall", units="m"),),
        objectives=(Objective("mass", "min", "mass"),),
        constraints=(),
        evaluate=mass_and_margin,
        outputs=(("mass", "kg", "1000 w"), ("margin", "1", "1000 w - 2")),
    )
    pareto = xr.Dataset(
        {
            "mass": ("design", [1e3 * w for w in walls]),
            "overrides": ("design", [json.dumps({"shaft.wall_thickness": w}) for w in walls]),
        }
    )
    return OptimizationResult(problem, evaluations=None, pareto=pareto)


def test_pareto_designs_written_all_or_spread_with_both_ends(tmp_path):
    """Docstring of write_designs: all of them (3 of 3 when 8 are allowed), or max_designs
    spread evenly along the front, its ends included (2 of 3: the first and the last)."""
    walls = [0.002, 0.0025, 0.003]
    result = _front(walls)
    paths = result.write_designs(tmp_path / "all", max_designs=8)
    assert [load_design(p).shaft.wall_thickness for p in paths] == walls
    assert result.pareto["file"].values.tolist() == ["pareto_01.toml", "pareto_02.toml", "pareto_03.toml"]
    paths = result.write_designs(tmp_path / "ends", max_designs=2)
    assert [load_design(p).shaft.wall_thickness for p in paths] == [0.002, 0.003]
