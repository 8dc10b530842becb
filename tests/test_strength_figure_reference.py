"""The shaft-strength figures show the failure line and the load shares the verdict reads.

``safety_factor_figure`` and ``load_shares_figure`` are drawn from small hand-built inputs and
read back from their matplotlib artists. References, by hand:

* Tsai-Wu failure is R = 1 (the safety factor R scales the stresses to the failure surface,
  F(R sigma) = 1); the figure draws that line (labelled "failure (R = 1)"), so the y range must
  contain 1 whatever the factors are: on the logarithmic axis too, which the figure picks when
  the factors span more than 50:1 (``safety_factor_figure``'s docstring, code; here 2 to 400,
  200:1, and the axis is checked to be logarithmic);
* the load-share chart labels each bar with its load: the bar at tick "torque" has the torque's
  share as its width, and so on (shares 0.5, 0.375, 0.25, -0.125 summing to 1, exact binary
  fractions, so widths and the "+50.0%" style labels are exact).

Agg, no file.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from flexshaft.plot.driveline import load_shares_figure, safety_factor_figure  # noqa: E402


def test_log_safety_factor_axis_still_shows_the_failure_line():
    """Factors 400, 20, 2, 40 along 4 stations (200:1, so a log axis): every factor exceeds 1.25,
    yet the failure line R = 1 is inside the y range and the critical point (x = 2, R = 2) is
    marked at the smallest factor."""
    x = np.array([0.0, 1.0, 2.0, 3.0])
    factor = np.array([400.0, 20.0, 2.0, 40.0])
    fig = safety_factor_figure(x, factor)
    ax = fig.axes[0]
    assert ax.get_yscale() == "log"
    low, high = ax.get_ylim()
    assert low < 1.0 < high
    (failure,) = [ln for ln in ax.get_lines() if ln.get_label() == "failure (R = 1)"]
    assert list(failure.get_ydata()) == [1.0, 1.0]
    (critical,) = [ln for ln in ax.get_lines() if ln.get_label() == "critical point"]
    assert list(critical.get_xdata()) == [2.0] and list(critical.get_ydata()) == [2.0]
    plt.close(fig)


def test_each_load_share_bar_sits_at_its_own_name():
    """Shares torque 0.5, bending 0.375, thermal 0.25, axial -0.125: the bar at each tick name
    has that load's share as its width and the text beside it reads the share in per cent."""
    shares = {"torque": 0.5, "bending": 0.375, "thermal": 0.25, "axial": -0.125}
    fig = load_shares_figure(shares)
    ax = fig.axes[0]
    tick_of = {t.get_text(): round(float(y)) for t, y in zip(ax.get_yticklabels(), ax.get_yticks())}
    assert set(tick_of) == set(shares)
    width_at = {}
    for bar in ax.patches:
        width_at[round(bar.get_y() + 0.5 * bar.get_height())] = bar.get_width()  # bars at integer y
    for name, share in shares.items():
        assert width_at[tick_of[name]] == share, name
    texts = {t.get_text() for t in ax.texts}
    assert texts == {"+50.0%", "+37.5%", "+25.0%", "-12.5%"}  # the labels' format is the code's own
    plt.close(fig)
