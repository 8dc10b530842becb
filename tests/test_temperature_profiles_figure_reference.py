"""The temperature-profile figure (thesis figures 3.18, 3.19) draws each sweep in its own panel.

Hand-built curves (no analysis); reference derived here: the left panel, titled for the wall
thickness, holds exactly the curves of the wall-thickness sweep, and the right panel, titled
for the convection coefficient, exactly those of the convection sweep, each at the nodes'
positions and with the rise as given [K] (docs/thermal.md: the wall-thickness sweep's
profiles are thesis figure 3.18, the convection sweep's over several h figure 3.19). The two
sweeps' values are disjoint, so a curve drawn in the other panel is seen.

Compared to rel 1e-12 (no arithmetic). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.thermal import temperature_profiles_figure  # noqa: E402

REL = 1e-12


def test_each_sweep_in_the_panel_titled_for_it():
    x = np.array([0.0, 0.5, 1.0, 1.5])  # [m]
    by_wall = {"t = 2 mm": np.array([1.0, 4.0, 4.0, 1.0]), "t = 3 mm": np.array([0.8, 3.0, 3.0, 0.8])}
    by_h = {"h = 10": np.array([9.0, 20.0, 20.0, 9.0]), "h = 40": np.array([5.0, 11.0, 11.0, 5.0])}
    fig = temperature_profiles_figure(x, by_wall, by_h)
    left, right = fig.axes[:2]
    assert "wall thickness" in left.get_title() and "convection" in right.get_title()
    for ax, sweep in ((left, by_wall), (right, by_h)):
        lines = {ln.get_label(): ln for ln in ax.get_lines()}
        assert set(lines) == set(sweep)
        for name, rise in sweep.items():
            np.testing.assert_allclose(lines[name].get_xdata(), x, rtol=REL)
            np.testing.assert_allclose(lines[name].get_ydata(), rise, rtol=REL)
