"""A failing check never shows a positive relative margin (mutation hunt h33c).

:func:`flexshaft.verdict.result.normalised_margin` is the margins figure's measure, margin/|limit|,
read as "how far inside the requirement" (positive) or "how far outside" (negative). A check can
fail with a margin that is not negative: the temperature check of a thermal runaway (no
self-heating equilibrium below the allowable temperature) keeps the largest temperature computed
and its margin to the allowable, which may be positive, yet the check fails
(:func:`flexshaft.verdict.checks.temperature`). Its relative margin must then be below zero, so
that no figure or ranking shows a failed requirement as met; it is the smallest negative number
the rule writes (−1e-300), not the positive normalised margin (0.5 here). The numbers are
binary-exact: 64 K below a 416.15 K allowable, whose rise above the 288.15 K standard day (the
temperature's scale) is 128 K: 64/128 = 0.5.

A check that fails with a negative margin keeps its own relative margin (−64/128 = −0.5), and a
passing one its positive one (no floor applies).
"""

from __future__ import annotations

from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import temperature
from flexshaft.verdict.evidence import Evidence
from flexshaft.verdict.result import normalised_margin as relative_margin

ALLOWABLE = 416.15  # K: 128 K above the standard day


def _check(max_temperature: float, runaway: bool):
    ev = Evidence(
        operating_speed=300.0, max_temperature=max_temperature, allowable_temperature=ALLOWABLE, thermal_runaway=runaway
    )
    return temperature(ev, Requirements())


def test_a_runaway_below_the_allowable_fails_with_a_negative_relative_margin():
    check = _check(ALLOWABLE - 64.0, runaway=True)
    assert check.status == "fail" and check.margin == 64.0  # the reference: fails, margin positive
    r = relative_margin(check)
    assert r < 0.0
    assert r == -1e-300


def test_other_checks_keep_margin_over_limit():
    hot = _check(ALLOWABLE + 64.0, runaway=False)
    assert hot.status == "fail" and relative_margin(hot) == -0.5
    cool = _check(ALLOWABLE - 64.0, runaway=False)
    assert cool.status == "pass" and relative_margin(cool) == 0.5
