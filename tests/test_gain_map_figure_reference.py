"""Gain maps place the gains where they are and show the quantity in the unit of the bar.

Hand-built 3×3 grids (no analysis); references derived here:

* both gain axes hold log10 positions, so gains (K_p, K_d) = (10⁷ N/m, 10² N s/m) sit at
  (7, 2); K_p is the abscissa, K_d the ordinate;
* a value given in SI (metres) with ``scale`` = 1000 is drawn in millimetres;
* a cell is unstable when its smallest damping ratio ζ < 0: exactly those cells are hatched.

Compared to rel 1e-12. Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from matplotlib.patches import Rectangle  # noqa: E402

from flexshaft.plot.gain_maps import gain_map_figure, stability_margin_figure  # noqa: E402

KP = np.array([1e6, 1e7, 1e8])  # [N/m]
KD = np.array([1e1, 1e2, 1e3])  # [N s/m], all > 0: no K_d = 0 strip
REL = 1e-12


def test_gain_map_star_at_the_best_gains_and_cells_in_display_units():
    values = np.arange(1.0, 10.0).reshape(3, 3) * 1e-4  # [m]
    fig = gain_map_figure(KP, KD, values, "orbit [mm]", scale=1e3, best=(1e7, 1e2), other={"design": (1e8, 1e1)})
    ax = fig.axes[0]
    (star,) = [ln for ln in ax.get_lines() if str(ln.get_label()).startswith("best")]
    np.testing.assert_allclose([star.get_xdata()[0], star.get_ydata()[0]], [7.0, 2.0], rtol=REL)
    (ring,) = [ln for ln in ax.get_lines() if str(ln.get_label()).startswith("design")]
    np.testing.assert_allclose([ring.get_xdata()[0], ring.get_ydata()[0]], [8.0, 1.0], rtol=REL)
    (mesh,) = ax.collections[:1]
    # pcolormesh of z.T: rows K_d, columns K_p, flattened row by row
    np.testing.assert_allclose(np.asarray(mesh.get_array()).ravel(), (values * 1e3).T.ravel(), rtol=REL)


def test_stability_margin_hatches_exactly_the_unstable_cells():
    zeta = np.array([[-0.02, 0.01, 0.03], [0.02, -0.001, 0.04], [0.05, 0.06, 0.07]])  # two cells unstable
    ax = stability_margin_figure(KP, KD, zeta).axes[0]
    hatched = [p for p in ax.patches if isinstance(p, Rectangle) and p.get_hatch()]
    corners = sorted(
        (round(p.get_x() + 0.5 * p.get_width(), 9), round(p.get_y() + 0.5 * p.get_height(), 9)) for p in hatched
    )
    assert corners == [(6.0, 1.0), (7.0, 2.0)]  # cell centres (log10 K_p, log10 K_d) of ζ < 0
