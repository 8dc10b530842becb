"""The thermal figure draws each element's heat over that element and the rise as given.

Hand-built arrays (no analysis); references derived here:

* a temperature rise is a difference, the same number in K and in °C (no 273.15 offset);
* an element's heat per length is uniform over the element between its two nodes: drawn as a
  step centred on the element's centre, the curve at any x inside element i is q_i.

Compared to rel 1e-12. Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np
from matplotlib.cbook import STEP_LOOKUP_MAP

matplotlib.use("Agg")

from flexshaft.plot.thermal import shaft_temperature_figure  # noqa: E402

REL = 1e-12


def test_rise_as_given_and_the_heat_over_its_element():
    nodes = np.array([0.0, 1.0, 2.0, 3.0])  # [m]
    centres = 0.5 * (nodes[:-1] + nodes[1:])
    rise = np.array([5.0, 12.0, 9.0, 4.0])  # [K]
    heat = np.array([2.0, 7.0, 3.0])  # [W/m]
    top, bottom = shaft_temperature_figure(nodes, {"loss": rise}, centres, {"loss": heat}).axes[:2]
    np.testing.assert_allclose(top.get_lines()[0].get_ydata(), rise, rtol=REL)
    (step,) = bottom.get_lines()
    x, y = STEP_LOOKUP_MAP[step.get_drawstyle()](step.get_xdata(), step.get_ydata())  # the polyline drawn
    # points strictly inside element i and inside the drawn range (centre of the first to centre of the last)
    for i, inside in enumerate((0.7, 1.3, 2.3)):
        k = np.searchsorted(x, inside, side="right") - 1  # the drawn segment holding it
        assert x[k] <= inside < x[k + 1] and y[k] == y[k + 1] == heat[i]
