"""Candidates equal to a variable's precision are one design in the optimizer's record.

Reference: docs/optimizer.md, "The search": "Continuous values are kept to 4 significant digits
(clean design files; candidates equal to that precision are one design)"; and "every
evaluation" of evaluations.nc, "pareto.nc  the feasible non-dominated designs".

Hand-built case (derived here): the wall w in [1, 4] mm kept to ONE significant digit can only
be 1, 2, 3 or 4 mm. A search of 40 candidates (random) or of 12 (NSGA-II, population 4) then
meets at most four designs, by the pigeonhole principle several times each, so the record holds
at most four evaluations, each design once. With shaft_mass = 1000 w minimised and
safety_factor = 1000 w maximised no design dominates another, so the Pareto set is the same
distinct designs, each once.

Cheap: analytic output function, at most 40 candidates.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.optimize import DesignProblem, DesignVariable


def mass_and_safety_factor(point):
    """Both grow with the wall: a thicker wall is heavier and stronger."""
    w = point.design.shaft.wall_thickness
    return {"shaft_mass": 1e3 * w, "safety_factor": 1e3 * w}


@pytest.mark.parametrize("method, budget", [("random", 40), ("nsga2", 12)])
def test_designs_equal_to_their_precision_are_recorded_once(method, budget):
    pytest.importorskip("xarray")
    if method == "nsga2":
        pytest.importorskip("pymoo")
    from flexshaft.optimize import optimize

    problem = DesignProblem(
        (DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall", units="m", significant_digits=1),),
        objectives=("shaft_mass", "safety_factor"),
        constraints=(),
        evaluate=mass_and_safety_factor,
        outputs=(("shaft_mass", "kg", "1000 w"), ("safety_factor", "1", "1000 w")),
        name="one-digit wall",
    )
    result = optimize(problem, budget, None, seed=1, pop_size=4 if method == "nsga2" else None, method=method)
    walls_mm = np.round(result.evaluations["wall"].values * 1e3, 9)  # decoded through "%.1g": exact digits
    assert set(walls_mm) <= {1.0, 2.0, 3.0, 4.0}
    assert np.unique(walls_mm).size == walls_mm.size  # each design once
    assert 2 <= walls_mm.size <= 4  # the pigeonhole bound; more than one design met (seed 1)
    front_mm = np.round(result.pareto["wall"].values * 1e3, 9)
    np.testing.assert_array_equal(front_mm, np.sort(walls_mm))  # the trade-off: every design, once


def test_random_samples_cover_the_bounds():
    """docs/optimizer.md, Algorithm: "`method="random"` (API) samples the bounds uniformly". The
    wall in [1, 4] mm (4 significant digits, so a sample just below 4 mm may read 4.000 mm), 40
    samples: every recorded wall lies in [1, 4] mm and each third of the range, [1, 2], [2, 3]
    and [3, 4] mm, holds one. Derived here: a third is empty with probability (2/3)^40, any of
    the three at most 3·(2/3)^40 ≈ 2.7e-7 (union bound); the seed is fixed anyway."""
    pytest.importorskip("xarray")
    from flexshaft.optimize import optimize

    problem = DesignProblem(
        (DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall", units="m"),),
        objectives=("shaft_mass", "safety_factor"),
        constraints=(),
        evaluate=mass_and_safety_factor,
        outputs=(("shaft_mass", "kg", "1000 w"), ("safety_factor", "1", "1000 w")),
        name="random wall",
    )
    result = optimize(problem, 40, None, seed=1, method="random")
    walls_mm = result.evaluations["wall"].values * 1e3
    assert np.all((walls_mm >= 1.0) & (walls_mm <= 4.0))
    for low in (1.0, 2.0, 3.0):
        assert np.any((walls_mm >= low) & (walls_mm <= low + 1.0)), f"no sample in [{low}, {low + 1}] mm"
