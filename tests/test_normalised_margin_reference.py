"""One normalised margin compares checks of different kinds (hand-made checks, no analysis run).

:func:`flexshaft.verdict.result.normalised_margin` ranks the checks and points of a verdict (the
governing point, each check's worst point of an envelope), draws the margins figures and feeds
the optimizer and the explorer. References, with binary-exact numbers:

* **temperature**: margin/|limit| is a share of the requirement for a safety factor or an orbit,
  but not for a temperature on the kelvin scale: 11 K below a 100 °C allowable is 3 % of 373 K,
  read as "3 % from failing" although the shaft may heat 11 K more of the 85 K the allowable
  leaves above the ISA standard day (ISO 2533: 15 °C = 288.15 K at sea level). The measure is
  margin / (T_allow − 288.15 K), the same at every point of an envelope, so the hottest shaft is
  both the check's worst point and its tightest share. Here T_allow = 416.15 K (143 °C), a rise
  of 128 K: 32 K below reads 0.25, 64 K 0.5.
* **separation**: each critical speed's finding has its own required separation (API 684 asks
  more of a sharper peak); the check's normalised margin is the smallest of margin/required over
  its findings, not the finding nearest in raw fraction of the speed. A critically damped peak
  (AF < 2.5) requires nothing (limit 0): it cannot approach a limit (+inf), it does not read as
  its raw fraction.
* **runaway**: a check that fails with a non-negative margin (a thermal runaway below the
  allowable keeps its last temperature's margin) reads −1e-300 in the figures and enters the
  optimizer as a violation of its whole limit (−inf margin → :data:`NOT_EVALUATED_VIOLATION`),
  not as a violation of 1e-300, which the search would rank as all but feasible.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

from test_montecarlo_bounds import SMALL  # a 2 m steel tube

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.design.requirements import Requirements
from flexshaft.optimize.evaluate import assessment_metrics
from flexshaft.verdict.checks import temperature
from flexshaft.verdict.envelope import PointAssessment, envelope_verdict, governing_point
from flexshaft.verdict.evidence import Evidence
from flexshaft.verdict.result import Check, Finding, Verdict, normalised_margin

ALLOWABLE = 416.15  # K: 128 K above the 288.15 K standard day


def _temperature(max_temperature: float, runaway: bool = False) -> Check:
    ev = Evidence(
        operating_speed=300.0, max_temperature=max_temperature, allowable_temperature=ALLOWABLE, thermal_runaway=runaway
    )
    return temperature(ev, Requirements())


def test_the_temperature_margin_is_a_share_of_the_allowables_rise_above_the_standard_day():
    check = _temperature(ALLOWABLE - 32.0)
    assert check.margin == 32.0 and check.limit == ALLOWABLE  # the margin stays in kelvin
    assert normalised_margin(check) == 0.25  # 32 K of 128 K, not 32/416.15
    assert normalised_margin(_temperature(ALLOWABLE + 64.0)) == -0.5


def test_a_runaway_fails_below_zero_and_violates_the_optimizers_whole_limit():
    check = _temperature(ALLOWABLE - 32.0, runaway=True)
    assert check.status == "fail" and check.margin == 32.0
    assert normalised_margin(check) == -1e-300
    model = build_model(loads_design(SMALL))  # any model: the metrics read its masses
    assessment = SimpleNamespace(verdict=Verdict((check,)), operating_speed=300.0, model=model)
    margin = assessment_metrics(assessment)["margin_temperature"]
    assert margin == -math.inf


def _separation(findings: list[tuple[float, float]], status: str = "pass") -> Check:
    """findings: (separation, required) fractions of the operating speed; the check's own value is
    the finding with the smallest raw margin, as the verdict's rule takes it."""
    fs = tuple(Finding(value, limit, value - limit) for value, limit in findings)
    worst = min(fs, key=lambda f: f.margin)
    return Check(
        "separation", "separation", "fraction", "at least", status, worst.value, worst.limit, worst.margin, findings=fs
    )


def test_a_separation_is_normalised_by_each_criticals_own_requirement():
    """Critical A 0.0703125 from the speed with 0.0625 required (margin 2⁻⁷ = 0.125 of it);
    critical B 0.171875 from it with 0.15625 required (a sharper peak: margin 2⁻⁶ = 0.1 of it);
    critical C 0.015625 from it, critically damped (nothing required). A is the nearest in raw
    fraction (the check's value); B is the tighter share of its requirement: 0.1. C alone is +inf."""
    check = _separation([(0.0703125, 0.0625), (0.171875, 0.15625), (0.015625, 0.0)])
    assert check.margin == 0.0078125 and check.value == 0.0703125  # A: the raw nearest
    assert normalised_margin(check) == 0.1  # B: 0.015625 / 0.15625
    assert normalised_margin(_separation([(0.015625, 0.0)])) == math.inf  # nothing required, nothing near


def _orbit(value: float) -> Check:
    return Check("actuator_orbit", "actuator excursion", "length", "at most", "pass", value, 4e-4, 4e-4 - value)


def _point(name: str, *checks: Check) -> PointAssessment:
    evidence = Evidence(operating_speed=300.0)
    return PointAssessment(name=name, analyses=None, evidence=evidence, verdict=Verdict(checks))  # type: ignore[arg-type]


def test_the_governing_point_compares_a_temperature_by_its_share_of_the_rise():
    """hot_soak: 32 K below the allowable (0.25 of its rise; 0.077 of 416 K) and an orbit at 1/4
    of its limit (margin 0.75); cold: 128 K below (1.0) and an orbit at 5/8 (margin 0.375). The
    tightest check is hot_soak's temperature (0.25 < 0.375): hot_soak governs. Then the orbit at
    7/8 (0.125) at cold: cold governs, though over kelvin (0.077) the temperature would."""
    hot = _point("hot_soak", _temperature(ALLOWABLE - 32.0), _orbit(1e-4))
    cold = _point("cold", _temperature(ALLOWABLE - 128.0), _orbit(2.5e-4))
    assert governing_point([hot, cold]) == "hot_soak"
    cold = _point("cold", _temperature(ALLOWABLE - 128.0), _orbit(3.5e-4))
    assert governing_point([hot, cold]) == "cold"


def test_an_envelopes_temperature_is_its_hottest_shaft_and_governs_by_it():
    """hot_day: 32 K below (0.25); cold_day: 64 K below (0.5); the orbits 0.375 at both. The
    combined temperature check is the hot day's (the hottest shaft), its normalised margin 0.25 is
    the envelope's tightest, and the hot day governs: the figure's bar, the optimizer's limiting
    check and the governing point agree."""
    hot = _point("hot_day", _temperature(ALLOWABLE - 32.0), _orbit(2.5e-4))
    cold = _point("cold_day", _temperature(ALLOWABLE - 64.0), _orbit(2.5e-4))
    combined = {c.key: c for c in envelope_verdict([cold, hot]).checks}
    assert combined["temperature"].margin == 32.0 and combined["temperature"].location["point"] == "hot_day"
    assert normalised_margin(combined["temperature"]) == 0.25
    assert min(combined.values(), key=normalised_margin).key == "temperature"
    assert governing_point([cold, hot]) == "hot_day"


def test_the_results_file_carries_the_figures_number():
    """results.json's check entry (``Check.to_dict``) gives the normalised margin the figure
    draws: 32 K below the allowable, 0.25 of its rise; ``null`` (strict JSON has no infinity)
    for a critically damped peak's separation, which has nothing to approach."""
    entry = _temperature(ALLOWABLE - 32.0).to_dict()
    assert entry["margin"] == 32.0 and entry["normalised_margin"] == 0.25
    assert _separation([(0.015625, 0.0)]).to_dict()["normalised_margin"] is None
