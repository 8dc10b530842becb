"""What the figures show is what the verdict uses: limits in view, bands where the checks look,
stability coloured by the sign of δ, shapes normalised as the docstrings state.

Hand-built arrays (no model); references derived here:

* a log decrement δ < 0 is a growing mode (x(t) ∝ e^{−δ t/T}), δ > 0 a decaying one: the
  Campbell points are red (matplotlib's "Reds", red the largest RGB channel) exactly when
  δ < 0, whatever the colour range; viridis, used for δ > 0 over [0, 0.85] of its range (the
  part ``damping_colormap`` uses), never has red as its largest channel there (its R ≤
  max(G, B) up to 0.95; red leads only in its last yellows);
* a limit line drawn outside the axes is not seen: the |S|max requirement 4 above every
  loop's peak (2) and the failure line R = 1 of a shaft whose R is 0.4-0.7 must lie inside
  the y-limits;
* the operating speed range (4500, 5200) rpm the imbalance checks end at is shaded from
  4500 to 5200 rpm;
* the critical point at x = 1.5 m between stations with R = 1.5 and 2.0 (at 1 m and 2 m)
  sits at the linear interpolation R = 1.75, not at the curve's minimum 1.2;
* the bearing stations 0.5 m and 1.5 m are drawn at 0.5 and 1.5 on the metre axis;
* a mode shape with a node, v = 1 − 2x on [0, 0.75] (w = 0; largest |v| at x = 0 alone),
  normalised to a largest orbit radius of 1 with its largest component real and positive, is
  drawn as 1 − 2x itself: it changes sign at x = 0.5;
* a torsional shape is scaled by its largest |θ|: θ = (0.2, −0.5, −1.0, 0.4, 0) is drawn as
  θ/(−1), largest magnitude exactly 1, not θ/0.4 (largest positive value);
* the first axial mode of a fixed-free bar, u = sin(πx/2L) (derived: EA u'' + ρAω² u = 0 with
  u(0) = 0 and u'(L) = 0 gives u ∝ sin((2n−1)πx/2L)), carried with round-off v and w, is
  drawn as u normalised, labelled as the axial u: not as a lateral shape.

Compared to 1e-12 (far above the round-off of one division of unit-sized values, ~1e-16; far
below any mutation's change). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.campbell import campbell_figure  # noqa: E402
from flexshaft.plot.driveline import imbalance_response_figure, safety_factor_figure  # noqa: E402
from flexshaft.plot.loops import loop_sensitivity_figure  # noqa: E402
from flexshaft.plot.shapes import deflected_shape_figure, mode_shapes_figure  # noqa: E402

TOL = 1e-12


def _red(rgba) -> bool:
    return rgba[0] > max(rgba[1], rgba[2])


def test_campbell_points_are_red_exactly_where_the_log_decrement_is_negative():
    speeds = np.array([1000.0, 2000.0, 3000.0, 4000.0, 5000.0, 6000.0])
    delta = np.array([-0.5, -0.01, 0.01, 0.2, 0.5, 1.0])
    freqs = np.linspace(20.0, 30.0, speeds.size)[:, None]
    fig = campbell_figure(speeds, freqs, np.full((speeds.size, 1), "forward"), log_decrement=delta[:, None])
    ax = fig.axes[0]
    (points,) = [c for c in ax.collections if len(c.get_offsets()) == speeds.size]
    np.testing.assert_array_equal(np.asarray(points.get_offsets())[:, 0], speeds)
    colours = points.to_rgba(points.get_array())
    assert [_red(c) for c in colours] == [d < 0.0 for d in delta]


def test_the_sensitivity_requirement_above_every_peak_is_in_view():
    f = np.array([1.0, 10.0, 100.0])
    fig = loop_sensitivity_figure({"a": (f, np.array([0.5, 2.0, 0.5]))}, peaks={"a": (10.0, 2.0)}, required_peak=4.0)
    top = fig.axes[0]
    (line,) = [ln for ln in top.get_lines() if ln.get_label().startswith("required |S|max")]
    np.testing.assert_array_equal(line.get_ydata(), [4.0, 4.0])
    assert top.get_ylim()[0] <= 0.0 and top.get_ylim()[1] > 4.0


def test_the_imbalance_response_shades_the_operating_speed_range():
    speeds = np.linspace(1000.0, 6000.0, 6)
    fig = imbalance_response_figure(
        speeds, {"max shaft": 1e-4 * np.ones(6)}, operating_rpm=5000.0, speed_range_rpm=(4500.0, 5200.0)
    )
    ax = fig.axes[0]
    spans = []
    for patch in ax.patches:
        xs = patch.get_patch_transform().transform(patch.get_path().vertices)[:, 0]
        spans.append((float(xs.min()), float(xs.max())))
    assert spans == [(4500.0, 5200.0)]
    assert [ln.get_xdata()[0] for ln in ax.get_lines() if ln.get_label().startswith("operating speed")] == [5000.0]


def test_a_shaft_failing_everywhere_keeps_the_failure_line_in_view():
    x = np.array([0.0, 1.0, 2.0])
    fig = safety_factor_figure(x, np.array([0.7, 0.4, 0.6]))
    ax = fig.axes[0]
    (failure,) = [ln for ln in ax.get_lines() if ln.get_label() == "failure (R = 1)"]
    np.testing.assert_array_equal(failure.get_ydata(), [1.0, 1.0])
    assert ax.get_yscale() == "linear"
    assert ax.get_ylim()[0] <= 0.4 and ax.get_ylim()[1] > 1.0


def test_the_critical_point_between_stations_sits_on_the_interpolated_curve():
    x = np.array([0.0, 1.0, 2.0, 3.0])
    fig = safety_factor_figure(x, np.array([3.0, 1.5, 2.0, 1.2]), critical_x=1.5)
    (marker,) = [ln for ln in fig.axes[0].get_lines() if ln.get_label() == "critical point"]
    np.testing.assert_allclose(np.ravel(marker.get_xydata()), [1.5, 1.75], rtol=TOL)


def test_the_deflected_shape_draws_the_bearing_stations_in_metres():
    x = np.array([0.0, 1.0, 2.0])
    fig = deflected_shape_figure(x, 1e-3 * x, -1e-3 * x, bearings_x=[0.5, 1.5])
    for ax in fig.axes[:2]:
        stations = sorted(float(ln.get_xdata()[0]) for ln in ax.get_lines() if ln.get_linestyle() == ":")
        assert stations == [0.5, 1.5]
        markers = [ln for ln in ax.get_lines() if ln.get_marker() == "^"]
        assert sorted(float(m.get_xdata()[0]) for m in markers) == [0.5, 1.5]
        assert ax.get_xlim()[1] <= 2.0 + 0.1  # the shaft's 2 m (and a margin), not 1500 "m"


def test_a_mode_shape_with_a_node_changes_sign_there():
    x = np.linspace(0.0, 0.75, 4)
    v = 3e-3 * (1.0 - 2.0 * x)  # 1, 0.5, 0, -0.5 (x 3e-3): the largest |v| at x = 0 alone, positive
    fig = mode_shapes_figure(x, [{"label": "mode 1", "v": v, "w": np.zeros_like(x)}])
    (drawn,) = [ln for ln in fig.axes[0].get_lines() if ln.get_label() == "shaft v (vertical)"]
    np.testing.assert_allclose(drawn.get_ydata(), 1.0 - 2.0 * x, rtol=TOL, atol=TOL)


def test_a_torsional_shape_is_scaled_by_its_largest_magnitude():
    x = np.linspace(0.0, 1.0, 5)
    theta = np.array([0.2, -0.5, -1.0, 0.4, 0.0])
    fig = mode_shapes_figure(x, [{"label": "mode 1", "along": ("torsional", 7e-3 * theta)}])
    (drawn,) = [ln for ln in fig.axes[0].get_lines() if ln.get_label() == "shaft twist θ (torsion)"]
    np.testing.assert_allclose(drawn.get_ydata(), -theta, rtol=TOL, atol=TOL)


def test_an_axial_mode_is_drawn_as_its_axial_displacement():
    length = 2.0
    x = np.linspace(0.0, length, 9)
    u = 4e-4 * np.sin(np.pi * x / (2.0 * length))  # first mode of a fixed-free bar
    noise = 1e-19 * np.cos(7.0 * x)  # round-off lateral parts
    fig = mode_shapes_figure(x, [{"label": "mode 5", "along": ("axial", u), "v": noise, "w": noise}])
    lines = {ln.get_label(): ln for ln in fig.axes[0].get_lines()}
    assert "shaft v (vertical)" not in lines and "shaft w (lateral)" not in lines
    np.testing.assert_allclose(
        lines["shaft axial u"].get_ydata(), np.sin(np.pi * x / (2.0 * length)), rtol=TOL, atol=TOL
    )
