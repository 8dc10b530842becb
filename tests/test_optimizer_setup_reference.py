"""The optimizer's setup and bookkeeping against hand-worked expectations.

References (docs/optimizer.md and the :func:`flexshaft.optimize.optimize` docstring):

* the default population is ``max(16, 4 × variables)``, at most a third of the budget: the ZDT1
  problem (:mod:`flexshaft.optimize.reference`) has 5 variables, so 20 for a budget of 60 and
  30 // 3 = 10 for a budget of 30;
* a stand-in problem with one variable, the wall w in [1, 4] mm (the Table 3.1 baseline's 3 mm
  inside), outputs mass = 1000 w and margin = 1000 w − 2 (constraint margin >= 0, i.e.
  w >= 2 mm), objectives min mass and max margin;
* ``budget`` caps the candidates the search asks for: a budget of 18 with a population of 8 is
  the generations 8 + 8 + 2 (the last one cut), then the base design once as the reference;
* the first generation is a Latin hypercube with the base design's own values as its first
  member: each of its other n − 1 members lies in a stratum of width 1/n of the variable's
  range that no other member occupies;
* the stand-in's two objectives conflict along w, so no feasible design dominates another and
  the Pareto set is every feasible design (w >= 2 mm), listed by increasing mass; the best
  feasible values are min mass = 1000 min w and max margin = 1000 max w − 2 over the feasible w.

Cheap: analytic output functions (no model built), at most 18 evaluations per run.
"""

from __future__ import annotations

import json
import re
from dataclasses import replace

import numpy as np
import pytest

pytest.importorskip("pymoo")
pytest.importorskip("xarray")

from flexshaft.optimize import DesignProblem, DesignVariable, optimize
from flexshaft.optimize.reference import zdt1_problem
from flexshaft.optimize.store import evaluate_candidates
from flexshaft.optimize.variables import Objective


def interrupted_at_once(point):
    """Ctrl-C at the first evaluation: the run folder then holds the search's manifest only."""
    raise KeyboardInterrupt


def mass_and_margin(point):
    w = point.design.shaft.wall_thickness
    return {"mass": 1e3 * w, "margin": 1e3 * w - 2.0}


@pytest.mark.parametrize("budget, population", [(60, 20), (30, 10)])
def test_default_population(tmp_path, budget, population):
    problem = replace(zdt1_problem(), evaluate=interrupted_at_once)
    assert len(problem.variables) == 5
    with pytest.raises(KeyboardInterrupt):
        optimize(problem, budget, tmp_path / "run", seed=1)
    assert json.loads((tmp_path / "run" / "problem.json").read_text())["pop_size"] == population


def _wall_problem() -> DesignProblem:
    return DesignProblem(
        (DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall", units="m"),),
        objectives=(Objective("mass", "min", "mass"), Objective("margin", "max", "margin")),
        constraints=("margin",),
        evaluate=mass_and_margin,
        outputs=(("mass", "kg", "1000 w"), ("margin", "1", "1000 w - 2")),
        name="conflicting mass and margin",
    )


def test_budget_generations_and_first_generation(monkeypatch):
    import flexshaft.optimize.nsga as nsga

    asked: list[int] = []

    def counting(problem, candidates, *args, **kwargs):  # the batches the search asks for
        asked.append(len(candidates))
        return evaluate_candidates(problem, candidates, *args, **kwargs)

    monkeypatch.setattr(nsga, "evaluate_candidates", counting)
    problem = _wall_problem()
    n = 8
    result = optimize(problem, 18, None, pop_size=n, seed=4)
    assert asked == [8, 8, 2, 1]  # three generations, then the base design as the reference
    ev = result.evaluations
    assert ev["generation"].values[:n].tolist() == [0] * n  # the first generation: n distinct designs
    walls = ev["wall"].values[:n]
    # the base design's wall (Table 3.1 baseline: 3 mm) is the first member
    assert problem.base.shaft.wall_thickness == 0.003 and walls[0] == pytest.approx(0.003, rel=1e-12)
    # the other n - 1 members: one stratum of width 1/n each (the decoded values keep 4
    # significant digits, 1e-4 relative, far inside a stratum of 1/8 of the range)
    strata = np.floor(n * (walls[1:] - 0.001) / 0.003).astype(int)
    assert len(set(strata.tolist())) == n - 1 and strata.min() >= 0 and strata.max() <= n - 1, walls


def test_pareto_set_and_best_values_of_a_max_objective():
    problem = _wall_problem()
    lines: list[str] = []
    result = optimize(problem, 8, None, seed=3, method="random", progress=lines.append)
    walls = result.evaluations["wall"].values
    feasible = np.sort(walls[walls >= 0.002])
    assert 0 < feasible.size < walls.size  # both kinds among the samples (seed 3)
    np.testing.assert_array_equal(result.pareto["wall"].values, feasible)
    best = dict(re.findall(r"(?:min|max) (mass|margin) ([-0-9.e+]+)", lines[-1]))
    assert float(best["mass"]) == pytest.approx(1e3 * feasible[0], rel=1e-4)  # printed to 5 digits
    assert float(best["margin"]) == pytest.approx(1e3 * feasible[-1] - 2.0, rel=1e-4)
