"""What the verdict's one-line readers and its table say (hand-made checks, no analysis run).

References, documented rules quoted from hand-written docs:

* docs/requirements.md: "The overall verdict passes when no check fails", and in "The
  operating envelope" a check "is not evaluated when it could be evaluated nowhere";
  docs/optimizer.md, of the checks a driveline cannot have: "(they are "not evaluated" in the
  verdict of such a driveline, not failed)".
  So a design with one failing check is FAIL, and one whose checks pass but one not evaluated is
  PASS, in every place that states the verdict (here the data set's ``verdict`` attribute).
* README.md, "Output": the verdict line names the failing checks, "`verdict: FAIL — 2 of 13 checks
  fail: whirl onset speed (3125 rpm; required ≥ 5520 rpm), …`": only those that fail.
* docs/requirements.md, the whirl_onset row: "with no onset up to the highest speed analysed,
  that speed as a lower bound"; docs/magnetic-bearings.md's table writes such an onset
  "> 7200 rpm". A lower bound printed without its ">" would state the onset itself.
* docs/requirements.md, "The operating envelope": the check's location "names the point,
  `[cold_day]` in the tables" (the terminal's table is the compact one).

Numbers: round engineering values in SI (1 rpm = 2π/60 rad/s) printed back; comparisons are of
formatted strings, exact.
"""

from __future__ import annotations

import dataclasses

from test_verdict_text_reference import _speed_check

from flexshaft.verdict.result import Check, Verdict
from flexshaft.verdict.text import location_text, verdict_headline, verdict_rows


def _onset(value_rpm: float, limit_rpm: float, lower_bound: bool = False, key: str = "whirl_onset") -> Check:
    """The sibling test's speed check, a lower bound when ``lower_bound``."""
    return dataclasses.replace(_speed_check(key, value_rpm, limit_rpm), lower_bound=lower_bound)


def _skipped(key: str) -> Check:
    return Check(key=key, title=key, kind="length", sense="at most", status="not evaluated", note="no limit given")


def test_the_data_sets_verdict_is_fail_with_a_failing_check_and_pass_with_one_not_evaluated():
    """3125 rpm < 5520 rpm fails (every check evaluated): FAIL. 6000 rpm ≥ 5520 rpm with the
    spin-up orbit not evaluated: PASS."""
    failing = Verdict((_onset(3125.0, 5520.0), _onset(6000.0, 5520.0, key="other")))
    assert failing.to_dataset().attrs["verdict"] == "FAIL"
    skipped = Verdict((_onset(6000.0, 5520.0), _skipped("spinup_deflection")))
    assert skipped.to_dataset().attrs["verdict"] == "PASS"


def test_the_headline_names_only_the_failing_checks():
    """One check of three fails (3125 < 5520 rpm); the two that pass (6000 and 7000 rpm ≥ 5520)
    are not named after "fail:"."""
    verdict = Verdict(
        (_onset(3125.0, 5520.0), _onset(6000.0, 5520.0, key="other_a"), _onset(7000.0, 5520.0, key="other_b"))
    )
    assert verdict_headline(verdict) == "FAIL — 1 of 3 checks fail: whirl onset (3125 rpm; required ≥ 5520 rpm)"


def test_a_lower_bound_is_printed_as_one_in_the_table():
    """No onset up to 7200 rpm against ≥ 5520 rpm: value "> 7200 rpm", margin at least 7200 − 5520
    = 1680 rpm, "> +1680 rpm" (margins carry their sign), in the full and in the compact (terminal) table."""
    verdict = Verdict((_onset(7200.0, 5520.0, lower_bound=True),))
    for compact in (False, True):
        (row,) = verdict_rows(verdict, compact=compact)
        assert row[1:5] == ["> 7200 rpm", "≥ 5520 rpm", "> +1680 rpm", "PASS"]


def test_the_compact_location_keeps_the_envelope_point():
    """The worst point of an envelope's check, [cold_day], stays in the terminal's location text,
    which leaves out only the free-text detail."""
    location = {"point": "cold_day", "actuator": "amb_1", "detail": "static + imbalance"}
    assert location_text(location, compact=True) == "[cold_day], amb_1"
    assert location_text(location) == "[cold_day], amb_1, static + imbalance"
