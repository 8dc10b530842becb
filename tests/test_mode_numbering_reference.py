"""Which modes a table lists and numbers: the lowest damped frequencies, a list of n the start of
a longer one (:func:`flexshaft.analyses.eigen.lowest_modes`).

Reference: a hand-made spectrum of damped roots s = −ζω_n + iω_n√(1 − ζ²), whose damped
frequencies Im s are known exactly. A heavily damped mode (ζ = 0.6, ω_n = 120 rad/s, damped
frequency 96 rad/s) has a larger |s| than two light modes (ω_n = 100 and 110 rad/s, ζ = 0.01) but
the lowest damped frequency of the three: the tables number by damped frequency, so it is mode 1
however many modes are asked for (among the 2n of lowest |s|), and the n modes listed are the
first n of the n + 1. Exact comparisons: the selection is a sort of exactly representable keys.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.eigen import lowest_modes


def _root(omega_n: float, zeta: float) -> complex:
    return complex(-zeta * omega_n, omega_n * np.sqrt(1 - zeta**2))


def test_a_heavily_damped_mode_of_lower_damped_frequency_is_numbered_first():
    s = np.array([_root(100.0, 0.01), _root(110.0, 0.01), _root(120.0, 0.6), _root(400.0, 0.01), _root(500.0, 0.02)])
    assert s[2].imag < s[0].imag < s[1].imag and abs(s[2]) > abs(s[1])
    two, three = lowest_modes(s, 2), lowest_modes(s, 3)
    assert list(two) == [2, 0]  # 96 rad/s, then 100 rad/s
    assert list(three) == [2, 0, 1]
    assert list(three[:2]) == list(two)  # a list of n modes is the start of a longer one
