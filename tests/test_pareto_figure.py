"""The Pareto-front figure: a front point that coincides with the base or a reference is drawn
above their open markers, and a failing base far off does not squeeze the feasible designs.

Checked on the figure's content (markers, fill, drawing order, axes limits), never on pixels.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.optimize import pareto_front  # noqa: E402


def test_front_point_on_the_base_stays_visible_and_a_far_base_is_marked_at_the_edge():
    # the base is the search's first candidate and on the front; the tuned reference on another
    # front point; a failing reference 90 below the feasible margins
    x = np.array([29.1, 23.7, 24.6, 25.0, 30.0, 22.0])
    y = np.array([0.018, 0.012, 0.135, -0.1, -0.3, -7.0])
    feasible = np.array([True, True, True, False, False, False])
    front_x, front_y = np.array([23.7, 24.6, 29.1]), np.array([0.012, 0.135, 0.018])
    refs = {"base": (29.1, 0.018, True), "tuned": (23.7, 0.012, True), "baseline": (29.1, -92.9, False)}
    fig = pareto_front(x, y, feasible, front_x, front_y, references=refs, senses=("min", "max"))
    ax = fig.axes[0]
    front = [ln for ln in ax.get_lines() if ln.get_label().startswith("Pareto front")][0]
    for label in ("base", "tuned"):
        (ref,) = [ln for ln in ax.get_lines() if ln.get_label() == label]
        assert ref.get_markerfacecolor() == "none" and ref.get_zorder() < front.get_zorder()
    # the view holds the feasible designs and the nearby failing ones, not the base at -92.9
    y0, y1 = ax.get_ylim()
    assert y0 < -0.3 < 0.135 < y1 and y0 > -1.0
    (far,) = [ln for ln in ax.get_lines() if ln.get_label().startswith("baseline (fails)")]
    assert far.get_marker() == "v" and far.get_ydata()[0] == y0
    assert "off the axes" in far.get_label() and "-92.9" in far.get_label()
    (bad,) = [ln for ln in ax.get_lines() if ln.get_label().startswith("fails a requirement")]
    assert bad.get_label() == "fails a requirement (3, 1 off the axes)"
    # the legend sits under the axes
    fig.canvas.draw()
    assert ax.get_legend().get_window_extent().y1 < ax.xaxis.label.get_window_extent().y0
