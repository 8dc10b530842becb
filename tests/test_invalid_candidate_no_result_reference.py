"""A candidate the design schema refuses has no result: NaN outputs and the schema's message.

References (quoted):

* docs/optimizer.md, "Constraints": "A candidate the schema refuses (a bearing past its
  neighbour) is recorded with the schema's message and is infeasible; so is one whose evaluation
  raises (its outputs are NaN). If every evaluation of the first batch fails, the search stops
  and shows the first one's error."
* :func:`flexshaft.optimize.store.evaluate_candidates` (its documented return): ``outputs``
  "(name -> float, NaN where the evaluation failed or the design is invalid)".

Hand-built case: the baseline's outer diameter is 101.6 mm, so a 200 mm wall is refused by the
schema (the wall must be less than half the outer diameter); a 3 mm wall is a valid design. The
stand-in evaluation returns mass = 1000 w (no analysis), or raises for every design in the
second test. An invalid candidate was never evaluated, so none of its outputs may read as a
number (a 0 kg driveline is a result it does not have), and a batch whose valid candidates all
raise has failed entirely: the invalid one beside them is no result either.

Cheap: analytic output function through the sweep engine, in memory, 2 or 3 candidates.
"""

from __future__ import annotations

import math

import pytest

pytest.importorskip("xarray")

from flexshaft.optimize import DesignProblem, DesignVariable  # noqa: E402
from flexshaft.optimize.store import EvaluationCache, evaluate_candidates  # noqa: E402
from flexshaft.optimize.variables import Objective, OptimizeError  # noqa: E402

VALID = {"shaft.wall_thickness": 0.003}
REFUSED = {"shaft.wall_thickness": 0.2}  # > outer diameter / 2 = 0.0508 m


def mass_of_wall(point):
    return {"mass": 1e3 * point.design.shaft.wall_thickness, "margin": 1.0}


def always_raises(point):
    raise RuntimeError("stand-in: no model")


def _problem(evaluate) -> DesignProblem:
    return DesignProblem(
        (DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall", units="m"),),
        objectives=(Objective("mass", "min", "mass"),),
        constraints=("margin",),
        evaluate=evaluate,
        outputs=(("mass", "kg", "1000 w"), ("margin", "1", "1")),
        name="stand-in",
    )


def test_a_refused_candidate_has_nan_outputs_and_the_schema_message():
    records, computed = evaluate_candidates(_problem(mass_of_wall), [REFUSED, VALID], EvaluationCache(None))
    refused, valid = records
    assert computed == 1  # only the valid design is evaluated
    assert "wall_thickness" in refused["error"] and "outer_diameter/2" in refused["error"]
    assert all(math.isnan(v) for v in refused["outputs"].values()), refused["outputs"]
    assert valid["error"] is None
    assert valid["outputs"] == pytest.approx({"mass": 3.0, "margin": 1.0}, rel=1e-12)  # 1000 x 3 mm


def test_a_first_batch_of_refused_and_raising_candidates_shows_the_error():
    candidates = [REFUSED, VALID, {"shaft.wall_thickness": 0.002}]
    with pytest.raises(OptimizeError, match="every evaluation of the batch failed.*RuntimeError: stand-in: no model"):
        evaluate_candidates(_problem(always_raises), candidates, EvaluationCache(None))
