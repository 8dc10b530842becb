"""What the verdict's text says about where a finding is, which checks were not evaluated, and an
envelope point's tightest check when it is a lower bound (hand-made checks, no analysis run).

References, documented rules quoted from hand-written docs and module docstrings:

* src/flexshaft/verdict/evidence.py (module docstring): "Locations are small mappings with SI
  values (``station`` [m], ...)"; src/flexshaft/verdict/text.py converts "to engineering units
  here, at the edge" and prints a station as ``x = ... m``. A station at 1.25 m reads
  ``x = 1.25 m``.
* docs/requirements.md, "The checks": every check has "a status (`pass`, `fail` or
  `not evaluated`)"; "A requirement that cannot be evaluated says why instead of passing"; "The
  overall verdict passes when no check fails". A check not evaluated is shown as such in the
  table's status column, neither PASS nor FAIL.
* src/flexshaft/verdict/text.py, ``verdict_headline``: "The verdict in one line: ``FAIL — 2 of 9
  checks fail: …`` or ``PASS — 9 checks pass``, and the checks not evaluated." The list of checks
  not evaluated follows either verdict, a failing one too.
* docs/requirements.md, the whirl_onset row: "with no onset up to the highest speed analysed,
  that speed as a lower bound"; docs/magnetic-bearings.md's table writes such an onset
  "> 7200 rpm". The envelope table's "tightest check" column and the envelope line
  (docs/requirements.md: "governed by cold_day (its tightest check)") print the same value, so a
  lower bound keeps its ">".

Numbers: round engineering values in SI (1 rpm = 2π/60 rad/s) printed back; comparisons are of
formatted strings, exact.
"""

from __future__ import annotations

from types import SimpleNamespace

from test_verdict_table_and_headline_reference import _onset, _skipped
from test_verdict_text_reference import _point

from flexshaft.verdict.envelope_text import envelope_line, envelope_rows
from flexshaft.verdict.result import Verdict
from flexshaft.verdict.text import location_text, verdict_headline, verdict_rows


def test_a_station_prints_in_metres():
    """A finding at the SI station 1.25 m reads "x = 1.25 m" (two decimals, the unit metres)."""
    assert location_text({"station": 1.25}) == "x = 1.25 m"
    assert location_text({"actuator": "amb_1", "station": 0.4}, compact=True) == "amb_1, x = 0.40 m"


def test_a_check_not_evaluated_reads_not_evaluated_in_the_table():
    """One passing check (6000 ≥ 5520 rpm) and one without a limit: the status column reads
    "PASS" and "not evaluated" (not "FAIL": the verdict passes)."""
    verdict = Verdict((_onset(6000.0, 5520.0), _skipped("spinup_deflection")))
    statuses = [row[4] for row in verdict_rows(verdict)]
    assert statuses == ["PASS", "not evaluated"]
    assert [row[4] for row in verdict_rows(verdict, compact=True)] == ["PASS", "not evaluated"]


def test_a_failing_headline_still_names_the_checks_not_evaluated():
    """3125 < 5520 rpm fails, 6000 ≥ 5520 rpm passes, the spin-up orbit is not evaluated: the
    headline names the failure and then "1 not evaluated: spinup_deflection"."""
    verdict = Verdict((_onset(3125.0, 5520.0), _onset(6000.0, 5520.0, key="other"), _skipped("spinup_deflection")))
    assert verdict_headline(verdict) == (
        "FAIL — 1 of 3 checks fail: whirl onset (3125 rpm; required ≥ 5520 rpm); 1 not evaluated: spinup_deflection"
    )


def test_an_envelope_points_tightest_lower_bound_keeps_its_sign():
    """A point whose only evaluated check is an onset above the highest speed analysed (7200 rpm,
    a lower bound) against ≥ 5520 rpm: its tightest check reads "whirl onset > 7200 rpm,
    ≥ 5520 rpm" in the envelope table and in the envelope line."""
    verdict = Verdict((_onset(7200.0, 5520.0, lower_bound=True), _skipped("spinup_deflection")))
    point = _point("hot_soak", verdict, 35.0, 61.5, 450.0e3)
    assessment = SimpleNamespace(
        design=SimpleNamespace(envelope=object()), points=[point], governing_point="hot_soak", point=lambda name: point
    )
    (row,) = envelope_rows(assessment)
    assert row[7] == "whirl onset > 7200 rpm, ≥ 5520 rpm"
    assert "governed by hot_soak (whirl onset > 7200 rpm, ≥ 5520 rpm)" in envelope_line(assessment)
