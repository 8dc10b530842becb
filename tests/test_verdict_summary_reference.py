"""What a verdict tells its reader, on hand-built checks whose answers are counted by hand
(:mod:`flexshaft.verdict.result`, :mod:`flexshaft.verdict.evidence`).

Four checks, by hand:

* ``strength`` "at least": value 1.5, limit 1.0, margin = value − limit = 0.5 → pass;
* ``temperature`` "at most": value 500 K, limit 400 K, margin = limit − value = −100 K → fail;
* ``separation``: not evaluated (no margin);
* ``loop_gain``: passed with nothing to measure (no margin).

So the summary counts 1 failed, 2 passed (strength and the loop), 1 not evaluated: 2 pass,
not 3 (a check not evaluated is not a pass). The margins chart shows each margin over
its limit: 0.5 / 1.0 = 0.5 and −100 / 400 = −0.25 (the module's contract: "margin divided by its
limit"), NaN for the check not evaluated, +inf for a pass with no finite margin. The dataset's
margin column holds the signed margins 0.5, −100, NaN, NaN.

An evidence with a shaft temperature but no allowable (the default of
:class:`~flexshaft.verdict.evidence.Evidence`) cannot be judged: "not evaluated", never against
a made-up limit. Exact values (no arithmetic beyond one division). CPU: about 0.2 s (xarray's
import for the dataset).
"""

from __future__ import annotations

import math

import numpy as np

import flexshaft.verdict.result as result
from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.evidence import Evidence
from flexshaft.verdict.result import Check, Verdict


def _verdict() -> Verdict:
    return Verdict(
        (
            Check("strength", "strength", "ratio", "at least", "pass", 1.5, 1.0, 0.5),
            Check("temperature", "shaft temperature", "temperature", "at most", "fail", 500.0, 400.0, -100.0),
            Check("separation", "separation", "fraction", "at least", "not evaluated", note="no response"),
            Check("loop_gain", "gain margin", "decibel", "at least", "pass", None, 6.0, None),
        )
    )


def test_the_summary_counts_what_passed_failed_and_was_not_evaluated():
    verdict = _verdict()
    assert not verdict.passed
    assert [c.key for c in verdict.failed] == ["temperature"]
    assert verdict.summary == ("FAIL: 1 of 4 requirements fail: shaft temperature; 2 pass; 1 not evaluated: separation")


def test_the_margins_chart_shows_each_margin_over_its_limit(monkeypatch):
    seen = {}

    def record(titles, normalised, statuses, labels, bounds, ax=None, **kwargs):
        seen.update(titles=titles, normalised=normalised, statuses=statuses)

    monkeypatch.setattr(result, "margins_figure", record)
    _verdict().plot_margins()
    a, b, c, d = seen["normalised"]
    assert a == 0.5 and b == -0.25
    assert math.isnan(c) and d == math.inf
    assert seen["statuses"] == ["pass", "fail", "not evaluated", "pass"]


def test_the_dataset_holds_the_signed_margins():
    ds = _verdict().to_dataset()
    np.testing.assert_array_equal(ds["margin"].values, [0.5, -100.0, np.nan, np.nan])
    np.testing.assert_array_equal(ds["limit"].values, [1.0, 400.0, np.nan, 6.0])


def test_a_temperature_without_an_allowable_is_not_judged():
    check = evaluate(Evidence(operating_speed=600.0, max_temperature=350.0), Requirements()).check("temperature")
    assert check.status == "not evaluated" and check.margin is None and check.limit is None
