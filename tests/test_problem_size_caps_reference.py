"""The problem-size caps decide between running, warning and refusing (flexshaft.assembly.size).

Reference: the documented rule of docs/limits.md, section 5 — ``check_problem_size`` "refuses a
design above **2 GiB** or **4 hours** (estimated), with the numbers and what to change, and warns
(``ProblemSizeWarning``) above 512 MiB, 10 minutes or 3,000 DOFs" — applied to two designs whose
estimate is counted by hand from the documented cost model, on the validation's Jeffcott rotor
(``validation/designs/jeffcott_internal_damping.toml``: a 1 m shaft pinned at both ends,
``fixed_start = [u, v, w, theta]``, ``fixed_end = [v, w]``, no tailboom). No model is built:
each check takes milliseconds.

1. Between the memory caps. 24 shaft elements (25 nodes × 6 DOFs = 150 DOFs, 150 − 6 = 144
   free) and 11 contact bearings at the distinct grid stations x = 2k/24 m, k = 1..11: 10 bays,
   so the "worst" placement has 2^(10−1) = 512 load cases (the documented maximum). An
   assessment at ``SCREENING`` ("`flexshaft.resolution.SCREENING`, 261 spin-up speeds",
   docs/explorer.md:53; "`screening` | 261 speeds", docs/optimizer.md:129) holds "an
   assessment's spin-up responses, 2 × 16 × DOFs × load cases × spin-up speeds bytes (the
   resolution's spin-up speeds: 651 for a run's report and at `verdict` fidelity, 261 at
   `screening`; `flexshaft.resolution`)" (docs/limits.md:154-156) = 2 · 16 · 150 · 512 · 261 B
   = 641,433,600 B = 611.7 MiB, above the 512 MiB soft cap by a factor 1.19. The other arrays
   docs/limits.md lists are a few MB at most: the dense basis "about 5 × 8 n² bytes"
   = 5 · 8 · 144² B = 0.83 MB, the banded solves "16 n (3 k + 1) bytes" with the estimate's
   half-bandwidth 24 = 16 · 144 · 73 B = 0.17 MB, a first-order problem of 2 × 60 modal
   coordinates and no controller states "16 × states² bytes" = 16 · 120² B = 0.23 MB; so the
   total stays below 0.7 GB, far under 2 GiB. The time is seconds (150 DOFs) and the DOFs are
   below 3,000. So the design must be accepted with a ProblemSizeWarning about its memory:
   refusing it (the soft cap taken for the hard one) or keeping silent (the warning tested
   against the hard cap) both break the rule.

2. Over the time cap, the mesh to blame. 400 shaft elements (401 nodes: 2,406 DOFs, F = 2,400
   free, below 3,000), one active bearing with C(s) = (s² + 2s + 1)/(s² + 3s + 2) (order 2 on
   each of the two lateral directions: s = 4 controller states) and 12 envelope points. The
   every-root check of a design "with controller states or a remote sensor" is "a dense
   eigen-solution of the whole model at three speeds" at each point (docs/limits.md:174-175),
   and "the controller states add about 5e-9 s × states³ to each solve" (docs/limits.md:147-148,
   said of the first-order eigen-problems). Assumed here: that per-state³ cost applies to the
   whole model's first-order problem too, of 2F + s = 4,804 states. A lower bound, derived here
   from those statements and that assumption: 12 points × 3 speeds × 5e-9 s × 4804³ = 19,960 s
   = 5.5 h > 4 h. With one load case and few controller states the mesh is what makes the
   problem big; the design must be refused "with the numbers and what to change"
   (docs/limits.md:158-159), the mesh (``mesh.shaft_elements``) among the fields named, and the
   message states the cap as 4 h (1 h = 3,600 s) and the estimate in hours.
"""

from __future__ import annotations

import copy
import tomllib
import warnings

import pytest

from flexshaft.assembly.size import ProblemSizeWarning, check_problem_size
from flexshaft.design import DesignError, design_from_dict
from flexshaft.resolution import SCREENING
from flexshaft.validation.runner import design_text

JEFFCOTT = tomllib.loads(design_text("jeffcott_internal_damping.toml"))
MIB = 1024**2
GIB = 1024**3


def between_the_memory_caps():
    """Case 1 of the module docstring: 24 elements, 11 bearings, "worst" placement (512 cases)."""
    data = copy.deepcopy(JEFFCOTT)
    template = data["bearings"][0]
    data["bearings"] = [dict(template, name=f"b{k}", x=2 * k / 24) for k in range(1, 12)]
    data["loads"] = {"eccentricity": 1e-5, "imbalance_placement": "worst"}
    data["mesh"] = {"shaft_elements": 24}
    return design_from_dict(data)


def over_the_time_cap():
    """Case 2 of the module docstring: 400 elements, an order-2 magnetic bearing, 12 points."""
    data = copy.deepcopy(JEFFCOTT)
    data["bearings"] = [
        {
            "name": "amb",
            "kind": "active",
            "x": 0.5,
            "controller": {"numerator": [1.0, 2.0, 1.0], "denominator": [1.0, 3.0, 2.0]},
            "gap": 1e-3,
            "force_capacity": 100.0,
        }
    ]
    data["mesh"] = {"shaft_elements": 400}
    data["envelope"] = {"points": [{"name": f"point_{k}"} for k in range(12)]}
    return design_from_dict(data)


def test_memory_between_the_soft_and_the_hard_cap_warns_and_runs():
    """611.7 MiB of spin-up responses (hand count, module docstring): above 512 MiB, below
    2 GiB, time and DOFs under their soft caps: accepted, with a warning about the memory."""
    responses = 2 * 16 * 150 * 512 * SCREENING.spinup_speeds
    assert SCREENING.spinup_speeds == 261 and responses == 641_433_600
    assert 512 * MIB < responses < 2 * GIB
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        size = check_problem_size(between_the_memory_caps(), "assess", SCREENING)  # must not raise
    assert (size.dofs, size.free_dofs, size.load_cases) == (150, 144, 512)
    # the estimate counts at least the hand-counted responses and stays under the hard cap
    assert responses <= size.memory_bytes < 2 * GIB
    assert size.time_seconds < 600.0 and size.dofs <= 3000  # only the memory is over a soft cap
    messages = [str(w.message) for w in caught if issubclass(w.category, ProblemSizeWarning)]
    assert len(messages) == 1 and "needs about" in messages[0]


def test_over_four_hours_is_refused_naming_the_mesh():
    """The hand lower bound 12 · 3 · 5e-9 s · (2 · 2400 + 4)³ = 5.5 h exceeds the 4 h cap: refused,
    the mesh among the fields to change, though the design has 2,406 DOFs (< 3,000), one load
    case and 4 controller states."""
    lower_bound = 12 * 3 * 5e-9 * (2 * 2400 + 4) ** 3
    assert lower_bound == pytest.approx(19_960, rel=1e-3) and lower_bound > 4 * 3600
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        with pytest.raises(DesignError) as refused:
            check_problem_size(over_the_time_cap(), "assess", SCREENING)
    paths = [p.path for p in refused.value.problems]
    assert "mesh.shaft_elements" in paths
    mesh = refused.value.problems[paths.index("mesh.shaft_elements")]
    assert "2,406 DOFs" in mesh.message


def test_the_refusal_states_the_four_hour_cap_and_the_estimate_in_hours():
    """User-facing message: the cap reads "allowed: 4 h" (14,400 s / 3,600 s per hour), and the
    estimate is given in hours: at least the 5.5 h lower bound of case 2, and below 60 × 5.5 =
    330 h, since seconds divided by 60 and labelled hours would read 60 times the true estimate,
    itself at least 5.5 h (the bound only separates the two readings; it is no estimate of the
    true figure)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        with pytest.raises(DesignError) as refused:
            check_problem_size(over_the_time_cap(), "assess", SCREENING)
    message = refused.value.problems[0].message
    assert "allowed: 4 h)" in message
    hours = float(message.split("takes about ")[1].split(" h ")[0])
    assert 5.5 <= hours < 60 * 5.5
