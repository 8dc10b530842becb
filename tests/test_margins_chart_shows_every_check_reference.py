"""The margins chart shows every check of the verdict inside its axes.

docs/requirements.md: every check has a status and a normalised margin, "the margins figure's
number"; the figure draws one horizontal bar per check (its docstring: "One horizontal bar per
requirement"). A check whose bar lies outside the axes' vertical range is missing from the
chart. Reference, derived here: each of the n bars (one per title, in order top to bottom,
0.6 high) lies wholly inside the y limits, and each check's name is the tick label at its bar's
centre. Bar extents are sums of small floats (no rounding beyond 1 ulp), compared with the
limits directly (the bars keep 0.4 clear of the limits when drawn right); a centre is matched
to its tick at 1e-12 (a few ulp of numbers below 10). Agg, nothing written.
"""

from __future__ import annotations

import matplotlib
import pytest
from matplotlib.patches import Rectangle

matplotlib.use("Agg")

from flexshaft.plot.verdict import margins_figure  # noqa: E402

TITLES = ["Tsai-Wu safety factor", "separation", "whirl damping", "temperature"]
MARGINS = [0.4, -0.3, float("nan"), 1.2]
STATUS = ["pass", "fail", "not evaluated", "pass"]


@pytest.mark.parametrize("n", [1, 2, 4])
def test_every_bar_lies_inside_the_axes(n):
    """n = 1, 2, 4 checks: n bars, each within the y limits, each named by its own title."""
    fig = margins_figure(TITLES[:n], MARGINS[:n], STATUS[:n])
    ax = fig.axes[0]
    bars = [p for p in ax.patches if isinstance(p, Rectangle)]
    lo, hi = ax.get_ylim()
    ticks = dict(zip(ax.get_yticks(), (t.get_text() for t in ax.get_yticklabels()), strict=True))
    assert len(bars) == n
    # the first title is drawn at the top: bars sorted from the top down follow the titles
    for bar, title in zip(sorted(bars, key=lambda b: -b.get_y()), TITLES[:n], strict=True):
        assert lo <= bar.get_y() and bar.get_y() + bar.get_height() <= hi, title
        centre = bar.get_y() + bar.get_height() / 2
        tick = min(ticks, key=lambda t: abs(t - centre))
        assert tick == pytest.approx(centre, abs=1e-12)
        assert ticks[tick] == title
