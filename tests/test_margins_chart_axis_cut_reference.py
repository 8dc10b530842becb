"""The margins chart cuts long bars at its axis range and keeps a +inf bar inside the axes.

References (API contract: the docstring of margins_figure, flexshaft.plot.verdict; no docs page states it):

* ``limits`` is the "axis range [-]; longer bars are cut with an arrow": with the default
  limits (-2, 3) a margin of -500 % is drawn as a bar of exactly -200 % (np.clip of a finite
  value is exact) with a "<" arrow at its end, and the axis does not extend to -500 %.
* A margin of +inf that passed is "a bar to the axis end": with finite margins no larger than
  +80 % the axis ends near +80 % (hi = max(0.5, 0.8) = 0.8, then 30 % of the span for the
  texts), so the +inf bar must be at least as long as the longest finite bar (0.8) and end
  inside the axes' x range; a bar cut at the fixed +300 % limit would run past the axis end.

Hand-built stand-in margins, matplotlib Agg, bars and markers read back from the artists
(< 0.5 s). Bar widths are compared exactly or with a 1e-12 margin: they are copies of the
given values or of np.clip of them, no arithmetic beyond one subtraction.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from flexshaft.plot.verdict import margins_figure  # noqa: E402


def _bars(ax) -> list[float]:
    """Widths of the bars, top to bottom (the figure draws the first title at the top)."""
    patches = sorted(ax.patches, key=lambda p: -p.get_y())
    return [p.get_width() for p in patches]


def test_a_margin_beyond_the_lower_limit_is_cut_there_with_an_arrow() -> None:
    fig = margins_figure(["orbit", "onset"], [-5.0, 0.4], ["fail", "pass"])
    try:
        ax = fig.axes[0]
        widths = _bars(ax)
        assert widths[0] == -2.0  # cut at the lower limit, not -5
        assert widths[1] == 0.4
        lo, hi = ax.get_xlim()
        assert -2.5 < lo <= -2.0  # the axis stops near its limit, not at -500 %
        arrows = [line for line in ax.lines if line.get_marker() == "<"]
        assert len(arrows) == 1 and arrows[0].get_xdata()[0] == -2.0
    finally:
        plt.close(fig)


def test_an_infinite_pass_ends_at_the_axis_end_not_beyond() -> None:
    fig = margins_figure(["phase margin", "orbit"], [np.inf, 0.8], ["pass", "pass"])
    try:
        ax = fig.axes[0]
        widths = _bars(ax)
        lo, hi = ax.get_xlim()
        assert widths[1] == 0.8
        assert 0.8 <= widths[0] <= hi + 1e-12  # as long as the longest bar, inside the axes
        arrows = [line for line in ax.lines if line.get_marker() == ">"]
        assert len(arrows) == 1 and arrows[0].get_xdata()[0] <= hi + 1e-12
    finally:
        plt.close(fig)
