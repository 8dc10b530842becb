"""The drawing phase of a complex mode shape (plot/shapes.py, ``mode_shapes_figure``).

Reference: API contract (the docstring of ``mode_shapes_figure``, "scaled so that its largest
orbit radius is 1 and its largest component is real"; no docs page states it) and derived
here: the shape v = 0.5 i sin(πx), w = sin(πx) on x in [0, 1] has its largest component
w(½) = 1 (real already) and its largest |(v, w)| = √(|v|² + |w|²) = √1.25 at x = ½ (the
plot's "orbit radius"; the ellipse's major semi-axis is 1 here). Drawn at that phase, the w
curve is sin(πx)/√1.25 and the v curve Re(0.5 i sin(πx))/√1.25 = 0 (v is a quarter period
ahead: 0.5 i = 0.5 e^{iπ/2}; the whirl caught at the instant w peaks).

Agg, no file; CPU milliseconds.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from flexshaft.plot.shapes import mode_shapes_figure  # noqa: E402


def _curve(ax, label):
    (line,) = [ln for ln in ax.get_lines() if ln.get_label() == label]
    return np.asarray(line.get_ydata(), dtype=float)


def test_mode_is_drawn_at_the_phase_of_its_largest_component_in_either_plane():
    """w dominant and real, v in quadrature: w drawn as sin(πx)/√1.25, v drawn as zero.

    Values are a complex division of O(1) numbers: 1e-12 covers the round-off; the wrong phase
    (taken from v) would draw w as 0 and v as 0.5 sin(πx)/√1.25, O(0.4) away.
    """
    x = np.linspace(0.0, 1.0, 5)
    shape = np.sin(np.pi * x)
    fig = mode_shapes_figure(x, [{"label": "whirl", "v": 0.5j * shape, "w": shape}])
    ax = fig.axes[0]
    np.testing.assert_allclose(_curve(ax, "shaft w (lateral)"), shape / np.sqrt(1.25), atol=1e-12)
    np.testing.assert_allclose(_curve(ax, "shaft v (vertical)"), 0.0, atol=1e-12)
