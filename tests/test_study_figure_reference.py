"""The thesis-study figures draw the swept numbers against their own grid, in the axis units.

Each figure is drawn from small hand-built arrays and read back from its matplotlib artists.
References, derived by hand in each test:

* 1 m = 1000 mm for walls, orbits and amplitudes on millimetre axes; frequencies given in Hz
  are drawn unchanged on the Hz axis;
* the best ply angle / laminate is the largest safety factor, the starred spin-up orbit the
  smallest, a tuned-gain curve's written peak its largest value;
* the buckling factor is drawn as given, T_cr/T (safe above the line at 1);
* a map's cell (i, j) holds sf[i, j] at (α_i, β_j): pcolormesh's array is sf transposed,
  rows along β;
* a vertical line at a gain is drawn at that gain (the log scale is the axis's business).

Values are exact binary fractions or one multiplication's round-off: exact or 1e-12 relative.
Agg, no file.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from flexshaft.plot.studies import (  # noqa: E402
    buckling_figure,
    forced_response_figure,
    gain_figure,
    ply_angle_figure,
    response_surface_figure,
    tuned_gains_figure,
    two_angle_figure,
    wall_thickness_figure,
)


def _line(ax, prefix):
    return next(ln for ln in ax.get_lines() if ln.get_label().startswith(prefix))


def _xy(line):
    return float(np.ravel(line.get_xdata())[0]), float(np.ravel(line.get_ydata())[0])


def test_ply_angle_marks_the_largest_factor_and_the_thesis_angle():
    alpha = np.array([15.0, 45.0, 60.0, 75.0])
    sf = np.array([1.0, 3.0, 2.0, 0.5])  # best 3.0 at 45°
    fig = ply_angle_figure(alpha, sf, thesis_optimum_deg=55.0)
    try:
        ax = fig.axes[0]
        assert _xy(_line(ax, "best")) == (45.0, 3.0)
        assert _line(ax, "best").get_label() == "best ±45°: R = 3"
        np.testing.assert_array_equal(_line(ax, "thesis optimum").get_xdata(), [55.0, 55.0])
    finally:
        plt.close(fig)


def test_two_angle_map_cells_and_best_point_follow_alpha_beta():
    a = np.array([0.0, 30.0, 60.0])
    b = np.array([0.0, 45.0])
    sf = np.array([[1.0, 2.0], [3.0, 4.0], [5.0, 9.0]])  # largest 9 at (α, β) = (60, 45)
    fig = two_angle_figure(a, b, sf, thesis_best=None)
    try:
        ax = fig.axes[0]
        mesh = ax.collections[0]
        # pcolormesh(X edges along α, Y edges along β, C = sf.T): row j (β_j), column i (α_i)
        np.testing.assert_array_equal(np.asarray(mesh.get_array()).reshape(2, 3), sf.T)
        assert _xy(_line(ax, "best")) == (60.0, 45.0)
    finally:
        plt.close(fig)


def test_wall_figure_pairs_each_curve_with_its_label_and_unit():
    t = np.array([1e-3, 2e-3, 3e-3])  # m: 1, 2, 3 mm
    with_imb = np.array([1.0, 2.0, 3.0])
    without = np.array([4.0, 5.0, 6.0])
    f = np.array([40.0, 50.0, 60.0])  # Hz
    peak = np.array([3e-4, 1e-4, 2e-4])  # m: smallest 0.1 mm at 2 mm wall
    fig = wall_thickness_figure(t, with_imb, without, f, peak)
    try:
        sf_ax, f_ax, orbit_ax = fig.axes[:3]
        np.testing.assert_allclose(_line(sf_ax, "with imbalance").get_xdata(), [1.0, 2.0, 3.0], rtol=1e-12)
        np.testing.assert_array_equal(_line(sf_ax, "with imbalance").get_ydata(), with_imb)
        np.testing.assert_array_equal(_line(sf_ax, "without imbalance").get_ydata(), without)
        np.testing.assert_array_equal(_line(f_ax, "shaft's first").get_ydata(), f)
        orbit = _line(orbit_ax, "spin-up peak")
        np.testing.assert_allclose(orbit.get_xdata(), [1.0, 2.0, 3.0], rtol=1e-12)
        np.testing.assert_allclose(orbit.get_ydata(), [0.3, 0.1, 0.2], rtol=1e-12)
        star = _line(orbit_ax, "smallest")
        np.testing.assert_allclose(_xy(star), (2.0, 0.1), rtol=1e-12)
        assert star.get_label() == "smallest: 0.1 mm at 2 mm wall"
    finally:
        plt.close(fig)


def test_forced_and_tuned_responses_are_in_mm_with_the_largest_written():
    speeds = np.array([1000.0, 2000.0, 3000.0])
    orbit = np.array([2e-4, 8e-4, 4e-4])  # m: 0.2, 0.8, 0.4 mm, peak 0.8 mm at 2000 rpm
    fig = forced_response_figure(speeds, {"wall 2 mm": orbit})
    try:
        np.testing.assert_allclose(_line(fig.axes[0], "wall 2 mm").get_ydata(), [0.2, 0.8, 0.4], rtol=1e-12)
    finally:
        plt.close(fig)
    fig = tuned_gains_figure(speeds, {"tuned": orbit})
    try:
        ax = fig.axes[0]
        assert [t.get_text() for t in ax.texts] == ["0.8 mm"]
        assert tuple(ax.texts[0].xy) == (2000.0, 0.8)
    finally:
        plt.close(fig)


def test_gain_line_at_the_design_gain_and_buckling_factor_as_given():
    kp = np.array([1e4, 1e5, 1e6])
    fig = gain_figure(kp, [2.0, 3.0, 4.0], [1e-3, 5e-4, 2e-4], design_kp=1e5)
    try:
        for ax in fig.axes[:2]:
            np.testing.assert_array_equal(_line(ax, "design K_p").get_xdata(), [1e5, 1e5])
    finally:
        plt.close(fig)
    fig = buckling_figure([1e-3, 2e-3], [0.5, 4.0])  # T_cr/T: buckles at 1 mm, safe at 2 mm
    try:
        ax = fig.axes[0]
        data = next(ln for ln in ax.get_lines() if ln.get_label().startswith("_"))
        np.testing.assert_array_equal(data.get_ydata(), [0.5, 4.0])
    finally:
        plt.close(fig)


def test_response_surface_shares_an_amplitude_axis_in_mm():
    x = np.array([0.0, 1.0])
    speeds = np.array([1000.0, 2000.0])
    z = np.array([[1e-4, 3e-4], [2e-4, 4e-4]])  # m: peak 0.4 mm
    fig = response_surface_figure(x, speeds, {"case": z})
    try:
        ax = fig.axes[0]
        np.testing.assert_allclose(ax.get_zlim(), (0.0, 0.4), rtol=1e-12)
        assert ax.get_title() == "case\npeak 0.4 mm"
    finally:
        plt.close(fig)
