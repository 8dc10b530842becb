"""One resonance sampled with a flat top is one peak (mutation hunt h33c).

:func:`~flexshaft.analyses.separation.response_peaks` on one resonance,
A(N) = 1/√((N − 100)² + 4) (a single-degree-of-freedom peak's magnitude near its top), sampled at
100 ± 0.5, ± 1.5, …, ± 9.5 rad/s: the two samples nearest the top are equal exactly ((±0.5)²
alike in binary), a flat top. It is one resonance, so one critical speed: one peak, between
those two samples.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.separation import response_peaks


def test_a_flat_topped_resonance_is_one_peak():
    speeds = 100.0 + np.arange(-9.5, 10.0, 1.0)
    amplitude = 1.0 / np.sqrt((speeds - 100.0) ** 2 + 4.0)
    top = np.flatnonzero(amplitude == amplitude.max())
    assert top.size == 2  # the premise: two equal samples at the top
    peaks = response_peaks(speeds, amplitude)
    assert len(peaks) == 1
    assert 99.5 <= peaks[0].speed <= 100.5
