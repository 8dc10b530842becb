"""What a verdict says when a limit or a result is missing, from the contract of
:mod:`flexshaft.verdict.result` and :mod:`flexshaft.verdict.evidence` (their docstrings):

* an active bearing whose auxiliary-bearing clearance and force capacity are not given (the
  defaults of :class:`~flexshaft.verdict.evidence.ActuatorEvidence`) cannot be judged: its
  excursion and force checks are "not evaluated", never measured against a zero limit;
* :attr:`Check.passed` is None for a check not evaluated (neither passed nor failed), and a
  verdict passes when no check fails.

By hand: one actuator with a 0.1 mm orbit and a 20 N force, no limits given.
"""

from __future__ import annotations

from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.evidence import ActuatorEvidence, Evidence
from flexshaft.verdict.result import Check


def _evidence() -> Evidence:
    amb = ActuatorEvidence(name="amb", peak_orbit=1e-4, orbit_speed=500.0, peak_force=20.0, force_speed=500.0)
    return Evidence(operating_speed=600.0, actuators=(amb,))


def test_an_actuator_without_limits_is_not_judged_against_zero():
    verdict = evaluate(_evidence(), Requirements())
    for key in ("actuator_orbit", "actuator_force"):
        check = verdict.check(key)
        assert check.status == "not evaluated", key
        assert check.passed is None and check.margin is None, key
    assert verdict.passed


def test_a_check_not_evaluated_is_neither_passed_nor_failed():
    args = ("temperature", "shaft temperature", "temperature", "at most")
    assert Check(*args, "not evaluated", note="no shaft thermal result").passed is None
    assert Check(*args, "pass", 300.0, 400.0, 100.0).passed is True
    assert Check(*args, "fail", 500.0, 400.0, -100.0).passed is False
