"""Shape figures: mode shapes normalised by the orbit radius, bearings marked on the shape.

Hand-built shapes (no model); references derived here:

* a circular forward whirl mode (v, w) = (s(x), −i s(x)) has the orbit radius
  |(v, w)| = √2·|s|; normalised to a largest orbit radius of 1 and its largest component real,
  its drawn v is s/(√2·max|s|) (peak 1/√2) and the envelope √2|s|/(√2 max|s|) peaks at 1;
* the tailboom shape is drawn on the shaft's scale: a boom moving one tenth as much as the
  shaft peaks at one tenth of the shaft's drawn peak;
* a bearing's marker on each panel sits at that panel's own deflection at the bearing,
  interpolated linearly between the nodes (the shape is drawn piecewise linear).

Compared to rel 1e-12. Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.shapes import deflected_shape_figure, mode_shapes_figure  # noqa: E402

REL = 1e-12


def test_circular_whirl_mode_is_normalised_by_its_orbit_radius_and_the_boom_on_the_shaft_scale():
    x = np.linspace(0.0, 4.0, 9)
    s = np.sin(np.pi * x / 4.0)  # peak 1 at x = 2
    boom_x = np.linspace(0.0, 4.0, 5)
    boom = 0.1 * np.sin(np.pi * boom_x / 4.0)
    fig = mode_shapes_figure(x, [{"label": "mode 1", "v": s, "w": -1j * s}], boom_x, [{"v": boom, "w": -1j * boom}])
    ax = fig.axes[0]
    lines = {ln.get_label(): np.asarray(ln.get_ydata(), float) for ln in ax.get_lines()}
    np.testing.assert_allclose(lines["shaft v (vertical)"], s / np.sqrt(2.0), rtol=REL, atol=1e-15)
    np.testing.assert_allclose(lines["boom v"], boom / np.sqrt(2.0), rtol=REL, atol=1e-15)
    envelope = ax.collections[0].get_paths()[0].vertices[:, 1]
    np.testing.assert_allclose(envelope.max(), 1.0, rtol=REL)


def test_bearing_markers_sit_on_each_panels_own_deflection():
    x = np.array([0.0, 1.0, 2.0])
    v = np.array([0.0, -1e-3, 0.0])  # [m]
    w = np.array([0.0, 2e-3, 0.0])
    fig = deflected_shape_figure(x, v, w, bearings_x=[0.5])
    for ax, expected in zip(fig.axes[:2], (-0.5, 1.0)):  # half-way to the middle node, in mm
        (marker,) = [ln for ln in ax.get_lines() if ln.get_marker() == "^"]
        np.testing.assert_allclose(marker.get_ydata(), [expected], rtol=REL)
