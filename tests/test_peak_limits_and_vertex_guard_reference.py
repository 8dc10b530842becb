"""Half-power limits at the data's ends and the vertex guard of a response peak (hunt h45a).

References (the definitions in :mod:`flexshaft.analyses.separation`, worked by hand).

1. A peak that does not fall to A_c/√2 on either side before the data end is ``bounded``: its
   limits are the data's ends and ``AF = N_c / (N_right − N_left)`` is an upper bound. Samples
   s = 0..4, A = (0.9, 0.95, 1, 0.95, 0.9): the parabola through 1/A² at s = 1, 2, 3 is
   symmetric about s = 2 with 1/A² = 1 there, so N_c = 2, A_c = 1; the level 1/√2 = 0.707 lies
   below every sample, so the limits are 0 and 4: bandwidth 4, AF = 2/4 = 0.5 (exact up to
   round-off of the parabola's coefficients: rel 1e-12).

2. The vertex guard: the sampled maximum is kept when the parabola's half-power level lies
   above the SMALLER neighbour sample (the peak is narrower than the sampling). A = (0.1, 0.5,
   1, 0.85, 0.1) at s = 0..4: 1/A² = (4, 1, 1/0.7225) at x = −1, 0, 1 gives c2 = (0.3841 + 3)/2
   = 1.6920, c1 = 0.3841 − 1.6920 = −1.3080, vertex dx = 0.3865, 1/A² there 1 − 0.2528 = 0.7472,
   A = 1.157, half-power level 0.818: above the smaller neighbour 0.5 (below the larger 0.85),
   so the peak is the sample itself, N_c = 2, A_c = 1 exactly.

3. A half-power crossing toward a zero-amplitude sample: 1/A² is infinite there, so the
   crossing is interpolated linearly in A itself. A = (0, 0, 1, 0, 0) at s = 0..4: the peak is
   the sample (a zero neighbour: no parabola), level 1/√2, and A falls linearly from 1 at s = 2
   to 0 at s = 1 and s = 3: N_{1,2} = 2 ∓ (1 − 1/√2), bandwidth 2 − √2 and
   AF = 2/(2 − √2) = 2 + √2 (rel 1e-12).
CPU: pure array arithmetic, well under 10 ms.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.separation import response_peaks


def test_a_peak_that_never_falls_to_half_power_is_bounded_by_the_data_ends():
    (peak,) = response_peaks(np.arange(5.0), [0.9, 0.95, 1.0, 0.95, 0.9])
    assert peak.method == "bounded"
    assert (peak.lower, peak.upper) == (None, None)
    assert (peak.lower_limit, peak.upper_limit) == (0.0, 4.0)
    assert peak.speed == pytest.approx(2.0, rel=1e-12)
    assert peak.amplification_factor == pytest.approx(0.5, rel=1e-12)


def test_the_sampled_maximum_is_kept_when_the_vertex_level_tops_the_smaller_neighbour():
    s, a = np.arange(5.0), np.array([0.1, 0.5, 1.0, 0.85, 0.1])
    y = 1.0 / a[1:4] ** 2  # hand-worked parabola, the docstring's numbers
    c2 = ((y[2] - y[1]) - (y[1] - y[0])) / 2.0
    c1 = (y[2] - y[1]) - c2
    dx = -c1 / (2 * c2)
    level = (c0 := y[1] + dx * (c1 + c2 * dx)) ** -0.5 / np.sqrt(2.0)
    assert 0.5 < level < 0.85 and c0 > 0  # the case the guard is about
    peak = response_peaks(s, a)[0]
    assert (peak.speed, peak.amplitude) == (2.0, 1.0)


def test_a_crossing_toward_a_zero_sample_is_linear_in_the_amplitude():
    (peak,) = response_peaks(np.arange(5.0), [0.0, 0.0, 1.0, 0.0, 0.0])
    assert (peak.speed, peak.amplitude) == (2.0, 1.0)
    half = 1.0 - 1.0 / np.sqrt(2.0)
    assert (peak.lower, peak.upper) == (pytest.approx(2.0 - half, rel=1e-12), pytest.approx(2.0 + half, rel=1e-12))
    assert peak.amplification_factor == pytest.approx(2.0 + np.sqrt(2.0), rel=1e-12)
