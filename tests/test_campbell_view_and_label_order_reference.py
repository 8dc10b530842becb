"""The Campbell diagram keeps the verdict's criticals in view and its mode numbers on their curves.

Hand-made diagrams (plain arrays, no model). The references:

* the `campbell_figure` docstring: the verdict's critical speeds (``response_criticals``) are
  "marked on the 1× line as squares and labelled with their speed and AF": a critical n_c is at
  (n_c, n_c/60) [rpm, Hz], so the frequency axis must reach n_c/60 for the mark and its label to
  be shown, also when n_c/60 is above every drawn mode and 1× crossing (a response peak beyond
  ``max_critical_rpm``, or of a mode the diagram does not track);
* README.md:176, "Modes are numbered from 1": the number "k" names the k-th column's curve and
  sits at the height of that curve's last finite point (the rule of
  tests/test_campbell_labels_reference.py), here for two curves that cross (a forward mode
  rising from 20 to 80 Hz, a backward one falling from 60 to 30 Hz), so that their last points
  are in the reverse of the mode order;
* `spread`'s docstring (labels.py): "Move 1-D label positions apart by at least ``min_gap``, as
  little as possible. Positions keep their order": positions already ``min_gap`` apart are
  returned unchanged, in the caller's order; two positions a, b (a > b) closer than g move by
  the least squares displacement subject to a' − b' ≥ g, the symmetric split
  a' = (a + b + g)/2, b' = (a + b − g)/2 (Lagrange: both move by (g − (a − b))/2).

Data anchors go through the axes' pixel transform and back (an affine map and its inverse:
rounding of order 1e-13 of the axis range): compared at rel 1e-9, far below any misplacement
(the wrong curve is 50 Hz away, more than half the axis). `spread` on exact binary fractions:
compared at 1e-12. Agg, nothing written.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from flexshaft.plot.campbell import campbell_figure  # noqa: E402
from flexshaft.plot.labels import spread  # noqa: E402
from tests.test_campbell_labels_reference import _texts  # noqa: E402

SPEEDS = np.linspace(0.0, 6000.0, 13)  # [rpm]
REL = 1e-9


def test_a_verdict_critical_above_every_mode_is_in_view():
    """Modes at 20 and 70 Hz (1× crossings at 1200 and 4200 rpm); the verdict's critical at
    5400 rpm is on the 1× line at 5400/60 = 90 Hz, above both: its square and its label are
    inside the frequency axis."""
    n = SPEEDS.size
    freqs = np.column_stack([np.full(n, 20.0), np.full(n, 70.0)])
    whirl = np.array([["forward", "forward"]] * n)
    fig = campbell_figure(
        SPEEDS, freqs, whirl, critical_speeds_rpm=[1200.0, 4200.0], response_criticals=[(5400.0, 8.0)]
    )
    ax = fig.axes[0]
    low, high = ax.get_ylim()
    (square,) = [ln for ln in ax.get_lines() if ln.get_marker() == "s"]
    np.testing.assert_allclose(square.get_ydata(), [90.0], rtol=1e-12)
    assert low <= 90.0 <= high, (low, high)
    label = _texts(ax)["5400 rpm, AF 8"]
    assert label.xy[1] == pytest.approx(90.0, rel=REL)
    assert low <= label.xy[1] <= high
    plt.close(fig)


def test_mode_numbers_follow_their_curves_where_the_curves_cross():
    """Mode 1 (forward) rises 20 -> 80 Hz, mode 2 (backward) falls 60 -> 30 Hz: at 6000 rpm mode 1
    ends at 80 Hz and mode 2 at 30 Hz, 50 Hz apart (no spreading needed): "1" is anchored at
    80 Hz, "2" at 30 Hz."""
    n = SPEEDS.size
    freqs = np.column_stack([np.linspace(20.0, 80.0, n), np.linspace(60.0, 30.0, n)])
    whirl = np.array([["forward", "backward"]] * n)
    fig = campbell_figure(SPEEDS, freqs, whirl)
    texts = _texts(fig.axes[0])
    assert texts["1"].xy[1] == pytest.approx(80.0, rel=REL)
    assert texts["2"].xy[1] == pytest.approx(30.0, rel=REL)
    plt.close(fig)


def test_spread_keeps_the_callers_order():
    """Already apart: unchanged, in the given (unsorted) order; two too close: the symmetric split
    a' = (a + b + g)/2, b' = (a + b − g)/2 with a = 1, b = 0, g = 2 -> 1.5, −0.5, in the given order."""
    np.testing.assert_allclose(spread([10.0, 0.0, 5.0], 2.0), [10.0, 0.0, 5.0], rtol=0, atol=1e-12)
    np.testing.assert_allclose(spread([1.0, 0.0], 2.0), [1.5, -0.5], rtol=0, atol=1e-12)
