"""Overdamped stable roots come after every vibration mode in the numbered mode list.

Reference: docs/model.md (*Modal analysis*): modes are numbered by damped frequency Im s, the n of
lowest Im s among the 2n of lowest |s|, and "Overdamped stable roots (Im s below a tenth of
|s|, ζ > 0.995 ...) come after every vibration mode, so that they never take one's place".

The roots are those of viscously damped single-DOF oscillators, derived here:
s = −ζω_n + iω_n√(1 − ζ²), so Im s / |s| = √(1 − ζ²): 0.063 for ζ = 0.998 (overdamped by the
rule) and 0.141 for ζ = 0.99 (a vibration mode by the rule). The two cases pin the threshold
between these ratios, far from it on both sides (no rounding question).
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.eigen import lowest_modes


def root(zeta: float, omega_n: float) -> complex:
    """s = −ζω_n + iω_n√(1 − ζ²) [rad/s] of m ẍ + c ẋ + k x = 0, ω_n = √(k/m), ζ = c/(2mω_n)."""
    return complex(-zeta * omega_n, omega_n * np.sqrt(1.0 - zeta * zeta))


def test_a_root_past_the_overdamped_threshold_never_takes_a_mode_place():
    """A lightly damped mode (ζ = 0.01, ω_n = 100 rad/s) and a stable root with ζ = 0.998 at
    ω_n = 50 rad/s: the latter has the lower |s| (50) and the lower Im s (3.2), but Im s / |s| =
    0.063 < 0.1 makes it overdamped, so the one mode asked for is the vibration mode (index 0),
    and with two asked for the overdamped root comes second."""
    s = np.array([root(0.01, 100.0), root(0.998, 50.0)])
    assert list(lowest_modes(s, 1)) == [0]
    assert list(lowest_modes(s, 2)) == [0, 1]


def test_a_heavily_damped_root_below_the_threshold_is_still_a_mode():
    """The counter-case: ζ = 0.99 at ω_n = 50 rad/s has Im s / |s| = 0.141 > 0.1, a vibration
    mode by the rule, and its damped frequency 7.1 rad/s is the lowest: it is mode 1."""
    s = np.array([root(0.01, 100.0), root(0.99, 50.0)])
    assert list(lowest_modes(s, 1)) == [1]
    assert list(lowest_modes(s, 2)) == [1, 0]
