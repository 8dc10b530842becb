"""The projected peak's full-solve checks sit on the half-power (−3 dB) points.

A resonance's bandwidth is read where the amplitude falls to max/√2 (half the power:
|X|² = |X_max|²/2; e.g. Inman, Engineering Vibration, half-power bandwidth 2ζω_n), so the
projection of :mod:`flexshaft.analyses.peak_projection` must verify by full solves the two grid
samples that bracket each max/√2 crossing. Reference curve: the one-degree-of-freedom amplitude
|1/(1 − r² + 2iζr)|, ζ = 0.05, on a grid of 201 points r ∈ [0.5, 1.5]; the bracketing samples are
found here by scanning the curve for the level max/√2 (independent of the code's search).
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.peak_projection import _checked_samples


def test_half_power_crossings_are_checked():
    r = np.linspace(0.5, 1.5, 201)
    zeta = 0.05
    values = np.abs(1.0 / (1.0 - r**2 + 2j * zeta * r))
    peak = int(np.argmax(values))
    level = values[peak] / np.sqrt(2.0)
    left = max(k for k in range(peak) if values[k] < level)  # last sample below, left of the peak
    right = min(k for k in range(peak + 1, r.size) if values[k] < level)  # first below, right
    # the crossings lie inside the grid and away from the peak's own neighbours
    assert 1 < left < peak - 2 and peak + 2 < right < r.size - 2
    checked = set(_checked_samples(values).tolist())
    assert {left, left + 1, right - 1, right} <= checked
