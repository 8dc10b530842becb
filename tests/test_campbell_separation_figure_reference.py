"""The Campbell diagram shows what the separation check judges: the operating speed range its
margins are measured from, and the margin API 684 requires of each of the verdict's critical
speeds (issue: "the Campbell diagram shows less than the verdict uses").

A hand-built diagram (one mode, no model) with the tuned and current designs' range: operating
speed 4800 rpm, range 4560-5040 rpm (0.95-1.05 of it). Two verdict criticals, both with AF 5.2,
whose API 684 readings are worked here by hand (docs/requirements.md, "Separation margin"):

* 17 (1 − 1/(AF − 1.5)) = 17 (1 − 1/3.7) = 12.405 %; below the operating speed the required
  margin is min(16, 12.405) = 12.405 %, above it min(26, 10 + 12.405) = 22.405 %;
* the critical at 4000 rpm lies below: its margin is measured from the range's lowest speed,
  (4560 − 4000)/4560 = 12.28 %, short of 12.405 % (fails); the speeds it may have end at
  4560 (1 − 0.12405) = 3994.3 rpm, so its bar runs from 4560 to 3994.3 rpm and holds 4000;
* the critical at 6000 rpm lies above: (6000 − 5040)/5040 = 19.05 % from the highest speed,
  short of 22.405 %; its bar runs from 5040 to 5040 (1.22405) = 6169.2 rpm and holds 6000.
  (tuned.toml's comment: measured from 4800 rpm it would look like 25 %, a pass.)

The bars lie on each critical's frequency, f = n/60 [Hz]. The figure draws straight segments
from the numbers it is given: compared at rel 1e-12 (round-off of one product). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from types import SimpleNamespace as NS  # noqa: E402

from flexshaft.plot.campbell import campbell_figure  # noqa: E402
from flexshaft.report.verdict import separation_readings  # noqa: E402

SPEEDS = np.linspace(0.0, 7000.0, 8)  # [rpm]
RANGE = (4560.0, 5040.0)  # [rpm]
BASE = 17.0 * (1.0 - 1.0 / 3.7) / 100.0  # 0.12405
CRITICALS = [(4000.0, 5.2), (6000.0, 5.2)]
SEPARATION = [
    (4560.0, 4560.0 * (1.0 - BASE), 560.0 / 4560.0, BASE),
    (5040.0, 5040.0 * (1.0 + 0.10 + BASE), 960.0 / 5040.0, 0.10 + BASE),
]
REL = 1e-12


def _draw(criticals, separation, **extra):
    """The one-mode diagram (90 Hz, forward) with these verdict criticals and readings."""
    freqs = np.full((SPEEDS.size, 1), 90.0)
    return campbell_figure(
        SPEEDS, freqs, np.full(freqs.shape, "forward"), response_criticals=criticals, separation=separation, **extra
    )


def _close(fig) -> None:
    import matplotlib.pyplot as plt

    plt.close(fig)


@pytest.fixture(scope="module")
def ax():
    fig = _draw(CRITICALS, SEPARATION, operating_rpm=4800.0, speed_range_rpm=RANGE)
    yield fig.axes[0]
    _close(fig)


def _bars(ax):
    return [ln for ln in ax.get_lines() if ln.get_label().startswith("required separation")]


def test_the_operating_speed_range_is_shaded_where_the_margins_start(ax):
    (band,) = [p for p in ax.patches if p.get_label().startswith("operating speed range")]
    corners = band.get_patch_transform().transform(band.get_path().vertices)
    # axvspan: data x, axes-fraction y
    assert corners[:, 0].min() == pytest.approx(4560.0, rel=REL)
    assert corners[:, 0].max() == pytest.approx(5040.0, rel=REL)


def test_each_critical_has_its_required_separation_as_a_bar_on_its_frequency(ax):
    bars = sorted((tuple(b.get_xdata()), tuple(b.get_ydata())) for b in _bars(ax))
    (x_below, y_below), (x_above, y_above) = bars
    assert x_below == pytest.approx((4560.0, 4560.0 * (1.0 - 0.12405405405405405)), rel=REL)
    assert x_above == pytest.approx((5040.0, 5040.0 * (1.0 + 0.22405405405405405)), rel=REL)
    assert y_below == pytest.approx((4000.0 / 60.0,) * 2, rel=REL)
    assert y_above == pytest.approx((6000.0 / 60.0,) * 2, rel=REL)
    # both criticals fail: each lies inside its bar
    assert min(x_below) < 4000.0 < max(x_below) and min(x_above) < 6000.0 < max(x_above)


def test_each_critical_is_labelled_with_its_margin_and_the_required_one(ax):
    texts = " | ".join(t.get_text() for t in ax.texts)
    assert "4000 rpm, AF 5.2, margin 12.3% (needs 12.4%)" in texts
    assert "6000 rpm, AF 5.2, margin 19.0% (needs 22.4%)" in texts


def test_a_critical_that_needs_no_margin_gets_no_bar():
    """AF 2 < 2.5: API 684 requires no separation (a critically damped peak): no bar, the label
    says 0 %."""
    fig = _draw([(4500.0, 2.0)], [(4560.0, 4560.0, 60.0 / 4560.0, 0.0)], operating_rpm=4800.0, speed_range_rpm=RANGE)
    ax = fig.axes[0]
    assert _bars(ax) == []
    assert any("needs 0.0%" in t.get_text() for t in ax.texts)
    _close(fig)


def test_the_separation_readings_must_match_the_criticals():
    """One reading per verdict critical, or none (the figure without the separation check)."""
    with pytest.raises(
        ValueError, match="one \\(reference, bound, margin, required\\) per response critical, got 1 for 2"
    ):
        _draw(CRITICALS, SEPARATION[:1])


def test_a_critical_inside_the_range_gets_the_bar_of_its_side_of_the_operating_speed():
    """The report's readings (report.driveline) as the check takes them: 4700 rpm lies inside
    4560-5040 rpm, below 4800: API 684 measures it from the lowest speed (its margin 0: inside
    the range), and the speeds it may have end at 4560 (1 − 0.12405): its bar runs down from
    4560 rpm, not up (the critical is above 4560; its side is the operating speed's). A
    critical exactly at the operating speed, at the range's lowest end (range 4800-5040), is
    inside the range too: margin 0."""
    rad = 2.0 * np.pi / 60.0  # rad/s per rpm
    inside = [NS(speed=4700.0 * rad, amplification_factor=5.2)]
    (reading,) = separation_readings(
        NS(operating_speed=4800.0 * rad, operating_range=(4560.0 * rad, 5040.0 * rad)), inside
    )
    assert reading == pytest.approx((4560.0, 4560.0 * (1.0 - 0.12405405405405405), 0.0, 0.12405405405405405), rel=REL)
    at_end = [NS(speed=4800.0 * rad, amplification_factor=5.2)]
    (reading,) = separation_readings(
        NS(operating_speed=4800.0 * rad, operating_range=(4800.0 * rad, 5040.0 * rad)), at_end
    )
    assert reading[2] == 0.0
