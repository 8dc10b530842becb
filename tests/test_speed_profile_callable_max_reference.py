"""A speed law given as a function: its largest speed where the function peaks, mid-run.

Ω(t) = Ω_max exp(−((t − t₀)/w)²) on [0, T], t₀ = 0.3 T, w = T/50: a narrow run up and back down
(Ω ≥ 0) that peaks at t₀ with Ω_max, off any uniform grid of [0, T] with 2^m + 1 points
(t₀/T = 0.3 is no dyadic fraction), and whose ends are at rest to exp(−225) ≈ 2e-98 Ω_max.
:attr:`SpeedProfile.max_speed` is the largest of the function's sampled speeds (its docstring:
"sampled for a callable"), so it can only fall short of Ω_max, never exceed it. Reference
(closed form): a grid of spacing h has a point within h/2 of t₀, and exp(−u²) ≥ 1 − u², so the
sampled maximum is at least Ω_max (1 − (h/(2w))²). Any grid of 1000 points or more (h ≤ T/999)
thus meets Ω_max to (50/1998)² ≈ 6.3e-4 relative; that bound is the tolerance (the code's grid
measures 9.5e-5 short: its nearest point is 0.2 h from t₀). A coarse grid misses the peak
entirely: three points (0, T/2, T) see at most exp(−100) Ω_max, and the two ends alone 2e-98.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.analyses.speed_profile import SpeedProfile

T, TOP = 4.0, 300.0
PEAK, WIDTH = 0.3 * T, T / 50


def _law(t: float) -> float:
    return TOP * math.exp(-(((t - PEAK) / WIDTH) ** 2))


def test_the_largest_speed_of_a_run_up_and_down_is_its_mid_run_peak():
    profile = SpeedProfile.from_callable(_law, T)
    assert profile.speed(0.0) == pytest.approx(0.0, abs=1e-12 * TOP)
    assert profile.speed(T) == pytest.approx(0.0, abs=1e-12 * TOP)
    assert profile.speed(PEAK) == pytest.approx(TOP, rel=1e-15)
    shortfall = (T / 999 / (2 * WIDTH)) ** 2  # (h/(2w))² for any grid of >= 1000 points
    assert TOP * (1 - shortfall) <= profile.max_speed <= TOP
