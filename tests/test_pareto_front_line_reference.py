"""The Pareto figure's front line joins the front's own designs, in order of the x objective.

Reference: :func:`flexshaft.plot.optimize.pareto_front`'s docstring (API contract):
``front_x, front_y`` -- "The Pareto front (drawn as the attainment line between its members)".
Each member is one design, the pair ``(front_x[i], front_y[i])``; a line between them runs
along x, so its vertices are the same pairs sorted by x.

Hand-built front of three designs (both objectives minimised), given out of x order (a front
need not come sorted by the objective the figure puts on x): ``(3, 1), (1, 3), (2, 2)``. The line
must be ``(1, 3), (2, 2), (3, 1)``: exact, the values are only reordered. Pairing the sorted x
with the unsorted y would draw ``(1, 1), (2, 3), (3, 2)``, a point better than every member in
both objectives. About 1 s (measured 0.6 to 1.04 s), nearly all of it matplotlib's first figure.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.optimize import pareto_front  # noqa: E402


def test_front_line_keeps_each_design_pair_in_x_order():
    front_x = np.array([3.0, 1.0, 2.0])
    front_y = np.array([1.0, 3.0, 2.0])
    x = np.r_[front_x, 2.5, 3.5]  # every evaluated design: the front and two dominated ones
    y = np.r_[front_y, 2.5, 3.5]
    feasible = np.ones(x.size, dtype=bool)
    fig = pareto_front(x, y, feasible, front_x, front_y)
    (line,) = [ln for ln in fig.axes[0].get_lines() if ln.get_label() == "Pareto front (3)"]
    drawn = list(zip(line.get_xdata(), line.get_ydata(), strict=True))
    assert drawn == [(1.0, 3.0), (2.0, 2.0), (3.0, 1.0)]
