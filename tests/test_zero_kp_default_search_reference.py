"""The default search of a design whose actuators have K_p = 0: run, not refused, not held.

Reference: docs/optimizer.md, "Default search": "the active bearings' K_p (1e5–1e7 N/m, log)
and K_d (0–3000 N s/m), each range widened to the design's own gains", and "The design is not
held (not seeded; the search runs without it) when a K_p is 0 (a log scale)". A log-scale range
cannot reach 0 (log10 0 = −∞), so a zero gain cannot widen it: the K_p range stays the
documented 1e5–1e7 N/m, and the base design, lying outside it, has no values in the search
(derived here from the rule).

Cheap: no model is built.
"""

from __future__ import annotations

import pytest

from flexshaft.design import baseline_design, with_overrides
from flexshaft.optimize import DesignProblem, default_variables


@pytest.mark.parametrize(
    "gains, names",
    [
        ({"bearings[1].kp": 0.0, "bearings[2].kp": 0.0}, ["kp"]),  # equal gains: one variable
        ({"bearings[1].kp": 0.0, "bearings[2].kp": 5e6}, ["amb_1_kp", "amb_2_kp"]),  # one a bearing
    ],
)
def test_a_zero_kp_keeps_the_documented_log_range_and_is_not_held(gains, names):
    design = with_overrides(baseline_design(), gains)
    variables, layup = default_variables(design)
    kp = [v for v in variables if any(p.endswith(".kp") for p in v.paths)]
    assert [v.name for v in kp] == names
    for v in kp:
        assert v.log
        assert (v.lower, v.upper) == (1e5, 1e7)  # the documented range: 0 does not widen it; 5e6 lies in it
    problem = DesignProblem(variables, base=design, layup=layup)
    assert problem.base_values() is None  # not held: K_p = 0 lies outside a log range
