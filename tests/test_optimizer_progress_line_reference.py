"""The optimizer's progress line counts the feasible designs the constraints make feasible.

Reference: docs/optimizer.md, "Constraints": each check enters as its "normalised margin (≥ 0
passes)". The stand-in problem of tests/test_optimizer_setup_reference.py (imported, not
copied): one variable, the wall w in [1, 4] mm, outputs mass = 1000 w and margin = 1000 w − 2,
constraint margin >= 0; so a design is feasible exactly when w >= 2 mm, and the progress line's
"N feasible" after the one random generation is the number of sampled walls of at least 2 mm,
counted here from the walls by that rule (the samples of seed 3 hold both kinds). The line also
names the 8 designs evaluated (the budget). Every design being valid, the count is the same as
evaluations.nc's ``feasible`` column (the dataset's own bookkeeping, checked elsewhere).

Cheap: analytic output function (no model built), 8 evaluations in memory.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

pytest.importorskip("xarray")

from flexshaft.optimize import optimize  # noqa: E402
from tests.test_optimizer_setup_reference import _wall_problem  # noqa: E402


def test_progress_line_counts_the_designs_that_meet_the_constraint():
    lines: list[str] = []
    result = optimize(_wall_problem(), 8, None, seed=3, method="random", progress=lines.append)
    walls = result.evaluations["wall"].values
    n_feasible = int(np.sum(walls >= 0.002))  # margin = 1000 w - 2 >= 0
    assert 0 < n_feasible < walls.size == 8
    (line,) = lines  # one generation of 8
    match = re.search(r"(\d+) designs evaluated \(\d+ computed\), (\d+) feasible", line)
    assert match is not None, line
    assert (int(match.group(1)), int(match.group(2))) == (8, n_feasible)
