"""Every interactive figure over speed draws the operating speed where the verdict judges it, in
rpm: the spin-up, actuator and whirl-stability figures as well as the Campbell diagram
(tests/test_interactive_figures_reference.py checks the Campbell's line).

References (derived, by hand): the stand-in assessment of tests/test_interactive_figures_reference.py
(no model, no analysis) with the operating speed Ω = 4800 rpm = 4800·2π/60 = 502.6548 rad/s; its
line on an rpm axis sits at Ω·60/(2π) = 4800, not at 502.65 (the speed left in rad/s), and its
label reads "operating 4800 rpm". The whirl-damping check judges its modes at that speed, so on
the stability figure the line passes through the checked-mode markers (also at 4800 rpm). The
line's position is the operating speed through one multiplication and one division (a few ulp),
so rel=1e-9 is loose enough for any rounding and 10⁸ times tighter than the factor 60/(2π) ≈ 9.55
the check separates. CPU about 0.01 s.
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import pytest
from test_interactive_figures_reference import RPM, _assessment, _trace

from flexshaft.report import interactive
from flexshaft.report.interactive import actuator_figure, spinup_figure, stability_figure

OPERATING_RPM = 4800.0  # the stand-in's operating speed [rpm]


def _operating_line(figure: dict) -> float:
    """The x [rpm] of the figure's operating-speed line, checking its label says the same."""
    (line,) = [s for s in figure["layout"]["shapes"] if s["type"] == "line" and s["line"]["color"] == "#444"]
    assert line["x1"] == line["x0"]
    (note,) = [n for n in figure["layout"]["annotations"] if n["text"].startswith("operating")]
    assert note["x"] == line["x0"]
    assert note["text"] == f"operating {OPERATING_RPM:.0f} rpm"
    return line["x0"]


def test_spinup_figure_operating_line_in_rpm():
    """Spin-up orbits over 1000 to 6000 rpm: the operating line at 4800 rpm, inside the sweep."""
    assert _operating_line(spinup_figure(_assessment())) == pytest.approx(OPERATING_RPM, rel=1e-9)


def test_actuator_figure_operating_line_in_rpm(monkeypatch):
    """Both actuator panels share the x axis in rpm: the operating line at 4800 rpm."""
    monkeypatch.setattr(interactive, "actuator_limits", lambda model: {"amb_1": NS(gap=None, force_capacity=None)})
    assert _operating_line(actuator_figure(_assessment())) == pytest.approx(OPERATING_RPM, rel=1e-9)


def test_stability_figure_operating_line_through_the_checked_modes():
    """A judged mode (25 Hz, log decrement 0.12) is marked at the operating speed 4800 rpm; the
    operating line is at the same 4800 rpm, through the marker."""
    a = _assessment()
    a.evidence = NS(modes_at_operating=[NS(label="1 (forward)", frequency=25.0 * 60.0 * RPM, log_decrement=0.12)])
    figure = stability_figure(a)
    x = _operating_line(figure)
    assert x == pytest.approx(OPERATING_RPM, rel=1e-9)
    assert _trace(figure, "checked at the operating speed")["x"] == [pytest.approx(x, rel=1e-9)]
