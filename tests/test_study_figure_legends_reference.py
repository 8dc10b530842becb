"""Study and gain-map figures name each marked series after its own data and place reference
points on the axes they are labelled with.

Hand-built arrays (no analysis), read back from the matplotlib artists. References:

* ``ply_angle_figure``'s docstring: "dominant : ... Dominant stress at each angle ("sigma1",
  "sigma2", "tau12"), drawn as marker shapes", and docs/studies.md: "`dominant_stress` (0 σ1,
  1 σ2, 2 τ12)": the markers labelled "σ1 dominates" sit exactly at the angles whose dominant
  stress is "sigma1", and so on for σ2 and τ12;
* ``two_angle_figure`` draws α on the abscissa ("α [deg]") and β on the ordinate ("β [deg]")
  and names the laminate "(α/−α/β/−β)s" (its docstring does not order ``thesis_best``; these
  labels do): the thesis laminate (α, β) = ``thesis_best`` is marked at x = α, y = β;
* ``gain_map_figure``'s docstring (src/flexshaft/plot/gain_maps.py): "best : (kp, kd), optional
  / Marked with a star at its gains. ``other``: more labelled points, each a ring larger than
  the star, e.g. ``{"design": (1e7, 0)}``": a ring's point is (K_p, K_d) as the star's, and
  its legend names its K_p in N/m and its K_d in N s/m, each with its own value.

Positions are the given values (exact); labels are compared as strings. Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from flexshaft.plot.gain_maps import gain_map_figure  # noqa: E402
from flexshaft.plot.studies import ply_angle_figure, two_angle_figure  # noqa: E402


def _only(ax, prefix):
    (line,) = [ln for ln in ax.get_lines() if str(ln.get_label()).startswith(prefix)]
    return line


def test_ply_angle_markers_are_named_after_their_dominant_stress():
    alpha = np.array([10.0, 30.0, 50.0, 70.0, 85.0])
    sf = np.array([1.0, 2.0, 3.0, 2.5, 1.5])
    dominant = ["sigma1", "sigma2", "sigma2", "tau12", "sigma1"]
    fig = ply_angle_figure(alpha, sf, dominant, thesis_optimum_deg=None)
    try:
        ax = fig.axes[0]
        for name, label in (("sigma1", "σ1 dominates"), ("sigma2", "σ2 dominates"), ("tau12", "τ12 dominates")):
            sel = np.array(dominant) == name
            line = _only(ax, label)
            np.testing.assert_array_equal(line.get_xdata(), alpha[sel])
            np.testing.assert_array_equal(line.get_ydata(), sf[sel])
    finally:
        plt.close(fig)


def test_two_angle_thesis_laminate_marked_at_alpha_beta():
    a = np.array([0.0, 30.0, 60.0, 90.0])
    b = np.array([0.0, 15.0, 45.0, 75.0, 90.0])
    sf = np.add.outer(np.arange(4.0), np.arange(5.0)) + 1.0  # shape (n_alpha, n_beta)
    fig = two_angle_figure(a, b, sf, thesis_best=(60.0, 15.0))
    try:
        ax = fig.axes[0]
        assert ax.get_xlabel().startswith("α") and ax.get_ylabel().startswith("β")
        line = _only(ax, "thesis")
        assert line.get_label() == "thesis (60/−60/15/−15)s"
        np.testing.assert_array_equal(np.ravel(line.get_xdata()), [60.0])
        np.testing.assert_array_equal(np.ravel(line.get_ydata()), [15.0])
    finally:
        plt.close(fig)


def test_gain_map_ring_legend_names_its_own_kp_and_kd():
    kp = np.array([1e6, 1e7, 1e8])  # [N/m]
    kd = np.array([0.0, 1e2, 1e3])  # [N s/m], with the K_d = 0 strip
    values = np.arange(1.0, 10.0).reshape(3, 3)
    fig = gain_map_figure(kp, kd, values, "orbit [m]", other={"design": (1e7, 0.0), "tuned": (1e8, 300.0)})
    try:
        labels = [str(ln.get_label()) for a in fig.axes for ln in a.get_lines()]
        assert "design: K_p = 1e+07 N/m, K_d = 0 N s/m (ring)" in labels
        assert "tuned: K_p = 1e+08 N/m, K_d = 300 N s/m (ring)" in labels
    finally:
        plt.close(fig)
