"""Each case's own verdict in the validation outputs (JSON report and docs/validation.md's table).

The rule (flexshaft.validation.runner's module docstring; docs/validation.md: "The command exits 0
when every case lies within its tolerance and 3 ... when one does not", and its "Results": "the
differences (flexshaft / published − 1) to 0.001 %"): a case passes when every one of *its* values
lies within *its* relative tolerance, |computed/published − 1| <= tolerance; the run passes when
every case does. So in a run where one case fails, the outputs that list the cases one by one
(``report_json``'s ``cases[i]["passed"]`` and the "result" column of
:func:`~flexshaft.validation.runner.markdown`) must single that case out and still show the others
as passing, while the run's own verdict is the failure.

The values are set by hand through a stand-in quantity (no design is built): every case computes
1.0; the published values 1.0, 1.01, 1.0002 with a 0.1 % tolerance give the differences
0, 1/1.01 − 1 = −0.990 % (outside) and 1/1.0002 − 1 = −0.020 % (inside). The verdicts are
far from the boundary (factors 10 and 5), so round-off cannot move them.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from flexshaft.validation import runner
from flexshaft.validation.cases import case_by_id
from flexshaft.validation.runner import ValidationReport, run_case

# a case on plain numbers (no design file): only its id, published values and tolerance matter here
TEMPLATE = case_by_id("iso21940-balance-tolerance")


def synthetic(case_id: str, published: float):
    return dataclasses.replace(
        TEMPLATE,
        id=case_id,
        quantity="synthetic",
        published=(published,),
        labels=("v",),
        unit="-",
        tolerance=1e-3,
        arguments={},
    )


@pytest.fixture
def mixed_report(monkeypatch) -> ValidationReport:
    """Three cases computing 1.0: "first" (published 1.0, passes), "off" (1.01, fails),
    "last" (1.0002, passes)."""
    monkeypatch.setattr(runner, "quantity", lambda name: lambda design, **kwargs: np.asarray([1.0]))
    cases = (synthetic("first", 1.0), synthetic("off", 1.01), synthetic("last", 1.0002))
    return ValidationReport(tuple(run_case(c) for c in cases), cpu_seconds=0.0)


def test_the_hand_worked_differences_and_verdicts(mixed_report):
    """Differences 0, −0.990 %, −0.020 % (worked in the module docstring) against 0.1 %."""
    differences = [r.differences[0] for r in mixed_report.results]
    assert differences == pytest.approx([0.0, 1.0 / 1.01 - 1.0, 1.0 / 1.0002 - 1.0], rel=1e-12, abs=1e-15)
    assert [r.passed for r in mixed_report.results] == [True, False, True]
    assert not mixed_report.passed


def test_the_json_verdict_of_each_case_is_its_own(mixed_report):
    """cases[i]["passed"] is case i's verdict (True, False, True), not the run's (False); the run's
    verdict and the count of failures are False and 1."""
    data = runner.report_json(mixed_report)
    assert [(c["id"], c["passed"]) for c in data["cases"]] == [("first", True), ("off", False), ("last", True)]
    assert data["passed"] is False
    assert data["n_failed"] == 1


def test_the_markdown_result_column_marks_only_the_failing_case(mixed_report):
    """The last column of each case's first row reads "pass", "**FAIL**", "pass"; the tolerance
    column reads 1e-3 as "0.1 %" and the failing and last cases' differences, rounded by hand to
    0.001 % (docs/validation.md, "Results"), read "-0.990 %" and "-0.020 %"."""
    table = runner.markdown(mixed_report).split("\n### Cases")[0]
    rows = [line for line in table.splitlines() if line.startswith("| [`")]
    verdicts = {row.split("`")[1]: row.rstrip(" |").rsplit("| ", 1)[1] for row in rows}
    cells = [[cell.strip() for cell in row.strip("| ").split("|")] for row in rows]
    assert [c[-2] for c in cells] == ["0.1 %"] * 3
    assert [c[-3] for c in cells[1:]] == ["-0.990 %", "-0.020 %"]
    assert verdicts == {"first": "pass", "off": "**FAIL**", "last": "pass"}
