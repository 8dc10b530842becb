"""A flat shoulder above the half-power level does not stop the half-power walk (mutation hunt
h35d).

The half-power point on a side is where the curve first falls to A_c/sqrt(2) (API 684 §2.8.2;
flexshaft.analyses.separation); it is undefined only where the curve RISES again into a
neighbouring peak before falling that far. A shoulder (equal samples, as a response that
saturates between two close modes, or amplitudes rounded in a test rig's log) neither falls
below the level nor rises: the walk must go on through it.

Hand derivation. Speeds 1, 2, ..., 11 and amplitudes
0.1, 0.2, 0.5, 0.8, 1.0, 0.8, 0.8, 0.8, 0.5, 0.2, 0.1: one interior peak, at 5 (symmetric
neighbours, so the parabola through 1/A^2 has its vertex on the sample: N_c = 5, A_c = 1); the
level 1/sqrt(2), i.e. 1/A^2 = 2. Interpolating 1/A^2 linearly between the last sample above and
the first at or below the level (the module's documented interpolation): between 0.8 (1/A^2 =
1.5625) and 0.5 (1/A^2 = 4) the level lies a fraction (2 - 1.5625)/(4 - 1.5625) = 7/39 of the
way, so N_1 = 4 - 7/39 and, past the shoulder 6-8, N_2 = 8 + 7/39:
AF = 5 / (4 + 14/39) = 195/170. Exact arithmetic up to rounding: 1e-12.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.separation import response_peaks

SPEEDS = np.arange(1.0, 12.0)
AMPLITUDE = np.array([0.1, 0.2, 0.5, 0.8, 1.0, 0.8, 0.8, 0.8, 0.5, 0.2, 0.1])


def test_the_walk_crosses_a_shoulder_to_the_half_power_point():
    (peak,) = response_peaks(SPEEDS, AMPLITUDE)
    assert peak.speed == pytest.approx(5.0, rel=1e-12) and peak.amplitude == pytest.approx(1.0, rel=1e-12)
    assert peak.method == "two-sided"
    assert peak.lower == pytest.approx(4.0 - 7.0 / 39.0, rel=1e-12)
    assert peak.upper == pytest.approx(8.0 + 7.0 / 39.0, rel=1e-12)
    assert peak.amplification_factor == pytest.approx(195.0 / 170.0, rel=1e-12)
