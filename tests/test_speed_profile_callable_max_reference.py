"""A speed law given as a function: its largest speed where the function peaks, mid-run.

Ω(t) = Ω_max sin(π t/T) on [0, T] (a run up and back down, Ω ≥ 0) peaks at t = T/2 with
Ω_max; its two ends are at rest (sin 0 = sin π = 0, the latter to round-off, ~1e-14 Ω_max).
:attr:`SpeedProfile.max_speed` samples a function's speed on a grid of [0, T]; the grid of 1025
points the docstring's sampling uses holds T/2 exactly, so the closed form's maximum is met to
round-off (1e-12). A second law, Ω(t) = Ω_max (1 − (2t/T − 1)²) (a parabola, the same peak)
checks that nothing but the function's own values decides.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.analyses.speed_profile import SpeedProfile

T, TOP = 4.0, 300.0


@pytest.mark.parametrize(
    "law",
    [lambda t: TOP * math.sin(math.pi * t / T), lambda t: TOP * (1.0 - (2.0 * t / T - 1.0) ** 2)],
    ids=["sine", "parabola"],
)
def test_the_largest_speed_of_a_run_up_and_down_is_its_mid_run_peak(law):
    profile = SpeedProfile.from_callable(law, T)
    assert profile.speed(0.0) == pytest.approx(0.0, abs=1e-12 * TOP)
    assert profile.speed(T) == pytest.approx(0.0, abs=1e-12 * TOP)
    assert profile.max_speed == pytest.approx(TOP, rel=1e-12)
