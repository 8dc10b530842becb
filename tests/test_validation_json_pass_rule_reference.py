"""The JSON report of ``flexshaft validate`` states each case's pass rule in the case's own terms.

References (an API contract, a documented rule, and counts worked by hand):

* The pass rule. API contract (docstring of :class:`flexshaft.validation.case_types.Case`,
  ``tolerance``: "Largest accepted relative difference |flexshaft/published − 1| of every
  value.") and the documented rule (docs/validation.md: "The command exits 0 when every case
  lies within its tolerance"): a case passes iff |d| <= tolerance for each of its values,
  d = computed/published − 1, both fractions. The JSON report carries d
  (``relative_difference``) and the tolerance side by side, so a reader of the JSON must be able
  to apply that rule to them and get the report's own verdict. Worked here: published 100,
  computed 100.5 → d = 5e-3; at a tolerance of 1e-3 the case fails (5e-3 > 1e-3), at 1e-2 it
  passes. A tolerance given in per cent (0.1 for 1e-3) would let the failing case pass the rule
  read from the JSON (5e-3 <= 0.1).
* The number of sources behind a run. API contract (docstring of
  :attr:`flexshaft.validation.runner.ValidationReport.sources`: "The keys of the sources the
  cases cite, in order of first use."): three cases citing "iso21940", "cengel", "iso21940"
  cite two sources, not the eleven flexshaft knows; a ``flexshaft validate --case ...`` run on a
  subset must not claim the whole bibliography.

The values are set by hand through a stand-in quantity (no design is built): milliseconds.
The differences are compared at 1e-12 relative: 100.5/100 − 1 is exact to a few ulps.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from flexshaft.validation import runner
from flexshaft.validation.cases import case_by_id
from flexshaft.validation.runner import ValidationReport, run_case

# a case on plain numbers (no design file): only its published value, source and tolerance matter
TEMPLATE = case_by_id("iso21940-balance-tolerance")


def _case(*, published: float, tolerance: float, source: str = "iso21940", case_id: str = "synthetic"):
    return dataclasses.replace(
        TEMPLATE,
        id=case_id,
        source=source,
        quantity="synthetic",
        published=(published,),
        labels=("v",),
        unit="-",
        tolerance=tolerance,
        arguments={},
    )


@pytest.fixture
def computes(monkeypatch):
    """``computes(value)``: the stand-in quantity returns ``value`` for every case."""

    def set_value(value: float):
        monkeypatch.setattr(runner, "quantity", lambda name: lambda design, **kwargs: np.asarray([value]))

    return set_value


@pytest.mark.parametrize(("tolerance", "passes"), [(1e-3, False), (1e-2, True)])
def test_the_json_tolerance_and_difference_give_the_reports_verdict(computes, tolerance, passes):
    """Published 100, computed 100.5: d = 5e-3 (docstring). The JSON's tolerance is the case's
    fraction, and |d| <= tolerance read from the JSON is the JSON's verdict: fail at 1e-3, pass
    at 1e-2."""
    computes(100.5)
    report = ValidationReport((run_case(_case(published=100.0, tolerance=tolerance)),), 0.0)
    (case,) = runner.report_json(report)["cases"]
    (value,) = case["values"]
    assert value["relative_difference"] == pytest.approx(5e-3, rel=1e-12)
    assert case["tolerance"] == pytest.approx(tolerance, rel=1e-12)
    assert case["passed"] is passes
    assert (abs(value["relative_difference"]) <= case["tolerance"]) is passes


def test_the_json_counts_the_sources_the_run_cites(computes):
    """Three cases citing iso21940, cengel, iso21940: two sources (hand count), three cases."""
    computes(100.0)
    cases = (
        _case(published=100.0, tolerance=1e-3, source="iso21940", case_id="a"),
        _case(published=100.0, tolerance=1e-3, source="cengel", case_id="b"),
        _case(published=100.0, tolerance=1e-3, source="iso21940", case_id="c"),
    )
    data = runner.report_json(ValidationReport(tuple(run_case(c) for c in cases), 0.0))
    assert data["n_cases"] == 3
    assert data["n_sources"] == 2
