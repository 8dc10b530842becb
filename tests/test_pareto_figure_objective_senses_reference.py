"""The optimizer result's Pareto figure takes each axis's direction of improvement from that
objective's own sense.

Reference (docs/optimizer.md, objectives): ``driveline_mass`` is minimised and ``min_margin``
maximised; the figure (:func:`flexshaft.plot.optimize.pareto_front`) labels an axis "lower is
better" for a minimised objective and "higher is better" for a maximised one, and joins the
front by "steps-post" when x is minimised, "steps-pre" when x is maximised (the attainment
staircase of tests/test_pareto_figure_axes_reference.py, derived there). Either objective may be
on either axis (``plot(x=..., y=...)``), so both orders are checked.

Stand-in datasets (three designs, all feasible, all on the front), no analysis: about 0.1 s
(the Agg canvas).
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import matplotlib
import pytest

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

xr = pytest.importorskip("xarray")

from flexshaft.optimize.result import OptimizationResult  # noqa: E402


def _result() -> OptimizationResult:
    mass, margin = [30.0, 31.0, 32.0], [0.01, 0.05, 0.09]  # more mass buys margin: all on the front
    problem = NS(
        name="stand-in",
        objectives=[NS(output="driveline_mass", sense="min", label=""), NS(output="min_margin", sense="max", label="")],
    )
    units = {"driveline_mass": "kg", "min_margin": "1"}
    data = {k: ("evaluation", v, {"units": units[k]}) for k, v in (("driveline_mass", mass), ("min_margin", margin))}
    evaluations = xr.Dataset({**data, "feasible": ("evaluation", [1, 1, 1])})
    pareto = evaluations.rename({"evaluation": "design"})
    return OptimizationResult(problem, evaluations=evaluations, pareto=pareto)


@pytest.mark.parametrize(
    "x, y, x_words, y_words, drawstyle",
    [
        ("driveline_mass", "min_margin", "lower is better", "higher is better", "steps-post"),
        ("min_margin", "driveline_mass", "higher is better", "lower is better", "steps-pre"),
    ],
)
def test_each_axis_takes_its_objectives_sense(x, y, x_words, y_words, drawstyle):
    figure = _result().plot(x=x, y=y)
    try:
        ax = figure.axes[0]
        assert ax.get_xlabel().endswith(f"({x_words})")
        assert ax.get_ylabel().endswith(f"({y_words})")
        (line,) = [ln for ln in ax.get_lines() if ln.get_label().startswith("Pareto front")]
        assert line.get_drawstyle() == drawstyle
    finally:
        plt.close("all")
