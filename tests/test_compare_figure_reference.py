"""The ``flexshaft compare`` figures draw the numbers given, in the units of their axes.

Each figure is drawn from small hand-built arrays and read back from its matplotlib artists.
References, derived by hand in each test:

* 1 Hz = 60 rpm, so the 1× excitation line is f = Ω/60 [Hz] for Ω in rpm, and a natural
  frequency given in Hz is drawn unchanged on the Hz axis;
* 1 m = 1000 mm for every orbit, deflection and limit drawn on a millimetre axis;
* the governing point of a safety-factor curve is its smallest value;
* stacked bars: each part's bar starts where the parts below it end (cumulative sum).

All values are exact binary fractions or products of one rounding, so comparisons are exact or
to 1e-12 relative (one multiplication's round-off). Agg, no file.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from flexshaft.plot.compare import (  # noqa: E402
    campbell_overlay_figure,
    mass_breakdown_figure,
    safety_factor_overlay_figure,
    spinup_overlay_figure,
    static_deflection_overlay_figure,
)


def _line(ax, label):
    return next(ln for ln in ax.get_lines() if ln.get_label() == label)


def test_campbell_overlay_draws_hz_and_the_whirl_of_each_run():
    # One mode: forward at the first two speeds, backward at the last two (whirl changes
    # between 2000 and 4000 rpm). Runs share one point of overlap: forward on speeds 0..2
    # (indices 0, 1, 2), backward on indices 2, 3.
    speeds = np.array([0.0, 2000.0, 4000.0, 6000.0])
    freqs = np.array([[50.0], [52.0], [48.0], [46.0]])
    whirl = np.array([["forward"], ["forward"], ["backward"], ["backward"]])
    fig = campbell_overlay_figure({"A": (speeds, freqs, whirl)})
    try:
        ax = fig.axes[0]
        data = [ln for ln in ax.get_lines() if ln.get_label().startswith("_")]
        assert len(data) == 2
        fwd, bwd = data
        assert fwd.get_linestyle() == "-" and bwd.get_linestyle() == "--"
        np.testing.assert_array_equal(fwd.get_xdata(), [0.0, 2000.0, 4000.0])
        np.testing.assert_array_equal(fwd.get_ydata(), [50.0, 52.0, 48.0])  # Hz drawn as given
        np.testing.assert_array_equal(bwd.get_ydata(), [48.0, 46.0])
        one_x = _line(ax, "1× excitation")
        np.testing.assert_array_equal(one_x.get_xdata(), [0.0, 6000.0])
        np.testing.assert_allclose(one_x.get_ydata(), [0.0, 100.0], rtol=1e-12)  # 6000 rpm / 60 = 100 Hz
    finally:
        plt.close(fig)


def test_spinup_overlay_draws_orbits_and_limit_in_mm():
    speeds = np.array([1000.0, 2000.0, 3000.0])
    peak = np.array([1e-4, 5e-4, 2e-4])  # m: 0.1, 0.5, 0.2 mm
    fig = spinup_overlay_figure({"A": (speeds, peak)}, limit=1.5e-3)
    try:
        ax = fig.axes[0]
        np.testing.assert_allclose(_line(ax, "A").get_ydata(), [0.1, 0.5, 0.2], rtol=1e-12)
        limit = _line(ax, "limit 1.5 mm")
        np.testing.assert_allclose(limit.get_ydata(), [1.5, 1.5], rtol=1e-12)
    finally:
        plt.close(fig)


def test_safety_factor_overlay_marks_the_smallest_and_the_requirement():
    x = np.array([0.0, 1.0, 2.0, 3.0])
    sf = np.array([4.0, 2.5, 3.0, 8.0])  # smallest 2.5 at x = 1 m
    fig = safety_factor_overlay_figure({"A": (x, sf, "Tsai-Wu")}, required=1.5)
    try:
        ax = fig.axes[0]
        marker = next(ln for ln in ax.get_lines() if ln.get_marker() == "o")
        assert (float(np.ravel(marker.get_xdata())[0]), float(np.ravel(marker.get_ydata())[0])) == (1.0, 2.5)
        assert [t.get_text() for t in ax.texts] == ["2.5 at 1.00 m"]
        np.testing.assert_array_equal(_line(ax, "required 1.5").get_ydata(), [1.5, 1.5])
    finally:
        plt.close(fig)


def test_static_deflection_overlay_puts_v_and_w_on_their_panels_in_mm():
    x = np.array([0.0, 1.0, 2.0])
    v = np.array([0.0, -2e-3, 0.0])  # m: vertical sag 2 mm at mid-span
    w = np.array([0.0, 5e-4, 1e-3])  # m: lateral 0.5, 1 mm
    fig = static_deflection_overlay_figure({"A": (x, v, w)}, joints={"A": [1.5]})
    try:
        top, bottom = fig.axes[0], fig.axes[1]
        assert top.get_ylabel().startswith("vertical v") and bottom.get_ylabel().startswith("lateral w")
        np.testing.assert_allclose(_line(top, "A").get_ydata(), [0.0, -2.0, 0.0], rtol=1e-12)
        np.testing.assert_allclose(_line(bottom, "A").get_ydata(), [0.0, 0.5, 1.0], rtol=1e-12)
        # coupling at 1.5 m: linear interpolation between nodes 1 and 2, (-2 + 0)/2 = -1 mm on v,
        # (0.5 + 1)/2 = 0.75 mm on w
        np.testing.assert_allclose(_line(top, "A: couplings").get_ydata(), [-1.0], rtol=1e-12)
        np.testing.assert_allclose(_line(bottom, "A: couplings").get_ydata(), [0.75], rtol=1e-12)
    finally:
        plt.close(fig)


def test_mass_breakdown_stacks_the_parts_to_the_written_total():
    masses = {"A": {"shaft": 3.0, "couplings": 1.5}, "B": {"shaft": 2.0, "couplings": 2.5}}
    fig = mass_breakdown_figure(masses)
    try:
        ax = fig.axes[0]
        bars = ax.patches
        assert len(bars) == 4  # shaft A, shaft B, couplings A, couplings B
        # couplings start on top of the shaft: bottoms 3.0 and 2.0, tops 4.5 and 4.5 kg
        assert [b.get_y() for b in bars[2:]] == pytest.approx([3.0, 2.0], abs=0.0)
        assert [b.get_y() + b.get_height() for b in bars[2:]] == pytest.approx([4.5, 4.5], abs=0.0)
        assert [t.get_text() for t in ax.texts] == ["4.5 kg", "4.5 kg"]
    finally:
        plt.close(fig)


def test_each_design_is_drawn_against_its_own_limit():
    """Each design is checked against its own [requirements]: where the two limits differ the
    figure draws both, each in its design's colour and named after it (A 1.5 mm and B 2 mm of
    spin-up orbit; a required safety factor of 1.5 and 2.25); where they agree, one line."""
    speeds = np.array([1000.0, 2000.0])
    both = {"A": (speeds, np.array([1e-4, 2e-4])), "B": (speeds, np.array([3e-4, 4e-4]))}
    fig = spinup_overlay_figure(both, limit={"A": 1.5e-3, "B": 2e-3})
    try:
        ax = fig.axes[0]
        a, b = _line(ax, "limit (A) 1.5 mm"), _line(ax, "limit (B) 2 mm")
        np.testing.assert_allclose(a.get_ydata(), [1.5, 1.5], rtol=1e-12)
        np.testing.assert_allclose(b.get_ydata(), [2.0, 2.0], rtol=1e-12)
        assert (a.get_color(), b.get_color()) == (_line(ax, "A").get_color(), _line(ax, "B").get_color())
        assert not [ln for ln in ax.get_lines() if ln.get_label().startswith("limit 1")]
    finally:
        plt.close(fig)
    fig = spinup_overlay_figure(both, limit={"A": 1.5e-3, "B": 1.5e-3})
    try:
        labels = [ln.get_label() for ln in fig.axes[0].get_lines() if ln.get_label().startswith("limit")]
        assert labels == ["limit 1.5 mm"]
    finally:
        plt.close(fig)
    x = np.array([0.0, 1.0])
    curves = {"A": (x, np.array([3.0, 4.0]), "Tsai-Wu"), "B": (x, np.array([5.0, 6.0]), "Tsai-Wu")}
    fig = safety_factor_overlay_figure(curves, required={"A": 1.5, "B": 2.25})
    try:
        ax = fig.axes[0]
        np.testing.assert_array_equal(_line(ax, "required (A) 1.5").get_ydata(), [1.5, 1.5])
        np.testing.assert_array_equal(_line(ax, "required (B) 2.25").get_ydata(), [2.25, 2.25])
        assert ax.get_ylim()[0] == pytest.approx(0.7 * 1.5, rel=1e-12)  # the lower limit in view
    finally:
        plt.close(fig)


def test_each_design_is_marked_at_its_own_operating_speed():
    """Two designs running at 4800 and 6000 rpm: a dash-dot line at each, in its design's colour
    and named after it, on the Campbell and spin-up overlays; one line when they agree."""
    speeds = np.array([0.0, 3000.0, 7000.0])
    freqs = np.array([[40.0], [41.0], [42.0]])
    whirl = np.full((3, 1), "forward")
    curves = {"A": (speeds, freqs, whirl), "B": (speeds, freqs + 5.0, whirl)}
    fig = campbell_overlay_figure(curves, {"A": 4800.0, "B": 6000.0})
    try:
        ax = fig.axes[0]
        a, b = _line(ax, "operating speed (A) 4800 rpm"), _line(ax, "operating speed (B) 6000 rpm")
        np.testing.assert_array_equal(a.get_xdata(), [4800.0, 4800.0])
        np.testing.assert_array_equal(b.get_xdata(), [6000.0, 6000.0])
        assert (a.get_color(), b.get_color()) == ("tab:blue", "tab:orange")
        legend = [t.get_text() for t in ax.get_legend().get_texts()]
        assert "operating speed (A) 4800 rpm" in legend and "operating speed (B) 6000 rpm" in legend
    finally:
        plt.close(fig)
    both = {"A": (speeds, np.array([1e-4, 2e-4, 1e-4])), "B": (speeds, np.array([2e-4, 3e-4, 2e-4]))}
    fig = spinup_overlay_figure(both, {"A": 4800.0, "B": 4800.0})
    try:
        marks = [ln.get_label() for ln in fig.axes[0].get_lines() if ln.get_label().startswith("operating")]
        assert marks == ["operating speed 4800 rpm"]
    finally:
        plt.close(fig)
