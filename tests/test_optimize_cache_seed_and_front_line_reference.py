"""Three rules of docs/optimizer.md and the result's docstrings: what the optimizer reuses, what
it starts from, and where its figure draws the Pareto front.

References (hand-written docs, quoted verbatim):

* docs/optimizer.md, "Parallel, cached, resumable": "A design's key is the SHA-256 of the
  evaluation (function, outputs, fidelity, flexshaft version) and of the design itself (all
  fields but its name), so a design met again ... is read, not computed." Two searches that
  differ only in the fidelity therefore key the same design differently: a design evaluated at
  the "verdict" fidelity is computed again at the "screening" fidelity, never read back.
* docs/optimizer.md, "Default search": "built to hold the design it starts from (the first
  generation is seeded with it)", and DesignVariable's bounds are closed (``lower``, ``upper``:
  "Bounds"; decode clips to them, so a bound itself is a value the search takes). A base design
  whose value sits exactly on a variable's lower (or upper) bound is inside the search and is
  read back as the seed (:meth:`DesignProblem.base_values`).

* The Pareto figure (docs/optimizer.md: "pareto.png, .svg  the Pareto-front figure";
  :func:`flexshaft.plot.optimize.pareto_front`: "front_x, front_y : The Pareto front (drawn as
  the attainment line between its members)"): the front line's vertices are the front members'
  own (x, y) pairs, here (30 kg, 0.01), (31 kg, 0.05), (32 kg, 0.09) of the sibling stand-in
  result of tests/test_pareto_figure_objective_senses_reference.py (values written there by
  hand, exact: the line holds the data as given).

Cheap: a stand-in evaluation that only reports the fidelity it was asked for (no driveline
model), one candidate, in-process (jobs=1): measured 0.8-1.0 s of CPU on first use (mostly the
sweep engine's imports, paid once per session), 0.02-0.03 s warm; the seed test builds a problem
and reads the base (0.05 s); the figure about 0.1 s (Agg) once matplotlib is imported (0.7 s
measured with its import).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.design import baseline_design
from flexshaft.optimize import DesignProblem, DesignVariable
from flexshaft.optimize.store import EvaluationCache, evaluate_candidates
from flexshaft.optimize.variables import Objective


def fidelity_seen(point) -> dict[str, float]:
    """1 when evaluated at the screening fidelity, 0 at the verdict fidelity (module level: the
    sweep engine may evaluate it in a worker process)."""
    return {"screening_fidelity": 1.0 if point.axes.get("fidelity") == "screening" else 0.0}


def _problem(fidelity: str) -> DesignProblem:
    return DesignProblem(
        [DesignVariable("shaft.wall_thickness", 0.001, 0.004, units="m")],
        objectives=[Objective("screening_fidelity")],
        constraints=(),
        fidelity=fidelity,
        evaluate=fidelity_seen,
        outputs=[("screening_fidelity", "1", "evaluated at the screening fidelity")],
    )


def test_a_design_evaluated_at_one_fidelity_is_computed_again_at_the_other():
    """The key rule itself (fidelity in the key) is already checked by
    tests/test_optimizer_resume_log_reference.py
    (test_a_stored_evaluation_is_reused_only_by_the_same_fidelity); this test adds only the check
    that the output comes from the fidelity asked for (the stand-in reports it)."""
    pytest.importorskip("xarray")
    cache = EvaluationCache()
    candidate = {"shaft.wall_thickness": 0.003}
    (first,), computed_first = evaluate_candidates(_problem("verdict"), [candidate], cache)
    assert (first["outputs"]["screening_fidelity"], computed_first) == (0.0, 1)
    (second,), computed_second = evaluate_candidates(_problem("screening"), [candidate], cache)
    # another key (the fidelity is part of it): computed, and at the fidelity asked for
    assert second["key"] != first["key"]
    assert (second["outputs"]["screening_fidelity"], computed_second) == (1.0, 1)
    # the same fidelity again: read back, not computed (the cache itself works)
    (third,), computed_third = evaluate_candidates(_problem("screening"), [candidate], cache)
    assert (third["key"], computed_third) == (second["key"], 0)


def test_a_base_value_on_a_bound_is_held_and_seeded():
    """The baseline's wall (read from the design, not assumed) as the lower, then the upper
    bound of the wall variable: both times the base is inside the closed range and is the seed;
    a range that excludes it (just above) gives no seed."""
    wall = baseline_design().shaft.wall_thickness
    for lower, upper in ((wall, 2 * wall), (wall / 2, wall)):
        problem = DesignProblem([DesignVariable("shaft.wall_thickness", lower, upper, name="wall")])
        assert problem.base_values() == {"wall": wall}
    outside = DesignProblem([DesignVariable("shaft.wall_thickness", 1.01 * wall, 2 * wall, name="wall")])
    assert outside.base_values() is None


def test_the_pareto_front_line_joins_the_front_members_own_pairs():
    pytest.importorskip("xarray")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from test_pareto_figure_objective_senses_reference import _result

    try:
        for x, y, pairs in (
            ("driveline_mass", "min_margin", [(30.0, 0.01), (31.0, 0.05), (32.0, 0.09)]),
            ("min_margin", "driveline_mass", [(0.01, 30.0), (0.05, 31.0), (0.09, 32.0)]),
        ):
            ax = _result().plot(x=x, y=y).axes[0]
            (line,) = [ln for ln in ax.get_lines() if ln.get_label().startswith("Pareto front")]
            drawn = np.column_stack([line.get_xdata(), line.get_ydata()])
            np.testing.assert_array_equal(drawn, pairs)  # exact: the data as given
    finally:
        plt.close("all")
