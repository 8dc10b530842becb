"""The samples checked by full solves when a peak's largest sample is at the edge of the speed
window, on Den Hartog's unbalance response (derived here).

:func:`flexshaft.analyses.peak_projection._checked_samples` documents its rule: both ends of the
round, every local maximum and minimum with its two neighbours (the three samples of the
parabolic vertex), and around each maximum the two samples on either side of max/√2. A window
that stops short of the critical speed has its largest sample at an end: that sample is the
window's maximum, and its inner neighbour is one of the vertex's three samples (the other is
outside the window), so it must be checked like any maximum's neighbour.

Reference curve: the Jeffcott rotor's unbalance orbit (Den Hartog), |x|/e = r²/√((1 − r²)² +
(2ζr)²) with r = Ω/ω_n, ζ = 0.05. With u = r² and D = (1 − u)² + 4ζ²u, d(u²/D)/du =
2u(1 − u(1 − 2ζ²))/D², positive for r < 1/√(1 − 2ζ²) = 1.0025 and negative above: sampled on
r = 0.50, 0.51, ..., 0.99 the curve rises strictly (no interior extremum; largest sample last,
9.71), and on r = 1.01, ..., 1.50 it falls strictly (largest sample first, 9.91). Each window
crosses its half-power level max/√2 inside (between r = 0.95 and 0.96, and between r = 1.05 and
1.06): that pair of samples is checked too.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.peak_projection import _checked_samples

ZETA = 0.05


def _den_hartog(r: np.ndarray) -> np.ndarray:
    return r * r / np.sqrt((1 - r * r) ** 2 + (2 * ZETA * r) ** 2)


def _crossing_pair(values: np.ndarray, top: int) -> set[int]:
    """The two samples either side of max/√2 on the flank away from ``top``, by a plain loop."""
    level = values[top] / np.sqrt(2.0)
    order = range(values.size) if top == values.size - 1 else range(values.size - 1, -1, -1)
    last_below = None
    for j in order:
        if j == top:
            break
        if values[j] < level:
            last_below = j
    assert last_below is not None
    return {last_below, last_below + (1 if top == values.size - 1 else -1)}


def test_largest_sample_last_has_its_inner_neighbour_checked():
    r = np.linspace(0.50, 0.99, 50)
    values = _den_hartog(r)
    assert np.all(np.diff(values) > 0)  # below the peak (r < 1.0025): rising, no interior extremum
    n = values.size
    checked = set(_checked_samples(values).tolist())
    assert {n - 2, n - 1} <= checked  # the window's maximum and its inner neighbour
    assert _crossing_pair(values, n - 1) == {45, 46}  # r = 0.95, 0.96 (docstring)
    assert {0} | _crossing_pair(values, n - 1) <= checked


def test_largest_sample_first_has_its_inner_neighbour_checked():
    r = np.linspace(1.01, 1.50, 50)
    values = _den_hartog(r)
    assert np.all(np.diff(values) < 0)  # above the peak (r > 1.0025): falling, no interior extremum
    n = values.size
    checked = set(_checked_samples(values).tolist())
    assert {0, 1} <= checked  # the window's maximum and its inner neighbour
    assert _crossing_pair(values, 0) == {4, 5}  # r = 1.05, 1.06 (docstring)
    assert {n - 1} | _crossing_pair(values, 0) <= checked
