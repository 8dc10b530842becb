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
* The consequence for feasibility (G ≤ 0 feasible; G = −margin of each constraint, then the
  validity column last: :func:`objectives_and_constraints`, docstring, API contract in the
  code): a
  candidate passing every applicable check by a margin of 0.2 is feasible although the verdict
  does not list the two checks its driveline has no part for (their margins are NaN); and
  docs/optimizer.md's "not evaluated is a violation" still holds for a check that does apply.
* Explicit constraints are the problem's, whatever the base has: docs/optimizer.md, min_margin
  is "the smallest normalised margin (below) of the problem's constraints ... (an
  `--ignore-check` check does not count ...)". A row failing every other check (−0.5) but
  passing tsai_wu (0.2) and separation (0.1) is feasible for constraints ("tsai_wu",
  "separation"), with min_margin 0.1.
* docs/optimizer.md, Algorithm: the first generation has "the base design's own values as its
  first member when they lie in the bounds".
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
    # docs/optimizer.md: "the thirteen of a one-piece FMC shaft with actuators"
    assert len(problem.constraints) == 13


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


def test_explicit_constraints_are_the_only_ones_counted():
    """constraints=("tsai_wu", "separation") on the baseline (driveline evaluation): those two
    margin outputs only. A row with margins 0.2 and 0.1 on them and −0.5 on every other check
    (an ignored requirement failed by half its limit): G = (−0.2, −0.1, 0), shape (1, 3) (two
    constraints, then validity), feasible; min_margin min(0.2, 0.1) = 0.1, not −0.5. Exact: a
    negation and a minimum, no arithmetic."""
    problem = DesignProblem(
        (DesignVariable("shaft.wall_thickness", 0.001, 0.004),),
        objectives=["driveline_mass"],
        constraints=("tsai_wu", "separation"),
    )
    assert problem.constraints == ("margin_tsai_wu", "margin_separation")
    margins = dict.fromkeys(CHECK_KEYS, -0.5) | {"tsai_wu": 0.2, "separation": 0.1}
    outputs = _outputs(problem, margins)
    _, G = objectives_and_constraints(problem, outputs, [True])
    assert G.shape == (1, 3)
    assert G[0].tolist() == [-0.2, -0.1, 0.0]
    assert G.max() <= 0.0  # feasible
    names = problem.all_output_names
    assert problem.with_derived(outputs)[0, names.index("min_margin")] == 0.1


def test_the_base_design_is_the_first_member_of_the_first_generation():
    """A log-scale K_p variable (1e5 to 1e7 N/m, search coordinate log10 K_p in [5, 7]) on the
    baseline with both gains 5e5 N/m: the first member of the initial population lies in the
    search box and decodes to 5e5 N/m. Tolerance 1e-12 relative: 10**log10(5e5) is two
    correctly rounded libm calls, a few ulp (~1e-15) from 5e5."""
    from flexshaft.optimize.nsga import _initial_population

    base = with_overrides(baseline_design(), {"bearings[1].kp": 5e5, "bearings[2].kp": 5e5})
    gain = DesignVariable(("bearings[1].kp", "bearings[2].kp"), 1e5, 1e7, log=True, name="kp")
    problem = DesignProblem((gain,), base=base, objectives=["driveline_mass"], constraints=["tsai_wu"])
    X = _initial_population(problem, 8, seed=1)
    lower, upper = problem.bounds
    assert lower[0] == 5.0 and upper[0] == 7.0  # log10 of the bounds, exact for powers of ten
    assert lower[0] <= X[0, 0] <= upper[0]
    assert problem.values(X[0])["kp"] == pytest.approx(5e5, rel=1e-12)
