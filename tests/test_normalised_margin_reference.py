"""The temperature check's normalised margin is a share of the rise the allowable leaves above the
point's ambient, and the governing point follows it (hand-made checks, no analysis run).

:func:`flexshaft.verdict.result.normalised_margin` is the one measure by which checks of
different kinds are compared: the governing point, the margins figures, the optimizer and the
explorer. margin/|limit| is a share of the requirement for a safety factor, an orbit or a
separation, but not for a temperature on the kelvin scale: 11 K below a 100 °C allowable is 3 %
of 373 K, read as "3 % from failing" although the shaft may heat 11 K more, a fifth of the 50 K
the allowable leaves above a 50 °C day. The reference is that reading: margin / (T_allow −
T_ambient), with binary-exact numbers (350 K against 400 K on a 300 K day: 50/100 = 0.5).

Within one check the worst point is the one nearest its limit in the check's own unit: the
hottest shaft against the allowable, whatever each point's ambient (tests below: 40 K of margin
on a hot day is worse than 50 K on a cold one, though the hot day's share of its rise is larger).
"""

from __future__ import annotations

from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import temperature
from flexshaft.verdict.envelope import PointAssessment, envelope_verdict, governing_point
from flexshaft.verdict.evidence import Evidence
from flexshaft.verdict.result import Check, Verdict, normalised_margin


def _temperature(max_temperature: float, ambient: float | None, allowable: float = 400.0, runaway: bool = False):
    ev = Evidence(
        operating_speed=300.0,
        max_temperature=max_temperature,
        allowable_temperature=allowable,
        ambient_temperature=ambient,
        thermal_runaway=runaway,
    )
    return temperature(ev, Requirements())


def test_the_temperature_margin_is_a_share_of_the_rise_above_ambient():
    check = _temperature(350.0, ambient=300.0)
    assert check.margin == 50.0 and check.limit == 400.0  # the margin stays in kelvin
    assert normalised_margin(check) == 0.5  # 50 K of the 100 K the allowable leaves


def test_without_an_ambient_or_above_the_allowable_the_limit_scales():
    assert normalised_margin(_temperature(350.0, ambient=None)) == 0.125  # 50/400
    assert normalised_margin(_temperature(350.0, ambient=400.0)) == 0.125  # no rise left: |limit|
    assert normalised_margin(_temperature(450.0, ambient=300.0)) == -0.5  # 50 K over a 100 K rise


def test_a_runaway_fails_below_zero_with_its_scale():
    check = _temperature(350.0, ambient=300.0, runaway=True)
    assert check.status == "fail" and check.scale == 100.0
    assert normalised_margin(check) == -1e-300


def _orbit(value: float) -> Check:
    return Check("actuator_orbit", "actuator excursion", "length", "at most", "pass", value, 4e-4, 4e-4 - value)


def _point(name: str, temperature_check: Check, orbit: Check) -> PointAssessment:
    evidence = Evidence(operating_speed=300.0)
    return PointAssessment(name=name, analyses=None, evidence=evidence, verdict=Verdict((temperature_check, orbit)))  # type: ignore[arg-type]


def test_the_governing_point_compares_a_temperature_by_its_rise():
    """hot_soak: 50 K below 400 K on a 300 K day (0.5 of its rise; 0.125 of 400 K) and an orbit
    at 1/4 of its limit (margin 0.75); cold: 140 K below (1.4) and an orbit at 3/4 (margin 0.25).
    The tightest check is cold's orbit (0.25 < 0.5): cold governs. Over kelvin (50/400 = 0.125)
    the soak's temperature would have governed."""
    hot = _point("hot_soak", _temperature(350.0, ambient=300.0), _orbit(1e-4))
    cold = _point("cold", _temperature(260.0, ambient=300.0), _orbit(3e-4))
    assert governing_point([hot, cold]) == "cold"


def test_a_checks_worst_point_is_the_hottest_shaft_whatever_its_ambient():
    """hot_day: 360 K on a 340 K day (40 K below 400 K: 2/3 of its 60 K rise); cold_day: 350 K
    on a 250 K day (50 K below: 1/3 of 150 K). The temperature check's worst point is the hot
    day's 360 K, the nearer to the allowable."""
    hot = _point("hot_day", _temperature(360.0, ambient=340.0), _orbit(1e-4))
    cold = _point("cold_day", _temperature(350.0, ambient=250.0), _orbit(1e-4))
    combined = {c.key: c for c in envelope_verdict([cold, hot]).checks}["temperature"]
    assert combined.value == 360.0 and combined.location["point"] == "hot_day"
