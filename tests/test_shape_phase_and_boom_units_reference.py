"""Shape figures: a complex mode drawn at the phase of its largest component, the boom in mm.

Hand-built shapes (no model); references derived here:

* a mode (v, w) = (2i·s(x), s(x)), s real with peak 1, has orbit radius |(v, w)| = √5·|s|;
  scaled to a largest radius of 1 with its largest component (v at the peak) made real, it is
  (v, w) = (2s/√5, −i·s/√5): the drawn v is 2s/√5, the drawn w (real part) is 0, and the
  orbit envelope √(4 + 1)|s|/√5 = |s| peaks at 1;
* the static deflection is given in metres and drawn in millimetres (1 m = 1000 mm), the
  tailboom's as well as the shaft's.

Compared to rel 1e-12 (arithmetic only). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.shapes import deflected_shape_figure, mode_shapes_figure  # noqa: E402

REL = 1e-12


def test_complex_mode_is_drawn_at_the_phase_of_its_largest_component():
    x = np.linspace(0.0, 2.0, 5)
    s = np.sin(np.pi * x / 2.0)  # peak 1 at x = 1
    ax = mode_shapes_figure(x, [{"label": "mode 1", "v": 2j * s, "w": s}]).axes[0]
    lines = {ln.get_label(): np.asarray(ln.get_ydata(), float) for ln in ax.get_lines()}
    np.testing.assert_allclose(lines["shaft v (vertical)"], 2.0 * s / np.sqrt(5.0), rtol=REL, atol=1e-15)
    np.testing.assert_allclose(lines["shaft w (lateral)"], 0.0, atol=1e-15)
    upper = ax.collections[0].get_paths()[0].vertices[:, 1]
    np.testing.assert_allclose(upper.max(), 1.0, rtol=REL)


def test_boom_deflection_is_drawn_in_mm():
    x = np.array([0.0, 1.0, 2.0])
    boom_x = np.array([0.0, 2.0])
    fig = deflected_shape_figure(x, np.zeros(3), np.zeros(3), boom_x, [0.0, -3e-3], [0.0, 1e-3])
    for ax, expected in zip(fig.axes[:2], ([0.0, -3.0], [0.0, 1.0])):
        (boom,) = [ln for ln in ax.get_lines() if ln.get_label() == "tailboom"]
        np.testing.assert_allclose(boom.get_ydata(), expected, rtol=REL)
