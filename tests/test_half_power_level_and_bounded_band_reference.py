"""The half-power level of a peak sampled off its top, and the refined band of a bounded peak
(hunt h55c).

References (the definitions of :mod:`flexshaft.analyses.separation` and docs/requirements.md,
"Critical speeds" steps 3-4, worked by hand here).

1. The half-power level is A_c/√2 with A_c the PEAK's amplitude (the vertex of the parabola
   through 1/A² at the three samples around the sampled maximum), not the largest sample's.
   Samples s = 8..12 with y = 1/A² = (3, 1.15625, 1.00625, 1.05625, 3): the middle three are
   y = 1 + 0.1 (x − 0.25)² at x = s − 10 = −1, 0, 1, so the parabola is that one, its vertex
   N_c = 10.25 with y = 1, A_c = 1 (the largest sample is only 1.00625^-1/2 = 0.99689). Its
   half-power level is y = 2 (A = 1/√2; the guard holds: 1/√2 < min(A(9), A(11)) = 0.930).
   The crossings interpolated linearly in 1/A²:

       N_1 = 9 − (2 − 1.15625)/(3 − 1.15625) = 9 − 0.84375/1.84375,
       N_2 = 11 + (2 − 1.05625)/(3 − 1.05625) = 11 + 0.94375/1.94375,

   AF = 10.25/(N_2 − N_1) = 3.4827... A level taken from the sample (y = 2.0125) moves each
   crossing by ~0.007 and the AF by 0.5 %. Tolerance 1e-12 relative: a handful of divided
   differences of O(1) numbers, round-off ~1e-15.

2. A bounded peak (the curve rises into its neighbours before falling to half power) takes its
   band from the flanking minima, and is refined until the sample intervals that contain the
   band's speeds are at most 1/20 of it. A(s) = 10 + cos s has its peak at 2π (A_c = 11, level
   7.78, below the minimum 9: never reached) and its flanking minima at π and 3π exactly, so
   the band is 2π and the AF bound 2π/2π = 1. Started from samples fine at the top (0.07-0.15
   apart) but 1.9-2.4 apart at the minima, the refined limits are the sampled minima; the true
   minimum lies within one resolved interval (≤ band/20 = π/10 ≈ 0.31) of each, so
   |N_left − π|, |N_right − 3π| ≤ 0.33 (the band itself known to ± that) and the AF within
   ±12 % of 1 (the peak's speed, sampled 0.07-0.15 apart at the top, is exact to about 1e-9, so
   the band's error is the limits' alone). The starting samples' minima 2.5 and 9.9 miss π and 3π by 0.64 and 0.48.
CPU: a few hundred evaluations of a cosine, well under 10 ms.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.separation import resolve_peak, response_peaks


def test_the_half_power_level_is_taken_from_the_vertex_not_the_sample():
    s = np.arange(8.0, 13.0)
    y = np.array([3.0, 1.0 + 0.1 * 1.25**2, 1.0 + 0.1 * 0.25**2, 1.0 + 0.1 * 0.75**2, 3.0])
    (peak,) = response_peaks(s, y**-0.5)
    assert peak.method == "two-sided"
    assert peak.speed == pytest.approx(10.25, rel=1e-12)
    assert peak.amplitude == pytest.approx(1.0, rel=1e-12)
    lower = 9.0 - 0.84375 / 1.84375
    upper = 11.0 + 0.94375 / 1.94375
    assert peak.lower == pytest.approx(lower, rel=1e-12)
    assert peak.upper == pytest.approx(upper, rel=1e-12)
    assert peak.amplification_factor == pytest.approx(10.25 / (upper - lower), rel=1e-12)


def test_a_bounded_peak_is_refined_until_its_flanking_minima_are_resolved():
    def response(speeds):
        return 10.0 + np.cos(speeds)

    s = np.array([0.3, 2.5, 4.5, 6.18, 6.33, 6.40, 8.0, 9.9, 12.3])
    start = response_peaks(s, response(s))
    assert [p.method for p in start] == ["bounded"]  # the case: no half-power point either side
    assert (start[0].lower_limit, start[0].upper_limit) == (2.5, 9.9)
    peak = resolve_peak(response, s, response(s), near=2 * np.pi)
    assert peak is not None and peak.resolved and peak.method == "bounded"
    resolution = 2 * np.pi / 20 * 1.05  # one resolved interval, with its band known to 5 %
    assert abs(peak.lower_limit - np.pi) <= resolution
    assert abs(peak.upper_limit - 3 * np.pi) <= resolution
    assert peak.speed == pytest.approx(2 * np.pi, abs=resolution)
    assert peak.amplification_factor == pytest.approx(1.0, rel=0.12)
