"""A critical-speed search that found no resonance peak passes the separation check; one that
could not be made leaves it not evaluated.

References (documented rules, docs/requirements.md, quoted):

* "The checks": every check has a status `pass`, `fail` or `not evaluated`; `normalised_margin`
  is null where it is not finite: "passed with nothing to measure, or not evaluated";
* "How flexshaft computes AF", step 1: "130 % is beyond the largest margin API can ask above the
  maximum continuous speed (26 %), so a peak above the scan needs no margin". Here the search
  reached 8000 rpm, 8000/4800 = 1.67 times the operating speed, beyond 1.26: a critical above it
  needs no margin, and there is none below it, so nothing fails and the check passes with no
  finding and no margin;
* "A requirement that cannot be evaluated says why instead of passing": the no-search case says
  why, in the analysis's note.

Read here, not quoted: `not evaluated` is for a missing result (no search), not for a result
with no instance in it (a search that found no peak); the `separation` row judges each lateral
critical speed found, so an empty search has nothing to judge.

The point's analyses are stand-ins written by hand (as in
tests/test_gather_range_and_buckling_reference.py): Ω_op = 4800 rpm, the search reached
8000 rpm and found no peak (an empty tuple), or no search was possible (None, with its note).
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import pytest
from test_gather_range_and_buckling_reference import RPM, criticals_only_point

from flexshaft.design.loads import Operating
from flexshaft.design.requirements import Requirements
from flexshaft.verdict import gather
from flexshaft.verdict.checks import evaluate

OPERATING_POINT = Operating(speed_rpm=4800.0, power=0.0)
# the form of scan_critical_speeds' note when the scan's solve is singular (its exception text after
# the colon, here written by hand in the banded solver's words)
NO_SEARCH = (
    "the unbalance response could not be scanned: dynamic stiffness is singular at ω = 502.655 rad/s, "
    "Ω = 502.655 rad/s (an undamped resonance); add damping or move the frequency"
)


def _point(criticals) -> NS:
    """A point whose only result is the critical-speed search (every other check not evaluated)."""
    return criticals_only_point(criticals, OPERATING_POINT, NO_SEARCH)


def _separation(monkeypatch, criticals):
    monkeypatch.setattr(gather, "_whirl", lambda p: {})  # no stability result: not judged here
    evidence = gather.gather_evidence(_point(criticals))
    return evidence, evaluate(evidence, Requirements()).check("separation")


def test_a_search_without_a_peak_passes_with_nothing_to_measure(monkeypatch):
    """No critical up to 8000 rpm: the evidence holds the empty search and its top, and the
    check passes with no finding and no margin (nothing to measure), saying how far it looked."""
    evidence, check = _separation(monkeypatch, ())
    assert evidence.critical_speeds == ()
    assert evidence.critical_search_max_speed == pytest.approx(8000.0 * RPM, rel=1e-15)
    assert check.status == "pass"
    assert check.findings == () and check.margin is None
    assert "8000 rpm" in check.note


def test_no_search_leaves_the_check_not_evaluated_with_its_reason(monkeypatch):
    """No search (the unbalance response could not be scanned, the note's form in
    flexshaft.analyses.criticals.scan_critical_speeds): not evaluated, the reason from the
    analysis's note."""
    evidence, check = _separation(monkeypatch, None)
    assert evidence.critical_speeds is None
    assert check.status == "not evaluated"
    assert check.note == NO_SEARCH
