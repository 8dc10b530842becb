"""The interactive Campbell diagram (``flexshaft run --interactive``, the explorer) shows what the
separation check judges, as the report's diagram does: each of the verdict's critical speeds
with its separation margin and the margin API 684 requires (on hover), and the required margin
as a grey bar on the critical's frequency from the end of the operating speed range its margin
is measured from; nothing of it when ``[requirements] separation = "off"``.

References (derived, by hand; docs/requirements.md, "Separation margin"): the stand-in
assessment of tests/test_interactive_figures_reference.py, operating speed 4800 rpm, range
4320-5280 rpm (0.9-1.1 of it); three verdict criticals, f = n/60 Hz on the 1× line:

* 2400 rpm, AF 6, below: 17 (1 − 1/(6 − 1.5)) = 13.222 %, required min(16, 13.222) = 13.222 %;
  margin from the lowest speed (4320 − 2400)/4320 = 44.44 % (passes); the bar runs from 4320 to
  4320 (1 − 0.13222) = 3748.8 rpm at 40 Hz;
* 6000 rpm, AF 3, above: 17 (1 − 1/1.5) = 5.667 %, required min(26, 10 + 5.667) = 15.667 %;
  margin from the highest speed (6000 − 5280)/5280 = 13.64 % (fails: the bar from 5280 to
  5280 (1.15667) = 6107.2 rpm at 100 Hz holds 6000);
* 5000 rpm, AF 2, inside the range: critically damped (AF < 2.5), required 0, margin 0 (above
  the operating speed: its zero-length bar at the highest speed 5280 rpm, 83.33 Hz).

Figures are JSON data: positions rounded to 6 significant digits (rel 1e-6), the hover's
margins to 4 (rel 1e-3 covers the rounding's 5e-4). Plain data, no plotly: about 0.01 s.
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import pytest
from test_interactive_figures_reference import RPM, _assessment, _trace

from flexshaft.report.interactive import campbell_figure

BARS = "separation API 684 requires"
CRITICALS = [(2400.0, 6.0), (6000.0, 3.0), (5000.0, 2.0)]  # [rpm], AF
BELOW = 17.0 * (1.0 - 1.0 / 4.5) / 100.0  # AF 6, below: 0.13222
ABOVE = 0.10 + 17.0 * (1.0 - 1.0 / 1.5) / 100.0  # AF 3, above: 0.15667
# (from [rpm], to [rpm], at [Hz]) of each bar; (AF, margin, required) on each critical's hover
SEGMENTS = [
    (4320.0, 4320.0 * (1.0 - BELOW), 40.0),
    (5280.0, 5280.0 * (1.0 + ABOVE), 100.0),
    (5280.0, 5280.0, 5000.0 / 60),
]
HOVER = [(6.0, 1920.0 / 4320.0, BELOW), (3.0, 720.0 / 5280.0, ABOVE), (2.0, 0.0, 0.0)]


def _with_criticals(separation: str = "api684") -> NS:
    a = _assessment()
    a.design.requirements.separation = separation
    a.evidence.critical_speeds = [NS(speed=n * RPM, amplification_factor=af) for n, af in CRITICALS]
    return a


def _segments(trace: dict) -> list[tuple[float, float, float]]:
    """The trace's straight segments, separated by nulls: (x0, x1, y) with y0 = y1 checked."""
    out = []
    x, y = trace["x"], trace["y"]
    assert len(x) == len(y) == 3 * len(CRITICALS) and x[2::3] == y[2::3] == [None] * len(CRITICALS)
    for k in range(0, len(x), 3):
        assert y[k] == y[k + 1]  # horizontal: at the critical's frequency
        out.append((x[k], x[k + 1], y[k]))
    return out


def test_each_critical_carries_its_margin_and_the_required_margin():
    marks = _trace(campbell_figure(_with_criticals()), "lateral critical speeds (unbalance peaks)")
    assert marks["x"] == pytest.approx([n for n, _ in CRITICALS], rel=1e-6)
    assert marks["y"] == pytest.approx([n / 60.0 for n, _ in CRITICALS], rel=1e-6)
    for row, expected in zip(marks["customdata"], HOVER):
        assert row == pytest.approx(expected, rel=1e-3, abs=1e-12)
    assert "separation margin %{customdata[1]:.1%} (needs %{customdata[2]:.1%})" in marks["hovertemplate"]


def test_required_margin_bars_run_from_the_range_end_the_margin_is_measured_from():
    figure = campbell_figure(_with_criticals())
    bars = _trace(figure, BARS)
    for got, expected in zip(_segments(bars), SEGMENTS):
        assert got == pytest.approx(expected, rel=1e-6)
    # the failing critical (6000 rpm) lies inside its bar, the passing one (2400) outside its own
    (lo_pass, hi_pass), (lo_fail, hi_fail) = (sorted(s[:2]) for s in _segments(bars)[:2])
    assert not lo_pass <= 2400.0 <= hi_pass and lo_fail <= 6000.0 <= hi_fail
    # drawn first, beneath the modes and the markers
    assert figure["data"][0] is bars


def test_nothing_of_the_check_when_it_is_off():
    figure = campbell_figure(_with_criticals("off"))
    assert BARS not in [t["name"] for t in figure["data"]]
    marks = _trace(figure, "lateral critical speeds (unbalance peaks)")
    assert marks["customdata"] == [[af] for _, af in CRITICALS]
    assert "margin" not in marks["hovertemplate"]


def test_no_critical_speed_draws_no_bar_and_no_marker():
    figure = campbell_figure(_assessment())  # critical_speeds None: no peak found
    names = [t["name"] for t in figure["data"]]
    assert BARS not in names and "lateral critical speeds (unbalance peaks)" not in names
