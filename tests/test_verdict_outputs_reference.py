"""What a verdict hands its reader (verdict/result.py: the JSON dict, the DataFrame, the
notebook table, the margins chart) and what an actuator check judges (verdict/evidence.py's
defaults), on hand-built checks.

By hand (the module's contract: margin = value − limit for "at least", limit − value for "at
most"; values in SI, speeds in rad/s):

* ``whirl_onset`` "at least": value 700 rad/s, limit 578 rad/s, margin 122 rad/s → pass;
* ``strength`` "at least": value 0.8, limit 1.0, margin −0.2 → fail, so the verdict fails;
* ``separation``: not evaluated (the only one).

An actuator with a spin-up peak of 0.2 mm and 120 N and no static offset or force given is
judged on its peaks alone: 0.2 mm against a 0.5 mm gap (margin 0.3 mm), 120 N against 200 N
(margin 80 N). Evidence without a stability analysis (no highest speed analysed) cannot
judge the whirl onset: "not evaluated", and its note claims no stable range (never "stable up
to 0 rad/s only"). Exact values; CPU
about 0.1 s beyond pandas's import (0.5 s on its own; the suite has it loaded).
"""

from __future__ import annotations

import re

import pytest

import flexshaft.verdict.result as result
from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.evidence import ActuatorEvidence, Evidence
from flexshaft.verdict.result import Check, Verdict


def _failing() -> Verdict:
    return Verdict(
        (
            Check("whirl_onset", "whirl onset speed", "speed", "at least", "pass", 700.0, 578.0, 122.0),
            Check("strength", "ply strength", "ratio", "at least", "fail", 0.8, 1.0, -0.2),
            Check("separation", "separation", "fraction", "at least", "not evaluated", note="no response"),
        )
    )


def test_json_of_a_check_keeps_value_limit_margin_and_si_unit():
    d = _failing().to_dict()["checks"][0]
    assert (d["value"], d["limit"], d["margin"]) == (700.0, 578.0, 122.0)
    assert d["unit"] == "rad/s" and d["status"] == "pass"


def test_dataframe_columns_and_units():
    frame = _failing().to_dataframe()
    assert frame.loc["whirl_onset", "value"] == 700.0 and frame.loc["whirl_onset", "limit"] == 578.0
    assert frame.loc["strength", "value"] == 0.8 and frame.loc["strength", "limit"] == 1.0
    assert frame.loc["whirl_onset", "unit"] == "rad/s"


def test_not_evaluated_lists_only_the_check_without_a_result():
    verdict = _failing()
    assert [c.key for c in verdict.not_evaluated] == ["separation"]
    assert [c.key for c in verdict.failed] == ["strength"]


def _headline_and_status_styles(verdict: Verdict) -> tuple[str, dict[str, str]]:
    html = verdict._repr_html_()
    headline = re.match(r'<p style="([^"]*)">verdict:', html).group(1)
    cells = re.findall(r'<td style="[^"]*?white-space:nowrap;([^"]*)">(PASS|FAIL)</td>', html)
    return headline, {status: style for style, status in cells}


def test_the_notebook_headline_has_the_colour_of_its_outcome():
    """A failing verdict's headline is styled as its FAIL cell; a passing one as a PASS cell."""
    headline, cells = _headline_and_status_styles(_failing())
    assert headline == cells["FAIL"] and headline != cells["PASS"]
    passing = Verdict((_failing().checks[0],))
    headline, cells = _headline_and_status_styles(passing)
    assert headline == cells["PASS"]


def test_the_margins_chart_is_titled_with_the_outcome(monkeypatch):
    seen = {}
    monkeypatch.setattr(result, "margins_figure", lambda *args, ax=None, **kwargs: seen.update(kwargs))
    _failing().plot_margins()
    assert seen["title"].startswith("Requirements verdict: FAIL")
    Verdict((_failing().checks[0],)).plot_margins()
    assert seen["title"].startswith("Requirements verdict: PASS")


def test_an_actuator_without_static_loads_is_judged_on_its_peaks():
    amb = ActuatorEvidence("amb_1", 2.0e-4, 500.0, 120.0, 480.0, gap=5.0e-4, force_capacity=200.0)
    verdict = evaluate(Evidence(operating_speed=600.0, actuators=(amb,)), Requirements())
    orbit, force = verdict.check("actuator_orbit"), verdict.check("actuator_force")
    assert orbit.value == 2.0e-4 and orbit.margin == pytest.approx(3.0e-4, rel=1e-12)
    assert force.value == 120.0 and force.margin == 80.0
    assert orbit.status == force.status == "pass"


def test_no_stability_analysis_leaves_the_onset_unjudged():
    check = evaluate(Evidence(operating_speed=600.0), Requirements()).check("whirl_onset")
    assert check.status == "not evaluated" and check.value is None and check.margin is None
    # its note says no analysis was made; it claims no stable range ("stable up to 0 rad/s only")
    assert "stability" in check.note and "stable up to" not in check.note
