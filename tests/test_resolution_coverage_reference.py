"""The grids of every resolution cover what the checks hold a design against.

The separation check (API 617/684, :mod:`flexshaft.analyses.separation`) can ask a critical
speed above the operating speed Ω_op for at most SM = min(26, 10 + 17 (1 − 1/(AF − 1.5))) % of
Ω_op: 26 %, reached by a lightly damped peak (AF → ∞ gives 27 %, capped). A critical speed the
search never reaches cannot fail that check, so the spin-up scan (the range searched for lateral
critical speeds) and the Campbell diagram must reach (1 + 0.26) Ω_op at every preset; and the
whirl-stability speeds must reach the speed the default onset requirement asks for,
(1 + 0.15) Ω_op (docs/requirements.md), with the scans starting from (near) rest.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.analyses.separation import required_separation_margin
from flexshaft.design.requirements import Requirements
from flexshaft.resolution import RESOLUTIONS

OPERATING = 503.0  # rad/s, any positive speed: the ranges are fractions of it


@pytest.mark.parametrize("name", sorted(RESOLUTIONS))
def test_the_critical_speed_search_reaches_the_largest_margin_the_separation_rule_asks(name):
    resolution = RESOLUTIONS[name]
    largest = required_separation_margin(math.inf, "above")
    assert largest == pytest.approx(0.26, abs=1e-15)
    assert resolution.spin_speeds(OPERATING)[-1] >= (1 + largest) * OPERATING
    assert resolution.spin_speeds(OPERATING)[0] < 0.05 * OPERATING
    if resolution.campbell_speeds:
        grid = resolution.campbell_grid(OPERATING)
        assert grid[0] == 0.0 and grid[-1] >= (1 + largest) * OPERATING


@pytest.mark.parametrize("name", sorted(RESOLUTIONS))
def test_the_whirl_speeds_reach_the_default_onset_requirement(name):
    speeds = RESOLUTIONS[name].stability_speeds(OPERATING)
    assert speeds[0] == 0.0
    assert speeds[-1] >= (1 + Requirements().min_onset_margin) * OPERATING
