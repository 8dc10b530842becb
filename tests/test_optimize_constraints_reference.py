"""What a :class:`~flexshaft.optimize.DesignProblem` constrains and what a candidate is, against
the rules of docs/optimizer.md (hand-written) and hand-made outputs (no analysis is run).

* docs/optimizer.md, Variables: ``--var "bearings[1].kp,bearings[2].kp=1e5:1e7:log"`` is one
  variable for "both actuators' gain" (the module docstring of
  :mod:`flexshaft.optimize.variables`: "several paths share one value"). A candidate's overrides
  and the design built from them carry the value at every path, none at the base design's.
* docs/optimizer.md, Constraints: "Constraints are the verdict checks that the base design's
  kind of driveline has ... with an isotropic segment ``metal_strength`` joins, with couplings
  ``coupling_angle``; without a laminated one-piece shaft ``tsai_wu`` and ``temperature`` drop
  out, without active bearings the two actuator checks". The Table 3.1 baseline is a one-piece
  laminated shaft on two active bearings with no coupling and no isotropic segment, so its
  default constraints are every check but ``metal_strength`` and ``coupling_angle``.
* The consequence for feasibility (G ≤ 0 feasible, :func:`objectives_and_constraints`): a
  candidate passing every applicable check by a margin of 0.2 is feasible although the verdict
  does not list the two checks its driveline has no part for (their margins are NaN); and
  docs/optimizer.md's "not evaluated is a violation" still holds for a check that does apply.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.design import baseline_design, with_overrides
from flexshaft.optimize import DesignProblem, DesignVariable
from flexshaft.optimize.evaluate import CHECK_KEYS
from flexshaft.optimize.problem import objectives_and_constraints

#: Checks whose part the baseline lacks (docs/optimizer.md: an isotropic segment, couplings).
NOT_IN_BASELINE = {"metal_strength", "coupling_angle"}


def test_a_variable_of_two_paths_sets_both_actuator_gains():
    """One K_p for both active bearings (docs/optimizer.md): 2.5e6 N/m at bearings[1] and
    bearings[2] of the overrides and of the design built from them, where the baseline has
    1e7 N/m at both (so a path left at the base value would show)."""
    base = baseline_design()
    assert base.bearings[1].kp == base.bearings[2].kp == 1e7  # the value a missed path would keep
    gain = DesignVariable(("bearings[1].kp", "bearings[2].kp"), 1e5, 1e7, log=True, name="kp")
    problem = DesignProblem((gain,), base=base, objectives=["driveline_mass"], constraints=["tsai_wu"])
    overrides = problem.overrides({"kp": 2.5e6})
    assert overrides == {"bearings[1].kp": 2.5e6, "bearings[2].kp": 2.5e6}
    design = with_overrides(base, overrides)
    assert design.bearings[1].kp == 2.5e6 and design.bearings[2].kp == 2.5e6
    # decoding the search coordinate log10(2.5e6) (4 significant digits) gives the same candidate
    assert problem.overrides(problem.values([gain.encode(2.5e6)])) == overrides


@pytest.fixture(scope="module")
def problem():
    """The baseline's default constraints (one model build, a fraction of a second)."""
    return DesignProblem((DesignVariable("shaft.wall_thickness", 0.001, 0.004),), objectives=["driveline_mass"])


def test_default_constraints_are_the_checks_the_baseline_driveline_has(problem):
    """Every verdict check but the two whose part the baseline lacks, each as its margin output."""
    assert set(problem.constraints) == {f"margin_{k}" for k in CHECK_KEYS if k not in NOT_IN_BASELINE}
    assert len(problem.constraints) == len(CHECK_KEYS) - len(NOT_IN_BASELINE)


def _outputs(problem, margins):
    """One output row: driveline mass 30 kg, the given margins, NaN for every other output."""
    row = np.full(len(problem.output_names), np.nan)
    names = list(problem.output_names)
    row[names.index("driveline_mass")] = 30.0
    for key, margin in margins.items():
        row[names.index(f"margin_{key}")] = margin
    return row[None, :]


def test_a_candidate_passing_every_applicable_check_is_feasible(problem):
    """Margins 0.2 on the applicable checks, NaN (not listed) on metal_strength and
    coupling_angle: G = −0.2 on each constraint and 0 on ``valid``, so max G ≤ 0 (feasible) and
    min_margin is 0.2. The same row with the temperature not evaluated (NaN) violates by 1
    (docs/optimizer.md: "counts as a violation of 1")."""
    applicable = {k: 0.2 for k in CHECK_KEYS if k not in NOT_IN_BASELINE}
    F, G = objectives_and_constraints(problem, _outputs(problem, applicable), [True])
    assert F[0, 0] == 30.0
    # −0.2 exactly: a negation, no arithmetic
    assert G.shape == (1, len(CHECK_KEYS) - len(NOT_IN_BASELINE) + 1)
    assert np.all(G[0, :-1] == -0.2) and G[0, -1] == 0.0
    assert problem.with_derived(_outputs(problem, applicable))[0, -1] == 0.2
    missing = _outputs(problem, {**applicable, "temperature": math.nan})
    _, G = objectives_and_constraints(problem, missing, [True])
    assert G.max() == 1.0
