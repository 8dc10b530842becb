"""Half-power points of a sampled response curve, on a curve the documented interpolant
reproduces exactly (derived here).

:func:`flexshaft.analyses.separation.response_peaks` places the peak at the vertex of the
parabola through 1/A² at the three samples around the sampled maximum and interpolates the
half-power speeds linearly in 1/A² (near a resonance 1/A² is a smooth low-order function of
speed). Take the curve

    1/A(N)² = 1 + |N − N_c|/w,    N_c = 100, w = 10 (any speed unit),

sampled every h = 3.7 with a sample on N_c: the three samples around the maximum are symmetric,
so their parabola's vertex is N_c with 1/A² = 1 (A_c = 1) exactly; 1/A² is linear on each side,
so the linear interpolation in 1/A² hits the half-power level A_c/√2 (1/A² = 2) exactly at
N_c ∓ w = 90 and 110, which lie between samples (N_c ± 7.4 and N_c ± 11.1). Hence

    N_1 = 90, N_2 = 110, AF = N_c/(N_2 − N_1) = 5     (two-sided half-power bandwidth).

Interpolating in 1/A instead puts N_2 near 110.04 (0.4 % on the bandwidth). Tolerance: a few
operations on numbers of order 100, relative 1e-12.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.separation import response_peaks

NC, W, H = 100.0, 10.0, 3.7


def test_half_power_points_are_interpolated_in_inverse_amplitude_squared():
    speeds = NC + H * np.arange(-8, 9)
    amplitude = 1.0 / np.sqrt(1.0 + np.abs(speeds - NC) / W)
    (peak,) = response_peaks(speeds, amplitude)
    assert peak.method == "two-sided"
    assert (peak.speed, peak.amplitude) == pytest.approx((NC, 1.0), rel=1e-12)
    assert (peak.lower, peak.upper) == pytest.approx((NC - W, NC + W), rel=1e-12)
    assert peak.amplification_factor == pytest.approx(NC / (2 * W), rel=1e-12)
