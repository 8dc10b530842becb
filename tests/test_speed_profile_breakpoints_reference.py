"""A speed table's rate at its breakpoints (mutation hunt h33c).

:class:`~flexshaft.analyses.speed_profile.SpeedProfile` documents a table's Ω̇ as
right-continuous at a breakpoint: the rate of the segment that starts there. The table
(0, 0) → (2, 100) → (5, 160) → (6, 160) [s, rad/s] has slopes 50, 20 and 0 rad/s² (by hand), so
at t = 2 s the run is already on the 20 rad/s² ramp and at t = 5 s in its dwell (Ω̇ = 0: the
imbalance force there is Ω² alone, no −iΩ̇ part); the speed is continuous, 100 and 160 rad/s.
Exact binary arithmetic: the rates compared exactly, the interpolated speeds to 1e-12.
"""

from __future__ import annotations

import pytest

from flexshaft.analyses.speed_profile import SpeedProfile


def test_the_rate_at_a_breakpoint_is_the_next_segments():
    p = SpeedProfile.table([0.0, 2.0, 5.0, 6.0], [0.0, 100.0, 160.0, 160.0])
    assert p.acceleration(2.0) == 20.0
    assert p.acceleration(5.0) == 0.0
    assert p.acceleration(0.0) == 50.0
    assert [p.speed(t) for t in (2.0, 5.0)] == pytest.approx([100.0, 160.0], rel=1e-12)


def test_the_largest_speed_of_a_run_down_and_of_a_rise_and_fall():
    """``max_speed`` (the Monte-Carlo run-up's basis size and output step read it) is the
    table's largest speed, not its last: a run-down from 300 to 100 rad/s peaks at its start,
    the table (0, 0) → (1, 250) → (3, 40) at its breakpoint t = 1 s (read off the tables)."""
    assert SpeedProfile.constant_acceleration(300.0, 100.0, 50.0).max_speed == 300.0
    assert SpeedProfile.table([0.0, 1.0, 3.0], [0.0, 250.0, 40.0]).max_speed == 250.0


def test_a_dwell_below_the_ramps_round_off_adds_no_breakpoint():
    """``runup --dwell 1e-300 --duration 1`` ended in an internal error (exit 4): the table
    [0, 1, 1 + 1e-300] is [0, 1, 1] in floating point, which the table refuses as not
    increasing. Such a dwell adds no time (1 + 1e-300 == 1 exactly), so the profile is the
    ramp alone, 0 -> 100 rad/s in 1 s; a dwell of 0.5 s still adds its breakpoint (1.5 s)."""
    for dwell in (1e-300, 5e-324):
        p = SpeedProfile.constant_acceleration(0.0, 100.0, 100.0, dwell=dwell)
        assert p.duration == 1.0 and list(p.times) == [0.0, 1.0]
    p = SpeedProfile.constant_acceleration(0.0, 100.0, 100.0, dwell=0.5)
    assert list(p.times) == [0.0, 1.0, 1.5] and list(p.speeds) == [0.0, 100.0, 100.0]
