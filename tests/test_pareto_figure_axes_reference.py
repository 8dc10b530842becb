"""The optimizer's Pareto figure: each axis names its own objective's direction of improvement,
and the attainment staircase bounds the side of the front its senses make dominated.

Reference (derived): with the front sorted by x, member i dominates the designs on the worse side
of both objectives. x maximised, y minimised: the front rises with x (more x costs y) and i
dominates {x <= x_i, y >= y_i} (up-left); the union's boundary from (x_i, y_i) to
(x_{i+1}, y_{i+1}) climbs at x_i first, then runs right: matplotlib's "steps-pre" (on
(x_i, x_{i+1}] the line holds y_{i+1}). x minimised, y maximised: i dominates
{x >= x_i, y <= y_i} (down-right); the boundary runs right at y_i first, then climbs at x_{i+1}:
"steps-post". Three stand-in designs, no analysis: about 0.1 s (the Agg canvas).
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from flexshaft.plot.optimize import pareto_front  # noqa: E402


def _front_line(senses):
    x = np.array([1.0, 2.0, 3.0])
    y = np.array([10.0, 20.0, 30.0])  # every one on the front: y rises with x
    fig = pareto_front(x, y, [True] * 3, x, y, x_label="mass [kg]", y_label="margin [-]", senses=senses)
    ax = fig.axes[0]
    (line,) = [ln for ln in ax.get_lines() if ln.get_label().startswith("Pareto front")]
    return ax, line


def test_each_axis_names_its_own_direction_and_the_staircase_follows_x():
    ax, line = _front_line(("max", "min"))
    assert ax.get_xlabel() == "mass [kg] (higher is better)"
    assert ax.get_ylabel() == "margin [-] (lower is better)"
    assert line.get_drawstyle() == "steps-pre"
    assert list(line.get_xdata()) == [1.0, 2.0, 3.0]  # joined in order of x
    ax, line = _front_line(("min", "max"))
    assert ax.get_xlabel() == "mass [kg] (lower is better)"
    assert ax.get_ylabel() == "margin [-] (higher is better)"
    assert line.get_drawstyle() == "steps-post"
    plt.close("all")
