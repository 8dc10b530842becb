"""Reference: the report's detail is computed at the governing point (hunt h40a).

:func:`flexshaft.verdict.assess.combine_points` at a resolution with ``report_detail`` adds the
report's detail (modes at rest, the strength's leave-one-out, …) to ONE point, the governing
one, and the assessment shows that point's analyses. The tuned design's four envelope points
are given Tsai-Wu factors 3.0, 1.8, 2.5, 4.0 against the 1.5 limit (docs/requirements.md): the
governing point, by hand, is the one of the smallest margin / limit, (1.8 − 1.5)/1.5 = 0.2, the
second, ``standard_day``; the first (``cold_day``, margin / limit (3.0 − 1.5)/1.5 = 1.0) must
not be the one detailed. The
analyses themselves are stand-ins that carry their point's name in ``notes`` (no step of the
combining reads them), and the detail step appends "detail" to what it is given.
"""

from __future__ import annotations

import dataclasses
from dataclasses import MISSING, fields

import flexshaft.verdict.assess as module
from flexshaft.design import tuned_design
from flexshaft.resolution import REPORT
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.envelope import PointAssessment
from flexshaft.verdict.evidence import Evidence
from flexshaft.verdict.operating_point import PointAnalyses


def test_the_report_detail_is_added_at_the_governing_point(monkeypatch):
    design = tuned_design()
    names = [p.name for p in design.envelope.points]
    assert names == ["cold_day", "standard_day", "hot_day", "hot_soak_start"]
    blank = {f.name: None for f in fields(PointAnalyses) if f.default is MISSING}
    evidence = {
        name: Evidence(operating_speed=500.0, safety_factor=factor, safety_factor_location={"station": 1.0})
        for name, factor in zip(names, (3.0, 1.8, 2.5, 4.0))
    }
    detailed = []

    def detail(analyses):
        detailed.append(analyses.notes[0])
        return dataclasses.replace(analyses, notes=(*analyses.notes, "detail"))

    monkeypatch.setattr(module, "add_report_detail", detail)
    monkeypatch.setattr(module, "gather_evidence", lambda analyses: evidence[analyses.notes[0]])
    judged = []
    for name in names:
        analyses = PointAnalyses(**{**blank, "design": design, "notes": (name,)})
        verdict = evaluate(evidence[name], design.requirements)
        judged.append(PointAssessment(name=name, analyses=analyses, evidence=evidence[name], verdict=verdict))
    a = module.combine_points(design, judged, REPORT)
    assert detailed == ["standard_day"]
    assert a.governing_point == "standard_day" and a.notes == ("standard_day", "detail")
    assert a.point("standard_day").analyses.notes == ("standard_day", "detail")
    assert a.point("cold_day").analyses.notes == ("cold_day",)
    assert a.evidence.safety_factor == 1.8 and a.verdict.check("tsai_wu").value == 1.8
