"""The verdict line of ``interactive.html`` names the failing checks only.

Reference: README.md, "the checks that fail" are ``a.verdict.failed`` ("a.verdict.passed,
a.verdict.failed # the checks that fail: value, limit, margin [SI], location"), and its
terminal headline names only them ("2 of 13 checks fail: whirl onset speed (3125 rpm; ...)");
docs/requirements.md:91-93, every check has "a status (`pass`, `fail` or `not evaluated`)", and
:123-124, "The overall verdict passes when no check fails; `--strict` fails only on failed
checks.": a not-evaluated check is not a failed one. docs/explorer.md: the page holds "the
verdict table" of the run. A stand-in assessment with three checks (one passes, one fails at
actuator amb_1, one not evaluated): the line after "Verdict: FAIL" holds the failing check's
title and neither other title. The location written after the title, "(amb_1)", is an API
contract (the page's format: the title, then :func:`flexshaft.verdict.text.location_text` of
the check's location in brackets, that docstring's ``amb_1`` for an actuator; no docs page
states it). Text only: no tolerance.
"""

from __future__ import annotations

import re
from types import SimpleNamespace

import pytest

import flexshaft.report.interactive_page as ip
from flexshaft.verdict.result import Check, Verdict


def _stand_in() -> SimpleNamespace:
    checks = (
        Check("shaft_strength", "shaft strength", "ratio", "at least", "pass", 2.0, 1.5, 0.5),
        Check(
            "actuator_orbit",
            "actuator excursion",
            "length",
            "at most",
            "fail",
            6.0e-4,
            5.0e-4,
            -1.0e-4,
            {"actuator": "amb_1"},
        ),
        Check("temperature", "matrix temperature", "temperature", "at most", "not evaluated", note="no thermal"),
    )
    return SimpleNamespace(
        verdict=Verdict(checks), design=SimpleNamespace(name="stand-in"), resolution=SimpleNamespace(name="report")
    )


def test_verdict_line_names_only_the_failing_check(monkeypatch: pytest.MonkeyPatch) -> None:
    """One of three checks fails: the verdict paragraph reads FAIL and names 'actuator
    excursion' only (the documented rule), written 'actuator excursion (amb_1)' (an API
    contract: see the module docstring); the table still lists all three checks (one row each)."""
    monkeypatch.setattr(ip, "assessment_figures", lambda a: {})
    page = ip.interactive_page(_stand_in(), plotly_js="")  # type: ignore[arg-type]
    line = re.search(r"<p>Verdict: <b>(\w+)</b>(.*?)</p>", page, re.S)
    assert line is not None
    assert line.group(1) == "FAIL"
    text = line.group(2)
    assert "actuator excursion" in text
    assert "actuator excursion (amb_1)" in text  # API contract: the location format
    assert "shaft strength" not in text
    assert "matrix temperature" not in text
    assert len(re.findall(r"<tr class=", page)) == 3
