"""The stability figures draw the requirement, the onset and the unstable side where they are.

Hand-built curves (no model); references derived here:

* the requirement is on the log decrement δ, the quantity on the axis: its line sits at δ_req
  (not at ζ = δ_req/2π);
* the onset speed [rpm] is marked at (n_onset, δ = 0) on an axis in rpm;
* δ < 0 is unstable (a free vibration grows by e^{−δ} per cycle): the red band covers only
  δ ≤ 0;
* the onset map's operating-speed line sits at the operating speed [rpm]; its required onset
  at (1 + min_onset_margin) × that speed (docs/requirements.md).

Compared to rel 1e-12 (no discretisation). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.stability import log_decrement_figure, stability_map_figure  # noqa: E402

REL = 1e-12


def _span_y(patch) -> np.ndarray:
    """The data y of a horizontal span's corners (a Rectangle or a Polygon, by matplotlib version)."""
    return patch.get_patch_transform().transform(patch.get_path().vertices)[:, 1]


def test_log_decrement_figure_marks_the_requirement_onset_and_unstable_side():
    speeds = np.linspace(0.0, 6000.0, 7)  # [rpm]
    delta = np.column_stack([0.4 - speeds / 10000.0, np.full(7, 0.25)])  # mode 1 crosses 0 at 4000 rpm
    fig = log_decrement_figure(speeds, {"shaft": delta}, {"shaft": 4000.0}, operating_rpm=4800.0, required=0.1)
    ax = fig.axes[0]
    (req,) = [ln for ln in ax.get_lines() if str(ln.get_label()).startswith("required")]
    np.testing.assert_allclose(req.get_ydata(), [0.1, 0.1], rtol=REL)
    (cross,) = [ln for ln in ax.get_lines() if ln.get_marker() == "X"]
    np.testing.assert_allclose([cross.get_xdata()[0], cross.get_ydata()[0]], [4000.0, 0.0], rtol=REL)
    verticals = [list(ln.get_xdata()) for ln in ax.get_lines() if ln.get_transform() == ax.get_xaxis_transform()]
    assert sorted(verticals) == [[4000.0, 4000.0], [4800.0, 4800.0]]  # the onset and the operating speed
    assert "onset 4000 rpm" in [t.get_text() for t in ax.texts]
    (band,) = ax.patches
    y = _span_y(band)
    assert y.max() == 0.0 and y.min() < delta.min()  # from below the lowest curve up to δ = 0


def test_stability_map_operating_line_at_the_operating_speed():
    kd = np.array([0.0, 100.0, 200.0])
    ax = stability_map_figure(kd, {"shaft": [3000.0, 5000.0, np.nan]}, operating_rpm=4800.0, max_rpm=7200.0).axes[0]
    (op,) = [ln for ln in ax.get_lines() if str(ln.get_label()).startswith("operating speed")]
    np.testing.assert_allclose(op.get_ydata(), [4800.0, 4800.0], rtol=REL)
    (bound,) = [ln for ln in ax.get_lines() if str(ln.get_label()).startswith("stable to")]
    np.testing.assert_allclose(bound.get_ydata(), [7200.0, 7200.0], rtol=REL)


def test_stability_map_required_onset_and_the_design_star():
    """The whirl-onset check requires (1 + margin) × Ω_op: 1.15 × 4800 = 5520 rpm, drawn dashed
    at 5520. The design's own gains: a design stable to the top speed is an open star at
    (K_d, max_rpm); one with an onset a filled star at (K_d, onset)."""
    kd = np.array([0.0, 100.0, 200.0])
    for onset, y, face in ((None, 7200.0, "none"), (6100.0, 6100.0, "gold")):
        ax = stability_map_figure(
            kd,
            {"shaft": [3000.0, 5000.0, np.nan]},
            operating_rpm=4800.0,
            max_rpm=7200.0,
            required_rpm=1.15 * 4800.0,
            design=(150.0, onset, "this design"),
        ).axes[0]
        (required,) = [ln for ln in ax.get_lines() if str(ln.get_label()).startswith("required onset")]
        np.testing.assert_allclose(required.get_ydata(), [5520.0, 5520.0], rtol=REL)
        (star,) = [ln for ln in ax.get_lines() if ln.get_label() == "this design"]
        assert star.get_marker() == "*" and star.get_markerfacecolor() == face
        np.testing.assert_allclose([star.get_xdata()[0], star.get_ydata()[0]], [150.0, y], rtol=REL)


def test_series_stable_at_the_same_gain_each_keep_a_visible_ring():
    """Three gain series all stable at K_d = 300 N s/m share the point (300, max_rpm). Rings of
    one size and centre drawn in turn leave only the last one's colour visible (the report's
    map showed K_p = 5e5 there and hid 1.67e4 and 1e5). Geometry: a later ring of strictly
    smaller diameter lies inside the earlier ones, so each series' ring shows its colour. The
    open markers at max_rpm are one per series, in the series' colour, each smaller than the
    one drawn before it by at least two strokes (rings of 1 pt strokes)."""
    kd = np.array([0.0, 300.0])
    series = {
        "K_p = 1.67e+04 N/m": [1280.0, np.nan],
        "K_p = 1e+05 N/m": [np.nan, np.nan],
        "K_p = 5e+05 N/m": [2400.0, np.nan],
    }
    ax = stability_map_figure(kd, series, max_rpm=7200.0).axes[0]
    named = {str(ln.get_label()): ln for ln in ax.get_lines() if str(ln.get_label()) in series}
    rings = [ln for ln in ax.get_lines() if ln.get_marker() == "o" and ln.get_markerfacecolor() == "none"]
    at_300 = [ln for ln in rings if 300.0 in ln.get_xdata()]
    assert [ln.get_color() for ln in at_300] == [named[name].get_color() for name in series]
    np.testing.assert_allclose([ln.get_ydata()[list(ln.get_xdata()).index(300.0)] for ln in at_300], 7200.0, rtol=REL)
    # a ring inside another shows when their radii differ by at least the outer ring's stroke
    # (markersize is a diameter [pt], markeredgewidth a stroke width [pt]): strokes do not overlap
    for outer, inner in zip(at_300, at_300[1:]):
        assert (outer.get_markersize() - inner.get_markersize()) / 2 >= outer.get_markeredgewidth()


def test_modes_the_requirement_does_not_judge_are_grey():
    """Three tracked modes, the first not judged by the δ requirement (a boom mode, say): drawn in
    the grey of NOT_JUDGED_COLOR with a legend entry, the judged two in the colour cycle; a
    mask of the wrong length is refused naming the set."""
    import matplotlib.colors as mcolors
    import pytest

    from flexshaft.plot.stability import NOT_JUDGED_COLOR

    speeds = np.array([0.0, 3000.0, 6000.0])
    delta = np.array([[0.06, 0.2, 0.3], [0.06, 0.21, 0.31], [0.06, 0.22, 0.32]])
    fig = log_decrement_figure(speeds, {"d": delta}, judged={"d": [False, True, True]}, required=0.1)
    ax = fig.axes[0]  # a Figure without pyplot's state: nothing to close
    grey = mcolors.to_rgba(NOT_JUDGED_COLOR)
    drawn = [ln for ln in ax.get_lines() if len(ln.get_xdata()) == 3]
    by_first = {round(float(ln.get_ydata()[0]), 3): mcolors.to_rgba(ln.get_color()) for ln in drawn}
    assert by_first[0.06] == grey and by_first[0.2] != grey and by_first[0.3] != grey
    legend = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "not judged by the δ requirement" in legend
    with pytest.raises(ValueError, match=r"judged\['d'\]: expected 3 entries"):
        log_decrement_figure(speeds, {"d": delta}, judged={"d": [True, False]})


def test_the_legend_band_leaves_the_x_label_visible():
    """Seven legend entries (a greyed mode, the requirement, the operating speed, an onset and
    three whirl styles): the band below the axes holds two rows; in three the legend covered
    the x label (audit a2, the Jeffcott rotor's report). Measured on the drawn boxes."""
    speeds = np.linspace(0.0, 6000.0, 7)
    delta = np.column_stack([0.09 - 1e-4 * np.maximum(speeds - 2885.0, 0.0), 0.062 + 0 * speeds, 0.09 + 0 * speeds])
    name = "this design"
    fig = log_decrement_figure(
        speeds,
        {name: delta},
        {name: 2885.0},
        4000.0,
        whirl={name: np.array([["forward", "backward", "planar"]] * speeds.size)},
        required=0.1,
        judged={name: [True, False, True]},
    )
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    (legend,) = fig.legends
    assert len(legend.get_texts()) == 7
    assert legend.get_window_extent(renderer).y1 <= fig.axes[0].xaxis.label.get_window_extent(renderer).y0
