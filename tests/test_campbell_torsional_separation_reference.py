"""The Campbell diagram draws the torsional separation check's reading (plot/campbell.py,
report/driveline.py's ``torsional_readings``).

The check (docs/requirements.md, ``torsional_separation``): every torsional natural frequency
f_n at least r from its nearest excitation, the margin |f_n − f_e|/f_e, over the operating
speed range. An excitation geared to the shaft runs at f_e = k·N/60 [Hz] at N rpm (k its order
on the shaft speed). Derived here: the margin is below r exactly while
f_n/(1 + r) < f_e < f_n/(1 − r), i.e. at the speeds 60·f_n/(k(1 + r)) < N < 60·f_n/(k(1 − r));
the excitation crosses the mode (f_e = f_n) at N = 60·f_n/k. With f_n = 8 Hz, k = 0.12 and
r = 0.10: the band 3636.36… to 4444.44… rpm, the crossing at 4000 rpm. At the band's upper
end the margin is (f_e − f_n)/f_e = 1 − (1 − r) = r: a range starting there just passes.

Before, the Campbell diagram drew the excitation rays but not the requirement: the tuned
design's torsional mode T1 (8.0 Hz, 12.7 % from the main rotor's 2/rev, 10 % required) showed
no bar. Drawn coordinates are doubles after a product and a division: rel 1e-12.
"""

from __future__ import annotations

import math
from types import SimpleNamespace as NS

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from flexshaft.plot.campbell import campbell_figure  # noqa: E402
from flexshaft.report.driveline import torsional_readings  # noqa: E402

SPEEDS = np.array([0.0, 3000.0, 6000.0])
FREQS = np.array([[8.0, 30.0], [8.0, 30.0], [8.0, 30.0]])
WHIRL = np.array([["none", "planar"]] * 3)


def _figure(torsional, **kwargs):
    return campbell_figure(SPEEDS, FREQS, WHIRL, torsional=torsional, **kwargs)


def _brown(ax):
    """The torsional bar (a brown line) and its crossing (a brown-edged diamond)."""
    return [ln for ln in ax.get_lines() if "tab:brown" in (ln.get_color(), ln.get_markeredgecolor())]


def test_torsional_bar_spans_the_speeds_where_the_margin_is_short():
    fig = _figure([(8.0, 0.12, 0.127, 0.10, "T1 × main rotor 2/rev")])
    ax = fig.axes[0]
    bar, crossing = _brown(ax)
    np.testing.assert_allclose(bar.get_xdata(), [60 * 8.0 / (0.12 * 1.1), 60 * 8.0 / (0.12 * 0.9)], rtol=1e-12)
    np.testing.assert_allclose(bar.get_ydata(), [8.0, 8.0], rtol=1e-12)
    assert crossing.get_marker() == "D"
    np.testing.assert_allclose([crossing.get_xdata()[0], crossing.get_ydata()[0]], [4000.0, 8.0], rtol=1e-12)
    # at the bar's upper end the check's own margin |f_n − f_e|/f_e is exactly r
    f_e = 0.12 * bar.get_xdata()[1] / 60.0
    assert abs(8.0 - f_e) / f_e == pytest.approx(0.10, rel=1e-12)
    legend = fig.legends[0]
    assert "required torsional separation" in [t.get_text() for t in legend.get_texts()]


def test_a_band_beyond_the_speeds_drawn_is_left_out():
    """A mode at 140 Hz from a 1.17× excitation has its band from 60·140/(1.17·1.1) = 6527 rpm
    on, past the 6000 rpm drawn: no bar, no crossing (drawn, they only grew the canvas). One at
    30 Hz: the band 60·30/(1.17·1.1) = 1398.6 to 60·30/(1.17·0.9) = 1709.4 rpm, drawn."""
    ax = _figure([(140.0, 1.17, 0.45, 0.10, "T2 × tail rotor 4/rev")]).axes[0]
    assert _brown(ax) == []
    ax = _figure([(30.0, 1.17, 0.45, 0.10, "T2 × tail rotor 4/rev")]).axes[0]
    bar, _ = _brown(ax)
    np.testing.assert_allclose(bar.get_xdata(), [60 * 30.0 / (1.17 * 1.1), 60 * 30.0 / (1.17 * 0.9)], rtol=1e-12)


def test_with_the_lateral_bars_one_legend_entry_holds_both():
    """A verdict critical with its API 684 bar and a torsional bar: one legend entry for the two
    kinds of required separation (a 20th entry re-balances the legend's columns and widens it
    past the figure)."""
    fig = _figure(
        [(8.0, 0.12, 0.127, 0.10, "T1")],
        operating_rpm=4800.0,
        response_criticals=[(1800.0, 10.0)],
        separation=[(4560.0, 3900.0, 0.6, 0.16)],
    )
    texts = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "required separation (API 684; torsional)" in texts
    assert "required separation (API 684)" not in texts and "required torsional separation" not in texts


def test_readings_from_the_checks_evidence():
    """Evidence of T1 at 2π·8 rad/s whose nearest excitation spans k·Ω over the operating range
    (4560, 5040) rpm with k = 0.12: the reading is (8 Hz, k, its margin, r, "T1 × its name")."""
    low, high = (2 * math.pi * n / 60 for n in (4560.0, 5040.0))
    mode = NS(
        label="T1",
        frequency=2 * math.pi * 8.0,
        margin=0.127,
        excitation="main rotor 2/rev",
        band=(0.12 * low, 0.12 * high),
    )
    evidence = NS(torsional_modes=(mode,), operating_range=(low, high), operating_speed=2 * math.pi * 80.0)
    ((f_n, order, margin, required, name),) = torsional_readings(evidence, 0.10)
    assert f_n == pytest.approx(8.0, rel=1e-12) and order == pytest.approx(0.12, rel=1e-12)
    assert (margin, required, name) == (0.127, 0.10, "T1 × main rotor 2/rev")
    # one operating speed: the band is one frequency, the order is it over that speed
    single = NS(
        torsional_modes=(NS(**{**vars(mode), "band": (0.12 * low,) * 2}),), operating_range=None, operating_speed=low
    )
    assert torsional_readings(single, 0.10)[0][1] == pytest.approx(0.12, rel=1e-12)
    assert torsional_readings(NS(torsional_modes=None, operating_range=None, operating_speed=low), 0.1) == []
