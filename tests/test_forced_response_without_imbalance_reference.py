"""A design without imbalance gets its report: the forced-response study's figure of zero orbits.

``flexshaft run`` on the packaged textbook rotor src/flexshaft/validation/designs/friswell_5_9_1.toml
(no ``[loads] eccentricity``: no imbalance) stopped with "internal error: ValueError: Data
cannot be log-scaled because all values are <= 0" while drawing the design studies' forced
response, and wrote no report (audit a2). Reference: with no imbalance force the steady
imbalance response is zero at every speed (a linear system driven by nothing), so every orbit
is 0 and a logarithmic axis has nothing to show: the figure is drawn on a linear axis from 0
and says why. A drawn figure with a positive orbit keeps its logarithmic axis.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from flexshaft.plot.studies import forced_response_figure  # noqa: E402

SPEEDS = np.array([1000.0, 2000.0, 3000.0])


def test_zero_orbits_draw_on_a_linear_axis_with_a_note():
    fig = forced_response_figure(SPEEDS, {"wall 1 mm": np.zeros(3), "wall 4 mm": np.zeros(3)}, 2500.0)
    fig.canvas.draw()  # the log axis failed here, at draw time
    ax = fig.axes[0]
    assert ax.get_yscale() == "linear" and ax.get_ylim() == (0.0, 1.0)
    assert any("no imbalance" in t.get_text() for t in ax.texts)


def test_a_positive_orbit_keeps_the_logarithmic_axis():
    fig = forced_response_figure(SPEEDS, {"wall 1 mm": [0.0, 1e-5, 2e-5]}, 2500.0)
    fig.canvas.draw()
    ax = fig.axes[0]
    assert ax.get_yscale() == "log" and not ax.texts
