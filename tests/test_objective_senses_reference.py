"""The senses of the driveline's named objectives against docs/optimizer.md and Pareto dominance.

References:

* docs/optimizer.md, "Objectives": "`driveline_mass` [kg] min", "`min_margin` max",
  "`shaft_mass` [kg] min, `safety_factor` (minimum ply Tsai-Wu) max, `buckling_safety_factor`
  max, `actuator_force` [N] min (...), `actuator_orbit` [m] min, `spinup_deflection` [m] min,
  `max_temperature` [K] min, `min_log_decrement` max" — read from the hand-written page, so the
  test follows the page and not the code;
* Pareto dominance (Deb et al. 2002): a design dominates another when it is no worse in every
  objective and better in one. A stand-in evaluation gives shaft_mass = 1000 w and
  safety_factor = 1000 w for the wall w [m]: with the mass minimised and the safety factor
  maximised the two conflict along w, so no design dominates another and every evaluated design
  is on the front (derived here); were the safety factor minimised, the thinnest design would
  dominate all others and the front would be one design.

Cheap: analytic output function, 8 random candidates.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from flexshaft.optimize import DesignProblem, DesignVariable
from flexshaft.optimize.variables import DESIGN_OBJECTIVES

DOC = Path(__file__).resolve().parents[1] / "docs" / "optimizer.md"


def _documented_senses() -> dict[str, str]:
    """``name -> "min" | "max"`` from the "Objectives" bullet of docs/optimizer.md: each
    objective written as `` `name` `` then an optional ``[unit]`` and ``(note)``, then its sense."""
    text = DOC.read_text(encoding="utf-8")
    section = text[text.index("* **Objectives**") : text.index("* **Constraints**")]
    pattern = r"`([a-z_]+)`\s*(?:\[[^\]]*\]\s*)?(?:\([^)]*\)\s*)?(min|max)\b"
    return dict(re.findall(pattern, section))


def test_every_named_objective_has_the_documented_sense():
    documented = _documented_senses()
    assert set(documented) == set(DESIGN_OBJECTIVES)  # the page names every objective, each once
    assert {name: o.sense for name, o in DESIGN_OBJECTIVES.items()} == documented
    assert all(o.output == name for name, o in DESIGN_OBJECTIVES.items())


def mass_and_safety_factor(point):
    """Both grow with the wall: a thicker wall is heavier and stronger."""
    w = point.design.shaft.wall_thickness
    return {"shaft_mass": 1e3 * w, "safety_factor": 1e3 * w}


def test_shaft_mass_against_safety_factor_is_a_trade_off():
    pytest.importorskip("xarray")
    from flexshaft.optimize import optimize

    problem = DesignProblem(
        (DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall", units="m"),),
        objectives=("shaft_mass", "safety_factor"),  # by name: the senses of DESIGN_OBJECTIVES
        constraints=(),
        evaluate=mass_and_safety_factor,
        outputs=(("shaft_mass", "kg", "1000 w"), ("safety_factor", "1", "1000 w")),
        name="mass against safety factor",
    )
    result = optimize(problem, 8, None, seed=1, method="random")
    walls = result.evaluations["wall"].values
    assert np.unique(walls).size == walls.size == 8  # eight distinct designs (seed 1)
    # no design dominates another: the front is every design, by increasing mass (first objective)
    np.testing.assert_array_equal(result.pareto["wall"].values, np.sort(walls))
