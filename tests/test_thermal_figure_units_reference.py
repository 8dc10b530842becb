"""The thermal figures give each axis the unit of the quantity drawn on it.

Hand-built arrays (no analysis). References, by dimensional analysis of what is drawn:

* the lower panel of the shaft-temperature figure draws the heat generated per unit length of
  shaft: the report passes each element's total heat [W] divided by its length [m]
  (``s.sources.total / np.diff(x)``, report/run_sections.py), and the function's docstring
  names it "the heat generated [W/m]": W / m = W/m, not W (a total);
* the upper panel and both panels of the temperature-profile figure draw a temperature rise
  above the air, a difference of temperatures: K;
* the abscissa is the axial position of the nodes, given in metres: m.

Only the unit in the label's brackets is compared (exact text; the wording around it is free).
Agg, no file.
"""

from __future__ import annotations

import re

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.thermal import shaft_temperature_figure, temperature_profiles_figure  # noqa: E402


def unit(label: str) -> str:
    """The unit in a label's last brackets, "heat generated [W/m]" -> "W/m"."""
    found = re.findall(r"\[([^\]]*)\]", label)
    assert found, f"no unit in {label!r}"
    return found[-1]


def test_heat_per_length_in_watts_per_metre_and_rise_in_kelvin():
    nodes = np.array([0.0, 0.5, 1.0])  # [m]
    lengths = np.diff(nodes)  # [m]
    total = np.array([3.0, 1.0])  # each element's heat [W]
    fig = shaft_temperature_figure(
        nodes, {"loss": np.array([2.0, 5.0, 3.0])}, 0.5 * (nodes[:-1] + nodes[1:]), {"loss": total / lengths}
    )
    top, bottom = fig.axes[:2]
    assert unit(top.get_ylabel()) == "K"
    assert unit(bottom.get_ylabel()) == "W/m"
    assert unit(bottom.get_xlabel()) == "m"


def test_temperature_profiles_in_kelvin_along_metres():
    x = np.array([0.0, 0.5, 1.0])  # [m]
    fig = temperature_profiles_figure(
        x, {"wall 2.0 mm": np.array([1.0, 2.0, 1.0])}, {"h = 5": np.array([3.0, 4.0, 3.0])}
    )
    for ax in fig.axes[:2]:
        assert unit(ax.get_ylabel()) == "K"
        assert unit(ax.get_xlabel()) == "m"
