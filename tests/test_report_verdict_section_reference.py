"""The report's verdict section says the verdict's PASS/FAIL and names the checks that fail,
those and no others (:func:`flexshaft.report.verdict.verdict_section`, rendered to HTML).

References:

* docs/requirements.md, "The checks": "The overall verdict passes when no check fails;
  `--strict` fails only on failed checks." — so a design whose checks pass or could not be
  evaluated reads "PASS".
* The section's own lead ``Verdict: PASS|FAIL.`` and its sentence "Failed, worst case of
  each: ..." (the failed checks, each with its location); the summary it quotes
  (:attr:`Verdict.summary` docstring): "PASS/FAIL, the failed requirements and the count not
  evaluated".

Hand-built checks, by hand:

* ``strength`` "at least": value 1.5, limit 1.0, margin 0.5 → pass;
* ``shaft temperature`` "at most": value 500 K, limit 400 K, margin −100 K → fail;
* ``spin-up deflection``: not evaluated (no limit given).

With all three: FAIL, the failed list is "shaft temperature" alone. Without the failing one:
PASS (nothing fails; the check not evaluated does not fail), no "Failed" sentence. The
paragraphs are read back from the rendered HTML's <p> elements (escaped text, unescaped
here). Strings only, CPU about 0.1 s.
"""

from __future__ import annotations

import html
import re

from flexshaft.report.html import render_report
from flexshaft.report.verdict import verdict_section
from flexshaft.verdict.result import Check, Verdict

STRENGTH = Check("strength", "strength", "ratio", "at least", "pass", 1.5, 1.0, 0.5)
TEMPERATURE = Check(
    "temperature", "shaft temperature", "temperature", "at most", "fail", 500.0, 400.0, -100.0, {"station": 1.0}
)
DEFLECTION = Check("spinup_deflection", "spin-up deflection", "length", "at most", "not evaluated", note="no limit")


def _paragraphs(verdict: Verdict) -> list[str]:
    page = render_report("t", [verdict_section(verdict, 4800.0)], design_name="t")
    return [html.unescape(re.sub(r"<[^>]+>", "", p)) for p in re.findall(r"<p>(.*?)</p>", page, re.S)]


def _section_text(verdict: Verdict) -> list[str]:
    paragraphs = _paragraphs(verdict)
    start = next(i for i, p in enumerate(paragraphs) if p.startswith("Verdict: "))
    return paragraphs[start:]


def test_no_failed_check_reads_pass_even_with_one_not_evaluated() -> None:
    text = _section_text(Verdict((STRENGTH, DEFLECTION)))
    assert text[0].startswith("Verdict: PASS."), text[0]
    assert not any(p.startswith("Failed") for p in text)


def test_a_failing_design_names_its_failed_check_and_only_it() -> None:
    text = _section_text(Verdict((STRENGTH, TEMPERATURE, DEFLECTION)))
    lead = text[0]
    assert lead.startswith("Verdict: FAIL."), lead
    assert "shaft temperature" in lead  # the summary's failed requirements, in the lead
    failed = [p for p in text if p.startswith("Failed, worst case of each: ")]
    assert len(failed) == 1
    listed = failed[0].removeprefix("Failed, worst case of each: ")
    assert listed.startswith("shaft temperature (")
    assert "strength" not in listed and "spin-up deflection" not in listed, listed
