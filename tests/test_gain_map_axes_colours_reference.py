"""Gain maps: the K_d = 0 strip, the axes, the contours and the sign colours where they belong.

Hand-built grids (no analysis); references derived here:

* K_p is the abscissa and K_d the ordinate, both at log10 positions: gains 10⁶, 10⁷, 10⁸ N/m
  tick at 6, 7, 8 and are labelled "1e6", "1e7", "1e8";
* a zero K_d has no log10 position: its row of values is the strip under the map (its own
  axes, y in [0, 1]) and a point at K_d = 0 sits on that strip at y = 1/2;
* a quantity that depends on K_p only, z = 10^i at log10 K_p = 6 + i (i = 0, 1, 2), has
  contour lines parallel to the K_d axis; on the logarithmic colour scale from 1 to 100 the
  seven inner contour levels are geometric, 10^(k/4), k = 1..7, and the level c lies where the
  cell-centre linear interpolation of z reaches c: x = 6 + (c − 1)/9 for c ≤ 10,
  x = 7 + (c − 10)/90 above;
* the stability-margin colours are diverging about ζ = 0: every ζ < 0 red (red > blue
  channel), every ζ > 0 blue, however small; the colour bar's "unstable" label sits on its
  ζ < 0 half and "stable" on its ζ > 0 half.

Positions compared to 1e-9 (exact arithmetic on log10 of powers of ten and linear
interpolation; matplotlib's contour vertices are exact to round-off). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.gain_maps import gain_map_figure, stability_margin_figure  # noqa: E402

KP = np.array([1e6, 1e7, 1e8])  # [N/m]
TOL = 1e-9


def test_zero_kd_row_is_the_strip_and_its_point_sits_on_it():
    kd = np.array([0.0, 1e1, 1e2])  # [N s/m]
    values = np.arange(1.0, 10.0).reshape(3, 3)  # values[i, j]: K_p index i, K_d index j
    fig = gain_map_figure(kd=kd, kp=KP, values=values, label="q [-]", other={"design": (1e7, 0.0)})
    main, strip = fig.axes[:2]
    np.testing.assert_allclose(np.asarray(strip.collections[0].get_array()).ravel(), values[:, 0], rtol=TOL)
    np.testing.assert_allclose(np.asarray(main.collections[0].get_array()).ravel(), values[:, 1:].T.ravel(), rtol=TOL)
    (ring,) = [ln for ln in strip.get_lines() if str(ln.get_label()).startswith("design")]
    np.testing.assert_allclose([ring.get_xdata()[0], ring.get_ydata()[0]], [7.0, 0.5], rtol=TOL)
    assert not [ln for ln in main.get_lines() if str(ln.get_label()).startswith("design")]
    assert "K_p" in strip.get_xlabel() and "K_d" in main.get_ylabel()
    np.testing.assert_allclose(strip.get_xticks(), [6.0, 7.0, 8.0], atol=TOL)
    assert [t.get_text() for t in strip.get_xticklabels()] == ["1e6", "1e7", "1e8"]


def test_contours_of_a_kp_only_quantity_are_vertical_at_geometric_levels():
    kd = np.array([1e1, 1e2, 1e3])
    values = np.repeat((10.0 ** np.arange(3))[:, None], 3, axis=1)  # 1, 10, 100 along K_p
    ax = gain_map_figure(KP, kd, values, "q [-]").axes[0]
    (contours,) = [c for c in ax.collections if hasattr(c, "levels")]
    levels = 10.0 ** (np.arange(1, 8) / 4.0)
    np.testing.assert_allclose(contours.levels, levels, rtol=TOL)
    expected_x = np.where(levels <= 10.0, 6.0 + (levels - 1.0) / 9.0, 7.0 + (levels - 10.0) / 90.0)
    for path, x in zip(contours.get_paths(), expected_x):
        np.testing.assert_allclose(path.vertices[:, 0], x, atol=TOL)  # a vertical line at x
        assert np.ptp(path.vertices[:, 1]) > 1.0  # spanning the K_d axis


def test_margin_colours_diverge_at_zero_and_the_bar_says_so():
    kd = np.array([1e1, 1e2, 1e3])
    zeta = np.array([[-0.02, 0.001, 0.03], [0.02, -0.001, 0.04], [0.05, 0.06, 0.07]])
    fig = stability_margin_figure(KP, kd, zeta)
    mesh = fig.axes[0].collections[0]
    z = np.asarray(mesh.get_array()).ravel()  # rows K_d, columns K_p: zeta.T flattened
    np.testing.assert_allclose(z, zeta.T.ravel(), rtol=TOL)
    rgba = mesh.to_rgba(z)
    assert np.all((rgba[:, 0] > rgba[:, 2]) == (z < 0))  # red where ζ < 0, blue where ζ > 0
    bar = fig.axes[-1]
    to_data = bar.transData.inverted()
    for text in bar.texts:
        y = to_data.transform(bar.transAxes.transform(text.get_position()))[1]
        assert (y < 0) == text.get_text().startswith("unstable"), (text.get_text(), y)
