"""Verdict, run-up and Monte-Carlo figures draw margins, limits and peaks as given.

Each figure is drawn from small hand-built inputs and read back from its matplotlib artists.
References, derived by hand in each test:

* margins bar chart: zero margin (the pass/fail boundary) is the vertical line at 0; the axis
  is margin/limit as a fraction written in percent (0.5 → "50%"); a bar longer than the axis
  (+400 % on an axis ending at +300 %) is cut at the end, with an arrow pointing outward (">")
  and the true margin written ("+400%");
* Ω [rpm] = Ω [rad/s] · 60 / (2π): 20π rad/s = 600 rpm, 40π rad/s = 1200 rpm;
* forces [N] drawn on a newton axis unchanged;
* Monte-Carlo exceedance estimate: k of N samples exceed → P = k/N (3/40 = 0.075).

Exact binary values or one multiplication's round-off: exact or 1e-12 relative. Agg, no file.
"""

from __future__ import annotations

from types import SimpleNamespace

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from flexshaft.plot.transient import _mark_bound, runup_envelope_figure  # noqa: E402
from flexshaft.plot.verdict import margins_figure  # noqa: E402


def _line(ax, label):
    return next(ln for ln in ax.get_lines() if ln.get_label() == label)


def test_margins_zero_line_percent_axis_and_cut_bar():
    # limits (-2, 3): lo = max(-2, min(-0.5, -0.5)) = -0.5, hi = min(3, max(0.5, 4)) = 3
    fig = margins_figure(["onset", "orbit", "force"], [4.0, 0.25, -0.5], ["pass", "pass", "fail"])
    try:
        ax = fig.axes[0]
        vertical = [ln for ln in ax.get_lines() if ln.get_label().startswith("_") and ln.get_marker() in ("None", "")]
        assert [list(ln.get_xdata()) for ln in vertical] == [[0.0, 0.0]]
        assert ax.xaxis.get_major_formatter()(0.5, 0) == "50%"
        arrows = [ln for ln in ax.get_lines() if ln.get_marker() in (">", "<")]
        assert len(arrows) == 1 and arrows[0].get_marker() == ">"
        assert float(np.ravel(arrows[0].get_xdata())[0]) == 3.0
        assert [t.get_text() for t in ax.texts] == ["+400%", "+25%", "-50%"]
    finally:
        plt.close(fig)


def test_runup_steady_curve_in_rpm_and_force_limit_in_newtons():
    two_pi = 2.0 * np.pi
    run = SimpleNamespace(
        speed=[10.0 * two_pi, 20.0 * two_pi],
        shaft_peak=[1e-4, 2e-4],
        actuator_displacement=np.array([[1e-5, 2e-5]]),
        actuator_force=np.array([[10.0, 20.0]]),
    )
    steady = SimpleNamespace(
        speeds=[10.0 * two_pi, 20.0 * two_pi],
        shaft_peak=[3e-4, 4e-4],
        actuator_displacement=np.array([[3e-5, 4e-5]]),
        actuator_force=np.array([[30.0, 40.0]]),
    )
    fig = runup_envelope_figure({"run": run}, steady, force_limit=150.0)
    try:
        shaft, _, force = fig.axes[:3]
        np.testing.assert_allclose(_line(shaft, "steady-state spin-up").get_xdata(), [600.0, 1200.0], rtol=1e-12)
        np.testing.assert_allclose(_line(shaft, "run").get_xdata(), [600.0, 1200.0], rtol=1e-12)
        np.testing.assert_array_equal(_line(force, "force limit 150 N").get_ydata(), [150.0, 150.0])
    finally:
        plt.close(fig)


def test_montecarlo_bound_marks_the_estimate_k_over_n():
    fig, ax = plt.subplots()
    try:
        _mark_bound(ax, 2.0, 3, 40, 0.2)
        dot = next(ln for ln in ax.get_lines() if ln.get_marker() == "o")
        assert float(np.ravel(dot.get_ydata())[0]) == 0.075
        assert ax.texts[0].get_text() == "3 of 40 samples exceed:\nP = 0.075, < 0.2 (95 %)"
    finally:
        plt.close(fig)
