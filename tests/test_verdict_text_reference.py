"""The verdict and envelope text (the report's verdict table, the terminal's verdict line and
table) against hand conversions of known SI values.

References (derived, unit definitions): 1 rpm = 2π/60 rad/s, 1 Hz = 2π rad/s, 1 kW = 1e3 W;
the margin is value − limit for an "at least" check (docs: the report's verdict paragraph). The
checks are built with the SI values of round engineering numbers (3125 rpm, 55.32 Hz), so the
text must print those numbers back; every comparison is of formatted strings, exact.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

from flexshaft.design.loads import Operating
from flexshaft.verdict.envelope_text import envelope_rows
from flexshaft.verdict.result import Check, Verdict
from flexshaft.verdict.text import location_text, verdict_headline, verdict_rows

RPM = 2.0 * math.pi / 60.0  # rad/s per rpm
HZ = 2.0 * math.pi  # rad/s per Hz


def _speed_check(key: str, value_rpm: float, limit_rpm: float, **location) -> Check:
    value, limit = value_rpm * RPM, limit_rpm * RPM
    return Check(
        key=key,
        title=key.replace("_", " "),
        kind="speed",
        sense="at least",
        status="pass" if value >= limit else "fail",
        value=value,
        limit=limit,
        margin=value - limit,
        location=location,
    )


def _skipped(key: str) -> Check:
    return Check(key=key, title=key, kind="speed", sense="at least", status="not evaluated")


def test_location_speed_in_rpm_and_frequency_in_hz():
    """4084 rpm = 427.68 rad/s and 55.32 Hz = 347.59 rad/s print as 4084 rpm and 55.32 Hz."""
    text = location_text({"mode": 6, "speed": 4084.0 * RPM, "frequency": 55.32 * HZ})
    assert text == "mode 6, 4084 rpm, 55.32 Hz"


def test_verdict_row_value_limit_and_margin_columns():
    """An onset at 3125 rpm against ≥ 5520 rpm: value 3125 rpm, limit ≥ 5520 rpm, margin
    3125 − 5520 = −2395 rpm (negative: failed)."""
    verdict = Verdict(checks=(_speed_check("whirl_onset", 3125.0, 5520.0, speed=3125.0 * RPM),))
    (row,) = verdict_rows(verdict)
    assert row[1:5] == ["3125 rpm", "≥ 5520 rpm", "-2395 rpm", "FAIL"]
    assert row[5] == "3125 rpm"


def test_headline_counts_failures_and_passes():
    """Three checks, one failing (3125 < 5520 rpm): "1 of 3 checks fail"; two passing and one
    not evaluated: "2 of 3 checks pass"."""
    failing = Verdict(
        checks=(
            _speed_check("whirl_onset", 3125.0, 5520.0),
            _speed_check("a", 6000.0, 5520.0),
            _speed_check("b", 7000.0, 5520.0),
        )
    )
    assert verdict_headline(failing).startswith(
        "FAIL — 1 of 3 checks fail: whirl onset (3125 rpm; required ≥ 5520 rpm)"
    )
    skipped = Verdict(checks=(_speed_check("a", 6000.0, 5520.0), _speed_check("b", 7000.0, 5520.0), _skipped("c")))
    assert verdict_headline(skipped) == "PASS — 2 of 3 checks pass; 1 not evaluated: c"


def _point(name: str, verdict: Verdict, ambient_c: float, material_c: float, power_w: float):
    conditions = SimpleNamespace(
        ambient_temperature_c=ambient_c, material_temperature_c=material_c, point=SimpleNamespace(load_scale=1.25)
    )
    design = SimpleNamespace(operating=Operating(speed_rpm=4800.0, power=power_w))  # the schema's own
    return SimpleNamespace(name=name, verdict=verdict, analyses=SimpleNamespace(design=design, conditions=conditions))


def test_envelope_row_conditions_and_failure_count():
    """A point at 35 °C ambient, 61.5 °C shaft, 4800 rpm, 450 kW (450e3 W / 1e3), load scale 1.25,
    failing one check of three: "FAIL 1/3"."""
    verdict = Verdict(
        checks=(
            _speed_check("whirl_onset", 3125.0, 5520.0),
            _speed_check("a", 6000.0, 5520.0),
            _speed_check("b", 7000.0, 5520.0),
        )
    )
    point = _point("hot", verdict, 35.0, 61.5, 450.0e3)
    assessment = SimpleNamespace(design=SimpleNamespace(envelope=object()), points=[point], governing_point="hot")
    (row,) = envelope_rows(assessment)
    assert row[:7] == ["hot (governs)", "35.0", "61.5", "4800", "450.0", "1.25", "FAIL 1/3"]
