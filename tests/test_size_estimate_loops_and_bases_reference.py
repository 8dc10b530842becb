"""Three parts of the problem-size estimate (flexshaft.assembly.size) against their documented
or derived forms.

* **The passive every-root check and bearing loops.** docs/limits.md (section 5, quoted): "the
  passive every-root check and the bearing loops 0.1 s + 1.2e-3 s × F + 3.5e-7 s × F²". The
  Jeffcott rotor (tests/validation design ``jeffcott_internal_damping.toml``) has one contact
  bearing and no actuator, so its check is the passive one, at F = 6 · 9 − 6 = 48 free DOFs
  (hand count: 9 shaft nodes of 6 DOFs, 4 held at the start and 2 at the end) and one point
  (no ``[envelope]``). A sum of three floats: rel 1e-12.
* **The sparse modal basis's time is linear in F.** Above 900 free DOFs (and a basis of 60
  modes below half of them) the basis is a shift-invert Lanczos solve: one banded LU factor of
  half-bandwidth k (Golub & Van Loan, Matrix Computations, §4.3: about 2 n k² flops) and a fixed
  number of Lanczos steps, each a banded solve (O(n k)) and a few vector operations (O(n)); k
  and the basis size do not grow with the mesh, so the cost is a + b F. At 160, 320 and 640
  elements (F = 960, 1,920 and 3,840) the increments of a + b F stand in the ratio 2 whatever a
  and b (a quadratic cost gives 4). The increments are 1.5e-4 s beside a = 0.05 s: float
  rounding of 1e-17 gives rel 1e-13, so rel 1e-9.
* **The report's detail runs a whirl solve at each Campbell speed.** The module docstring of
  flexshaft.assembly.size: an assessment is counted "from the grids of its Resolution (spin-up
  and whirl speeds, the report's Campbell speeds)". Derived here: the report's Campbell
  diagram (flexshaft.analyses.campbell.campbell → track_modes) is a solve on the reduced basis
  at each of its ``campbell_speeds``, the solve docs/limits.md costs per whirl speed at
  "1e-2 s + 1.5e-6 s × F" (no controller states here). The structural part, the detail's time
  linear in campbell_speeds with a positive slope (10, 30, 50: equal increments), rests on
  that count alone. Two resolutions that
  differ only in campbell_speeds (10 and 30) differ in the detail's time by 20 · (1e-2 + 1.5e-6
  · 48) s, and not at all in the whirl grid. Difference of two sums near 1 s: rel 1e-9.

No model is built and nothing is solved: a few ms.

Written for the mutations h57b-size-loops-dof-square-linear,
h57b-size-sparse-basis-time-quadratic and h57b-size-detail-whirl-grid of scripts/mutations.toml.
"""

from __future__ import annotations

import copy
import dataclasses
import tomllib
import warnings

import pytest

from flexshaft.assembly.size import ProblemSizeWarning, problem_size
from flexshaft.design import design_from_dict
from flexshaft.resolution import REPORT, SCREENING
from flexshaft.validation.runner import design_text

JEFFCOTT = tomllib.loads(design_text("jeffcott_internal_damping.toml"))


def _size(data, analysis, resolution):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        return problem_size(design_from_dict(data), analysis, resolution)


def test_the_passive_every_root_check_costs_the_documented_quadratic():
    """0.1 s + 1.2e-3 s × 48 + 3.5e-7 s × 48² for the passive Jeffcott rotor at one point."""
    s = _size(JEFFCOTT, "assess", SCREENING)
    f = 48
    assert (s.free_dofs, s.actuators) == (f, 0)
    assert "every-root state matrix" not in s.memory  # the passive check: no dense solve
    expected = 0.1 + 1.2e-3 * f + 3.5e-7 * f**2
    assert s.time["every-root check and loops"] == pytest.approx(expected, rel=1e-12)


def test_the_sparse_modal_basis_time_grows_linearly_with_the_free_dofs():
    """Increments of a + b F at F = 960, 1,920, 3,840: ratio 2."""
    t = {}
    for elements in (160, 320, 640):
        data = copy.deepcopy(JEFFCOTT)
        data["mesh"]["shaft_elements"] = elements
        s = _size(data, "model", SCREENING)
        assert not s.dense_basis and s.free_dofs == 6 * (elements + 1) - 6
        t[s.free_dofs] = s.time["modal basis"]
    assert (t[3840] - t[1920]) / (t[1920] - t[960]) == pytest.approx(2.0, rel=1e-9)


def test_the_report_detail_costs_one_whirl_solve_per_campbell_speed():
    """campbell_speeds 10 → 30: the detail costs 20 more whirl solves of 1e-2 + 1.5e-6 · 48 s."""
    few, many = (_size(JEFFCOTT, "assess", dataclasses.replace(REPORT, campbell_speeds=c)) for c in (10, 30))
    assert few.whirl_speeds == many.whirl_speeds == REPORT.whirl_speeds
    assert (few.campbell_speeds, many.campbell_speeds) == (10, 30)
    extra = many.time["report detail"] - few.time["report detail"]
    assert extra == pytest.approx(20 * (1e-2 + 1.5e-6 * 48), rel=1e-9)
    more = _size(JEFFCOTT, "assess", dataclasses.replace(REPORT, campbell_speeds=50))
    assert more.time["report detail"] - many.time["report detail"] == pytest.approx(extra, rel=1e-9)
    assert extra > 0
