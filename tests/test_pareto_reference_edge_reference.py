"""The Pareto figure draws a failing reference design with a thinner edge than a passing one.

Reference: :func:`flexshaft.plot.optimize.pareto_front`'s docstring (the API contract):
"references: Label -> (x, y, feasible) of designs to mark (the first one: the base design),
each an open marker under the front's points (...); one that fails its constraints has a
thinner edge and "(fails)" in its label." Checked on the drawn markers' edge widths, never on
pixels. Two references inside the view (no arrowheads), stand-in values; Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from flexshaft.plot.optimize import pareto_front  # noqa: E402


def test_a_failing_reference_has_the_thinner_edge():
    x = np.array([1.0, 2.0, 3.0, 2.5])
    y = np.array([0.3, 0.2, 0.1, 0.25])
    feasible = np.array([True, True, True, False])
    refs = {"base": (2.0, 0.2, True), "old": (2.5, 0.25, False)}
    fig = pareto_front(x, y, feasible, x[:3], y[:3], references=refs, senses=("min", "max"))
    lines = fig.axes[0].get_lines()
    (passing,) = [ln for ln in lines if ln.get_label() == "base"]
    (failing,) = [ln for ln in lines if ln.get_label().startswith("old (fails)")]
    assert failing.get_marker() not in ("^", "v", "<", ">")  # inside the view: its own marker
    assert failing.get_markeredgewidth() < passing.get_markeredgewidth()
    plt.close("all")
