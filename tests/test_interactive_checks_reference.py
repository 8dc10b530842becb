"""The interactive figures' marks of the verdict's numbers (report/interactive.py) beside those of
tests/test_interactive_figures_reference.py: the critical speeds on the Campbell diagram, the
whirl onset and the judged modes on the stability figure, the actuator panels at the point where
the excursion check governs with each checked peak at its own speed, and a margin with nothing
to measure on the margins chart.

References (derived, by hand) on that file's stand-in assessment: rpm = Ω·60/(2π), Hz = Ω/(2π)
= rpm/60, so a critical speed sits on the 1× line (f = N/60 Hz at N rpm). The margins chart's
rule is the static chart's (plot/verdict.py ``margins_figure``, its docstring's "+inf when it
passed with nothing to measure (a bar to the axis end)"; verdict/result.py ``normalised_margin``
and ``Verdict.plot_margins``: +inf passed with nothing to measure, "to the axis end", NaN not
evaluated): +inf reaches the axis end, not 0 (which reads "at the limit"); NaN draws no bar (0).
Figures are JSON data, rounded to 6 significant digits: rel=1e-6. CPU about 0.01 s.
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import pytest
from test_interactive_figures_reference import RPM, _assessment, _trace

from flexshaft.report import interactive
from flexshaft.report.interactive import actuator_figure, campbell_figure, margins_figure, stability_figure


def test_critical_speeds_sit_on_the_1x_line_in_rpm_and_hz():
    """The verdict's criticals at 2400 and 5400 rpm: (2400, 40 Hz) and (5400, 90 Hz), AF 6 and 3
    (the separation check off: their AF alone on hover; its readings:
    tests/test_interactive_campbell_separation_reference.py)."""
    a = _assessment()
    a.design.requirements.separation = "off"
    a.evidence.critical_speeds = [
        NS(speed=2400.0 * RPM, amplification_factor=6.0),
        NS(speed=5400.0 * RPM, amplification_factor=3.0),
    ]
    marks = _trace(campbell_figure(a), "lateral critical speeds (unbalance peaks)")
    assert marks["x"] == pytest.approx([2400.0, 5400.0], rel=1e-6)
    assert marks["y"] == pytest.approx([40.0, 90.0], rel=1e-6)
    assert marks["customdata"] == [[6.0], [3.0]]


def test_whirl_onset_line_in_rpm_and_judged_modes_in_hz():
    """Onset at Ω = 5500 rpm: the red line at x = 5500; a judged mode of 2π·25 rad/s = 25 Hz,
    log decrement 0.12, marked at the operating speed 4800 rpm."""
    a = _assessment()
    a.stability.onset_speed = 5500.0 * RPM
    a.evidence = NS(modes_at_operating=[NS(label="2 (forward)", frequency=25.0 * 60.0 * RPM, log_decrement=0.12)])
    figure = stability_figure(a)
    (onset,) = [s for s in figure["layout"]["shapes"] if s["type"] == "line" and s["line"]["color"] == "#c62828"]
    assert onset["x0"] == pytest.approx(5500.0, rel=1e-12) and onset["x1"] == onset["x0"]
    judged = _trace(figure, "checked at the operating speed")
    assert judged["x"] == [pytest.approx(4800.0, rel=1e-12)] and judged["y"] == [0.12]
    assert judged["text"] == ["mode 2 (forward), 25.00 Hz"]


def test_actuator_panels_at_the_excursion_checks_point_each_peak_at_its_speed(monkeypatch):
    """The excursion check governs at "hot" (the governing point is "nominal"): the panels show
    hot's spin-up (its orbit 0.1 mm constant, force 10 N) and hot's evidence, the excursion peak
    at 2000 rpm, the force peak at 5000 rpm."""
    monkeypatch.setattr(interactive, "actuator_limits", lambda model: {"amb_1": NS(gap=None, force_capacity=None)})
    a = _assessment()
    nominal = a.point("nominal")
    speeds = nominal.analyses.spinup.speeds
    hot_spin = NS(speeds=speeds, actuator_displacement={"amb_1": [1e-4] * 3}, actuator_force={"amb_1": [10.0] * 3})
    ev = NS(
        name="amb_1",
        static_offset=0.0,
        static_force=0.0,
        orbit_speed=2000.0 * RPM,
        peak_orbit=1e-4,
        force_speed=5000.0 * RPM,
        peak_force=10.0,
    )
    hot = NS(analyses=NS(spinup=hot_spin), evidence=NS(actuators=[ev]))
    a.point = {"nominal": nominal, "hot": hot}.__getitem__
    orbit_check = NS(key="actuator_orbit", location={"point": "hot"})
    a.verdict = NS(checks=[orbit_check], check={"actuator_orbit": orbit_check}.__getitem__)
    figure = actuator_figure(a)
    top, bottom = [t for t in figure["data"] if t["name"] == "amb_1: static + spin-up"]
    assert top["y"] == pytest.approx([0.1] * 3, rel=1e-6) and bottom["y"] == pytest.approx([10.0] * 3, rel=1e-6)
    orbit, force = [t for t in figure["data"] if t["name"] == "amb_1: checked peak"]
    assert (orbit["yaxis"], force["yaxis"]) == ("y", "y2")
    assert orbit["x"] == pytest.approx([2000.0], rel=1e-6) and force["x"] == pytest.approx([5000.0], rel=1e-6)


def test_a_margin_with_nothing_to_measure_reaches_the_axis_end(monkeypatch):
    """Three checks: passed with no margin (+inf) → a bar to the x axis's end (beyond the finite
    0.5); margin 0.75 against a limit 1.5 → 0.5; not evaluated (NaN) → no bar, 0."""

    def check(title, status, margin, limit):
        return NS(title=title, status=status, margin=margin, limit=limit, findings=[], scale=None)

    checks = [
        check("no critical", "pass", None, None),
        check("strength", "pass", 0.75, 1.5),
        check("loops", "not evaluated", None, None),
    ]
    monkeypatch.setattr(interactive, "verdict_rows", lambda verdict, compact: [["t", "v", "l", "m", "s", ""]] * 3)
    figure = margins_figure(NS(verdict=NS(checks=checks, passed=True)))
    (bars,) = figure["data"]
    axis_end = figure["layout"]["xaxis"]["range"][1]
    assert bars["x"][0] == axis_end and bars["x"][0] > 0.5
    assert bars["x"][1:] == [0.5, 0.0]
