"""The run report's speed-dependent tables and captions (report/driveline.py) are the governing
point's, and its "at rest" modes table holds the modes at rest.

References (documented rules and unit definitions, by hand):

* docs/requirements.md: "The assessment's own analyses (the report's figures, ``results.json``'s
  numbers) are those of the **governing point**". An envelope point spinning at 6600 rpm
  governs a design whose own speed is 6000 rpm: the modes at speed, the Campbell diagram's
  operating line and its 125 % band, and the summary's sentence naming the point are at
  6600 rpm (1.25 × 6600 = 8250 rpm), while the design's own 6000 rpm heads the summary.
* The "Natural frequencies at rest" table lists the modes at 0 rpm (docs/requirements.md lists
  "modes at rest" among what only the report shows). At rest the gyroscopic matrix vanishes, so
  a Jeffcott-like pair is degenerate (50 Hz twice); at speed it splits (here 45 Hz backward,
  55 Hz forward). rpm = 60·f: 50 Hz is 3000 rpm.

On the stand-in assessment of tests/test_run_report_pages_reference.py (sections other modules
write stubbed; figures only recorded as jobs). CPU about 0.01 s.
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import pytest
from test_run_report_pages_reference import DATA, _assessment, _rad_s

from flexshaft.report import driveline
from flexshaft.report.html import Section

AT_REST = NS(rows=[(1, 50.0, "backward"), (2, 50.0, "forward")])
AT_SPEED = NS(rows=[(1, 45.0, "backward"), (2, 55.0, "forward")])


def _rows(modes):
    """A modes table's rows (analyses.summary.modes_table's keys) of one stand-in Modes."""
    return [
        {
            "mode": n,
            "frequency_Hz": f,
            "frequency_rpm": 60.0 * f,
            "damping_ratio": 0.01,
            "whirl": whirl,
            "component": "shaft",
        }
        for n, f, whirl in modes.rows
    ]


def _plan(monkeypatch, a, tmp_path):
    monkeypatch.setattr(driveline, "results_json", lambda a, thesis: DATA)
    for name in ("verdict_section", "inputs_section", "imbalance_section", "stability_section"):
        monkeypatch.setattr(driveline, name, lambda *args, title=name, **kwargs: Section(title))
    monkeypatch.setattr(driveline, "report_title", lambda design: design.name)
    monkeypatch.setattr(driveline, "modes_table", _rows)
    monkeypatch.setattr(driveline, "torsional_excitations", lambda design: [])
    return driveline.plan_run_report(a, tmp_path, design_text="")


def _modes_section(plan):
    (section,) = [s for s in plan.sections if s.title == "Natural frequencies and Campbell diagram"]
    return section


def test_at_rest_table_holds_the_modes_at_rest(monkeypatch, tmp_path):
    """At rest the pair is degenerate, 50 Hz = 3000 rpm twice; at speed it splits to 45 / 55 Hz
    (2700 / 3300 rpm). Each table carries its own modes (exact products of decimals by 60)."""
    a = _assessment()
    a.modes_at_rest, a.modes_at_speed = AT_REST, AT_SPEED
    rest, speed = _modes_section(_plan(monkeypatch, a, tmp_path)).tables[:2]
    assert rest.caption == "Natural frequencies at rest"
    assert [row[1:3] for row in rest.rows] == [[50.0, 3000.0], [50.0, 3000.0]]
    assert speed.caption == "Natural frequencies at 6000 rpm"
    assert [row[1:3] for row in speed.rows] == [[45.0, 2700.0], [55.0, 3300.0]]


def test_speeds_of_the_analyses_are_the_governing_points(monkeypatch, tmp_path):
    """The governing point "hot_day" spins at 6600 rpm; the design's own speed is 6000 rpm. The
    modes-at-speed caption, the Campbell job's operating line (6600 rpm) and its band
    (1.25 × 6600 = 8250 rpm), and the summary's point sentence give 6600 rpm; the summary's head
    gives the design's 6000 rpm. rad/s → rpm of 2π·N/60 is N to rounding (rel 1e-12)."""
    a = _assessment(points=("cold_day", "hot_day"))
    a.model.speed = _rad_s(6600.0)
    a.modes_at_speed = AT_SPEED
    a.evidence = NS(critical_speeds=(), operating_speed=_rad_s(6600.0), operating_range=None, torsional_modes=())
    plan = _plan(monkeypatch, a, tmp_path)
    (at_speed,) = _modes_section(plan).tables[:1]
    assert at_speed.caption == "Natural frequencies at 6600 rpm"
    (campbell,) = [j for j in plan.jobs if j.stem == "campbell"]
    assert campbell.kwargs["operating_rpm"] == pytest.approx(6600.0, rel=1e-12)
    assert campbell.kwargs["max_critical_rpm"] == pytest.approx(8250.0, rel=1e-12)
    (summary,) = [s for s in plan.sections if s.title == "Design summary"]
    (paragraph,) = summary.paragraphs
    assert "6000 rpm, 150 kW." in paragraph
    assert paragraph.endswith("The analyses below are at the governing point, hot_day: 6600 rpm, 150 kW.")
