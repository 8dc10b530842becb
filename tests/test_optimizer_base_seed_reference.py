"""What the optimizer reads back from the base design to seed its search, and the laminate an
integer ply-angle variable writes, against the documented rules.

References (docs/optimizer.md and the :meth:`DesignProblem.base_values` docstring):

* "The first generation is a Latin hypercube from `--seed` with the base design's own values as
  its first member when they lie in the bounds"; ``base_values`` returns "None when a variable
  cannot be read back from it or lies outside its bounds". A value the variable cannot take is
  not the base design's own value:

  - an integer variable (``:int`` rounds) on a field whose base value is not a whole number
    (the Table 3.1 baseline's forward magnet at x = 3.21 m) takes only whole metres (2 ... 5 m on
    [2, 5] m) and 3.21 m is none of them: the base
    design is not a point of the search, so nothing is seeded (None), never 3 m;
  - one variable shared by several paths (``bearings[1].kp,bearings[2].kp``: both actuators'
    gain) sets them all to one value: a base whose two gains differ (1e6 and 2e6 N/m) is not a
    point of the search either (None); with equal gains (1e6 and 1e6) it is, the gain 1e6.

* Layup templates: ``{name}`` / ``{-name}`` placeholders, degrees; ``({a}/{-a})s`` with
  a = 45 is the balanced laminate 45/−45/−45/45 (the symmetric ``s`` mirrors the half), angles
  summing to 0, whether the variable is continuous (45.0) or integer (``:int``, 45).

No evaluation: the stand-in outputs below are never computed (only the problem's bookkeeping
runs). CPU about 0.1 s, the baseline design's construction.
"""

from __future__ import annotations

import pytest

from flexshaft.design import baseline_design, with_overrides
from flexshaft.design.layup import parse_layup
from flexshaft.optimize import DesignProblem, DesignVariable
from flexshaft.optimize.variables import Objective


def never_evaluated(point):  # pragma: no cover - the tests here evaluate nothing
    raise AssertionError("no evaluation expected")


def _problem(variables, base=None, layup=None) -> DesignProblem:
    return DesignProblem(
        variables,
        base=base if base is not None else baseline_design(),
        objectives=(Objective("mass", "min", "mass"),),
        constraints=(),
        layup=layup,
        evaluate=never_evaluated,
        outputs=(("mass", "kg", "stand-in"),),
    )


def test_an_integer_variable_on_a_fractional_base_value_seeds_nothing():
    """Base x = 3.21 m, variable x in [2, 5] m, integer: 3.21 is no value of the search."""
    base = baseline_design()
    assert base.bearings[1].x == pytest.approx(3.21, abs=1e-12)
    as_integer = _problem((DesignVariable("bearings[1].x", 2, 5, integer=True, name="x"),), base)
    assert as_integer.base_values() is None
    # the same bounds, continuous: the base's own 3.21 m is the seed (the test is not vacuous)
    continuous = _problem((DesignVariable("bearings[1].x", 2.0, 5.0, name="x"),), base)
    assert continuous.base_values() == {"x": pytest.approx(3.21, abs=1e-12)}


def test_a_shared_variable_over_unequal_base_values_seeds_nothing():
    """K_p of both actuators as one variable: 1e6 and 2e6 N/m in the base is no point of it."""
    gains = DesignVariable(("bearings[1].kp", "bearings[2].kp"), 1e5, 1e7, log=True, name="kp")
    unequal = with_overrides(baseline_design(), {"bearings[1].kp": 1e6, "bearings[2].kp": 2e6})
    assert _problem((gains,), unequal).base_values() is None
    equal = with_overrides(baseline_design(), {"bearings[1].kp": 1e6, "bearings[2].kp": 1e6})
    assert _problem((gains,), equal).base_values() == {"kp": pytest.approx(1e6, rel=1e-15)}


@pytest.mark.parametrize("integer, value", [(True, 45), (False, 45.0)])
def test_a_negated_placeholder_negates_an_integer_angle_too(integer, value):
    """``({a}/{-a})s`` at a = 45: plies 45/−45/−45/45, balanced (angles sum to 0)."""
    a = DesignVariable("layup.a", 30, 75, integer=integer, name="a")
    problem = _problem((a,), layup="({a}/{-a})s")
    layup = problem.overrides({"a": value})["shaft.layup"]
    assert parse_layup(layup) == (45.0, -45.0, -45.0, 45.0)
