"""A projected orbit whose largest sample is at an end: its half-power samples are still checked
(mutation hunt 101c).

Rule (flexshaft/analyses/peak_projection.py, module docstring): the full model is solved again
"at the samples that make the peak's reported numbers (every local maximum and minimum of the
projected orbit with its neighbours, the ends, and the two samples on each side of each
maximum's half-power level, where the bandwidth is interpolated". A round of samples can sit
on one flank of a critical speed, its largest orbit at the first (or last) speed: that sample is
the round's maximum, and the half-power crossing next to it is where the bandwidth is
interpolated (:func:`~flexshaft.analyses.separation._half_power_side` walks from the peak to
the first sample at or below max/√2), so the two samples around max/√2 are checked.
tests/test_peak_checked_samples_reference.py checks the rule on inner maxima only.

Reference curve: the Jeffcott rotor's imbalance orbit per unit eccentricity, |r|/e = ρ² /
√((1 − ρ²)² + (2ζρ)²), ρ = Ω/ω_n, ζ = 0.05 (closed form), on one flank of the resonance:

* above it, ρ = 1.02 ... 1.50 (25 samples, step 0.02): decreasing from 9.483 at ρ = 1.02 (by
  hand: 1.0404/√(0.0404² + 0.102²) = 1.0404/0.1097); max/√2 = 6.706 lies between sample 2
  (ρ = 1.06: 1.1236/√(0.1236² + 0.106²) = 6.901) and sample 3 (ρ = 1.08: 5.880). Required: the
  ends 0 and 24 and the half-power pair 2 and 3.
* below it, ρ = 0.60 ... 0.98 (20 samples, step 0.02): increasing to 9.086 at ρ = 0.98;
  max/√2 = 6.425 lies between sample 17 (ρ = 0.94: 5.906) and 18 (ρ = 0.96: 7.436). Required:
  the ends 0 and 19 and the half-power pair 17 and 18.

The tests assert only what the quoted rule requires, as subsets of the checked samples:
{0, 2, 3, 24} and {0, 17, 18, 19} (the rule's "local maximum ... with its neighbours" is read
for inner extrema only, so a neighbour of an end maximum is neither required nor excluded).
Leaving the end maximum's half-power pair unchecked checks {0, 1, 24} and {0, 18, 19} (review
r121), missing 2, 3 and 17. Indices are exact.

CPU: two arrays of 25 numbers: well under 0.01 s.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.peak_projection import _checked_samples

ZETA = 0.05


def _orbit(rho: np.ndarray) -> np.ndarray:
    return rho**2 / np.sqrt((1.0 - rho**2) ** 2 + (2.0 * ZETA * rho) ** 2)


def test_the_half_power_pair_next_to_a_maximum_at_the_first_sample_is_checked():
    values = _orbit(1.02 + 0.02 * np.arange(25))
    assert np.all(np.diff(values) < 0)  # one flank: the largest orbit at the first speed
    assert abs(values[0] - 9.483) <= 1e-3 and values[3] < values[0] / np.sqrt(2.0) < values[2]
    assert {0, 2, 3, 24} <= set(_checked_samples(values).tolist())


def test_the_half_power_pair_next_to_a_maximum_at_the_last_sample_is_checked():
    values = _orbit(0.60 + 0.02 * np.arange(20))
    assert np.all(np.diff(values) > 0)  # one flank: the largest orbit at the last speed
    assert abs(values[-1] - 9.086) <= 1e-3 and values[17] < values[-1] / np.sqrt(2.0) < values[18]
    assert {0, 17, 18, 19} <= set(_checked_samples(values).tolist())
