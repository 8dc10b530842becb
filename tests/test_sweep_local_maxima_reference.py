"""The local maxima that place the sweep's snapshots and resonance checks, by inspection.

:func:`flexshaft.analyses.sweep_projection._local_maxima` picks where the projected sweep adds
full solves (the error indicator's maxima) and where it measures the resonance sensitivity
(the response's maxima). Its contract (docstring): the indices of the local maxima, the ends
of the speed grid included (a response still rising at the top of the sweep peaks there),
only positive values, largest first. The expected indices below are read off the short
sequences by eye (a sample is a maximum when it is >= both neighbours, a missing neighbour
beyond an end counting as -inf); integers only, so the comparison is exact.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.sweep_projection import _local_maxima


def test_a_maximum_at_either_end_of_the_grid_counts() -> None:
    # 3 at index 0 (> 1), 2 at index 2 (> 1 and > 0.5), 4 at the top end (> 0.5): largest first
    values = np.array([3.0, 1.0, 2.0, 0.5, 4.0])
    assert _local_maxima(values).tolist() == [4, 0, 2]


def test_a_monotone_rise_peaks_at_the_top_end_only() -> None:
    assert _local_maxima(np.array([0.1, 0.2, 0.4, 0.8])).tolist() == [3]
    assert _local_maxima(np.array([0.8, 0.4, 0.2, 0.1])).tolist() == [0]


def test_zero_values_are_not_maxima() -> None:
    assert _local_maxima(np.zeros(4)).tolist() == []
