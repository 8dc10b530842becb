"""Reference: what :func:`flexshaft.verdict.assess.combine_points` adds at the governing point.

* **The report's detail** (hunt h40a). At a resolution with ``report_detail`` it adds the
  report's detail (modes at rest, the strength's leave-one-out, …) to ONE point, the governing
  one, and the assessment shows that point's analyses. The tuned design's four envelope points
  are given Tsai-Wu factors 3.0, 1.8, 2.5, 4.0 against the 1.5 limit (docs/requirements.md): the
  governing point, by hand, is the one of the smallest margin / limit, (1.8 − 1.5)/1.5 = 0.2,
  the second, ``standard_day``; the first (``cold_day``, margin / limit (3.0 − 1.5)/1.5 = 1.0)
  must not be the one detailed.
* **The explorer's Campbell diagram** (hunt h62a). docs/explorer.md:53-54: the explorer judges
  a design at the screening grids "plus a Campbell diagram of 25 speeds to draw" (one of its
  "five figures", :56-57), and :119-122: "A design with several ``[envelope]`` points has them
  judged in the workers side by side (...), then one worker combines them into the verdict and
  draws the figures at the governing point (``combine_points``)". At a resolution with
  Campbell speeds and no report detail (the explorer's ``EXPLORE``) it therefore adds the
  Campbell diagram to ONE point, the governing one, and the assessment shows it. Factors 3.0,
  2.5, 1.8, 4.0: the governing point is the third, ``hot_day``, (1.8 − 1.5)/1.5 = 0.2.

The analyses are stand-ins that carry their point's name in ``notes`` (no step of the combining
reads them), and the detail or Campbell step appends "detail" or "campbell" to what it is given.
"""

from __future__ import annotations

import dataclasses
from dataclasses import MISSING, fields

import flexshaft.verdict.assess as module
from flexshaft.design import tuned_design
from flexshaft.explore.compute import EXPLORE
from flexshaft.resolution import REPORT
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.envelope import PointAssessment
from flexshaft.verdict.evidence import Evidence
from flexshaft.verdict.operating_point import PointAnalyses

NAMES = ["cold_day", "standard_day", "hot_day", "hot_soak_start"]


def _judged(monkeypatch, factors):
    """The tuned design and its four points judged on stand-in analyses with these Tsai-Wu factors."""
    design = tuned_design()
    assert [p.name for p in design.envelope.points] == NAMES
    blank = {f.name: None for f in fields(PointAnalyses) if f.default is MISSING}
    evidence = {
        name: Evidence(operating_speed=500.0, safety_factor=factor, safety_factor_location={"station": 1.0})
        for name, factor in zip(NAMES, factors)
    }
    monkeypatch.setattr(module, "gather_evidence", lambda analyses: evidence[analyses.notes[0]])
    judged = []
    for name in NAMES:
        analyses = PointAnalyses(**{**blank, "design": design, "notes": (name,)})
        verdict = evaluate(evidence[name], design.requirements)
        judged.append(PointAssessment(name=name, analyses=analyses, evidence=evidence[name], verdict=verdict))
    return design, judged


def _appending(step: str, calls: list):
    def add(analyses):
        calls.append(analyses.notes[0])
        return dataclasses.replace(analyses, notes=(*analyses.notes, step))

    return add


def test_the_report_detail_is_added_at_the_governing_point(monkeypatch):
    detailed: list[str] = []
    monkeypatch.setattr(module, "add_report_detail", _appending("detail", detailed))
    design, judged = _judged(monkeypatch, (3.0, 1.8, 2.5, 4.0))
    a = module.combine_points(design, judged, REPORT)
    assert detailed == ["standard_day"]
    assert a.governing_point == "standard_day" and a.notes == ("standard_day", "detail")
    assert a.point("standard_day").analyses.notes == ("standard_day", "detail")
    assert a.point("cold_day").analyses.notes == ("cold_day",)
    assert a.evidence.safety_factor == 1.8 and a.verdict.check("tsai_wu").value == 1.8


def test_the_explorers_campbell_diagram_is_added_at_the_governing_point(monkeypatch):
    assert EXPLORE.campbell_speeds >= 2 and not EXPLORE.report_detail  # the branch under test
    drawn: list[str] = []

    def no_detail(analyses):
        raise AssertionError("the explorer's resolution adds no report detail")

    monkeypatch.setattr(module, "add_campbell", _appending("campbell", drawn))
    monkeypatch.setattr(module, "add_report_detail", no_detail)
    design, judged = _judged(monkeypatch, (3.0, 2.5, 1.8, 4.0))
    a = module.combine_points(design, judged, EXPLORE)
    assert drawn == ["hot_day"]
    assert a.governing_point == "hot_day" and a.notes == ("hot_day", "campbell")
    assert a.point("hot_day").analyses.notes == ("hot_day", "campbell")
    assert all(a.point(name).analyses.notes == (name,) for name in NAMES if name != "hot_day")
    assert a.verdict.check("tsai_wu").value == 1.8
