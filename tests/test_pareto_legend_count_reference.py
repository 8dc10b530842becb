"""The Pareto figure's legend counts the designs it draws.

pareto_front's docstring (the code's API contract): "x, y: Two objectives of every evaluated
design (NaN: no result, not drawn)". The legend entries "fails a requirement (n)" and "passes
every requirement (n)" name the markers of each series, so a design with no result is in
neither count. Reference: the designs below, counted by hand (exact integers). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.optimize import pareto_front  # noqa: E402


def test_designs_without_a_result_are_not_counted_in_the_legend():
    # 2 failing designs drawn, 2 failing ones with no result (NaN), 3 passing drawn, 1 passing NaN
    x = np.array([1.0, 2.0, np.nan, 1.5, 1.2, np.nan, 1.8, np.nan])
    y = np.array([0.5, 0.4, 0.3, 0.6, 0.45, np.nan, 0.55, 0.1])
    feasible = np.array([False, False, False, True, True, False, True, True])
    fig = pareto_front(x, y, feasible, [1.2, 1.5], [0.45, 0.6], senses=("min", "max"))
    ax = fig.axes[0]
    (bad,) = [ln for ln in ax.get_lines() if ln.get_label().startswith("fails a requirement")]
    assert bad.get_label() == "fails a requirement (2)"
    assert len(bad.get_xdata()) == 2
    (good,) = [ln for ln in ax.get_lines() if ln.get_label().startswith("passes every requirement")]
    assert good.get_label() == "passes every requirement (3)"
    assert len(good.get_xdata()) == 3
