"""The sources of a validation report, in the order the cases first cite them.

Rule (``ValidationReport.sources``' docstring): "the keys of the sources the cases cite, in order
of first use"; ``flexshaft validate`` prints one citation line per source in that order under
its table, so the citations follow the table's cases. Worked by hand for three results whose
cases cite gibert, friswell2010, gibert, cengel (none of them in alphabetical order): each key
once, at its first appearance, gives (gibert, friswell2010, cengel). No quantity is computed:
the results are built directly, so only the bookkeeping is tested.
"""

from __future__ import annotations

from flexshaft.validation.cases import case_by_id
from flexshaft.validation.runner import CaseResult, ValidationReport


def result(case_id: str) -> CaseResult:
    case = case_by_id(case_id)
    values = tuple(case.published)
    return CaseResult(case, values, tuple(0.0 for _ in values), 0.0)


def test_sources_are_listed_once_in_order_of_first_use():
    ids = ("gibert-spinning-rod", "friswell-9.7.1-torsion", "gibert-spinning-rod", "cengel-7-53-crossflow")
    report = ValidationReport(tuple(result(i) for i in ids), cpu_seconds=0.0)
    assert [r.case.source for r in report.results] == ["gibert", "friswell2010", "gibert", "cengel"]
    assert report.sources == ("gibert", "friswell2010", "cengel")
