"""How ``flexshaft validate`` judges a case (flexshaft.validation.runner), on values set by hand.

A case passes when every computed value lies within the case's relative tolerance of its
published value: |computed/published − 1| <= tolerance for *each* value, so the case is judged by
its worst value, in either direction. The run passes only when every case passes. These tests
feed the runner synthetic values through a stand-in quantity (no design is built, no model is
solved: a few milliseconds of CPU) and check the verdict against that rule, worked by hand:

* one value 0.3 % below its published value among values within 0.02 % fails a 0.1 % tolerance
  (the worst |difference| is 3e-3, not the best 0 or the signed maximum 2e-4);
* a NaN or a value too many cannot be compared and is an error, wherever it sits;
* the display units: 1 Hz = 2π rad/s, 1 rev/min = 2π/60 rad/s, 1 kg m = 10³ g × 10³ mm = 10⁶ g mm
  (SI definitions), so 100π rad/s is 50 Hz and 3000 rev/min exactly;
* one failing case among passing ones fails the run and is the one listed as failed.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from flexshaft.validation import runner
from flexshaft.validation.cases import case_by_id
from flexshaft.validation.runner import CaseResult, ValidationReport, run_case

# a case on plain numbers (no design file): only its published values, unit and tolerance matter here
TEMPLATE = case_by_id("iso21940-balance-tolerance")


def synthetic(published, unit="-", tolerance=1e-3):
    labels = tuple(f"v{i}" for i in range(len(published)))
    return dataclasses.replace(
        TEMPLATE,
        id="synthetic",
        quantity="synthetic",
        published=tuple(published),
        labels=labels,
        unit=unit,
        tolerance=tolerance,
        arguments={},
    )


@pytest.fixture
def computes(monkeypatch):
    """``computes(values)``: the stand-in quantity returns ``values`` (SI) for every case."""

    def set_values(values):
        monkeypatch.setattr(runner, "quantity", lambda name: lambda design, **kwargs: np.asarray(values, dtype=float))

    return set_values


def test_a_case_is_judged_by_its_worst_value_in_either_direction(computes):
    """Published (100, 200, 300), computed (100.02, 199.4, 300): differences +2e-4, −3e-3, 0;
    the worst |difference| is 3e-3 > 1e-3, so the case fails; within 4e-3 it passes."""
    computes([100.02, 199.4, 300.0])
    result = run_case(synthetic((100.0, 200.0, 300.0), tolerance=1e-3))
    assert result.differences == pytest.approx((2e-4, -3e-3, 0.0), abs=1e-13)
    assert result.worst == pytest.approx(3e-3, rel=1e-10)
    assert not result.passed
    assert run_case(synthetic((100.0, 200.0, 300.0), tolerance=4e-3)).passed


def test_values_below_the_published_ones_fail_as_those_above(computes):
    """Computed 0.5 % low and 0.5 % high, tolerance 0.1 %: both fail."""
    for factor in (0.995, 1.005):
        computes([factor * 10.0, factor * 20.0])
        assert not run_case(synthetic((10.0, 20.0), tolerance=1e-3)).passed


@pytest.mark.parametrize("values", [[1.0, math.nan], [math.nan, 1.0], [1.0, math.inf]], ids=["last", "first", "inf"])
def test_a_value_that_is_not_finite_is_an_error_wherever_it_is(computes, values):
    computes(values)
    with pytest.raises(ValueError, match="not finite"):
        run_case(synthetic((1.0, 1.0)))


@pytest.mark.parametrize("values", [[1.0, 1.0, 1.0], [1.0]], ids=["one too many", "one too few"])
def test_a_value_count_other_than_the_published_one_is_an_error(computes, values):
    """Two published values: three computed (a mode too many would shift the pairs) or one
    computed cannot be compared value by value."""
    computes(values)
    with pytest.raises(ValueError, match="values computed, 2 published"):
        run_case(synthetic((1.0, 1.0)))


@pytest.mark.parametrize(
    "unit, si, shown",
    [("Hz", 100.0 * math.pi, 50.0), ("rpm", 100.0 * math.pi, 3000.0), ("g mm", 12.0e-6, 12.0), ("rad/s", 7.0, 7.0)],
)
def test_the_display_units_are_the_si_definitions(computes, unit, si, shown):
    """100π rad/s = 50 Hz = 3000 rev/min; 12e-6 kg m = 12 g mm."""
    computes([si])
    result = run_case(synthetic((shown,), unit=unit, tolerance=1e-12))
    assert result.computed[0] == pytest.approx(shown, rel=1e-14)
    assert result.passed


def test_one_failing_case_fails_the_run(computes):
    """Three cases, the second 1 % off at a 0.1 % tolerance: the run fails, listing that case."""
    computes([1.0])
    good = run_case(synthetic((1.0,)))
    bad = dataclasses.replace(run_case(synthetic((1.01,))), case=dataclasses.replace(synthetic((1.01,)), id="bad"))
    report = ValidationReport((good, bad, good), cpu_seconds=0.0)
    assert not bad.passed and good.passed
    assert report.failed == (bad,)
    assert not report.passed
    assert ValidationReport((good, good), cpu_seconds=0.0).passed


def test_case_result_rule_directly():
    """The rule on a CaseResult: worst = max |d|; passed iff worst <= tolerance (the boundary
    itself passes)."""
    case = synthetic((1.0, 1.0, 1.0), tolerance=2e-3)
    assert CaseResult(case, (1.0, 1.0, 1.0), (-2e-3, 1e-3, 0.0), 0.0).passed
    assert not CaseResult(case, (1.0, 1.0, 1.0), (1e-4, -2.5e-3, 0.0), 0.0).passed
    assert CaseResult(case, (1.0, 1.0, 1.0), (1e-4, -2.5e-3, 0.0), 0.0).worst == 2.5e-3


def test_the_json_worst_difference_is_the_largest_in_magnitude(computes):
    """Published (100, 200, 300), computed (100.02, 199.4, 300): differences +2e-4, −3e-3, 0
    (worked above); the JSON report's worst_relative_difference is max |d| = 3e-3, not the first
    value's +2e-4, and its verdict is the case's (3e-3 > 1e-3: failed)."""
    computes([100.02, 199.4, 300.0])
    report = ValidationReport((run_case(synthetic((100.0, 200.0, 300.0), tolerance=1e-3)),), 0.0)
    (case,) = runner.report_json(report)["cases"]
    assert case["worst_relative_difference"] == pytest.approx(3e-3, rel=1e-10)
    assert case["passed"] is False


@pytest.mark.parametrize(
    ("unit", "published_key", "flexshaft_key"),
    [
        ("-", "published", "flexshaft"),
        ("Hz", "published_Hz", "flexshaft_Hz"),
        ("g mm", "published_g_mm", "flexshaft_g_mm"),
        ("rpm", "published_rpm", "flexshaft_rpm"),
        ("rad/s", "published_rad_per_s", "flexshaft_rad_per_s"),
        ("N/m", "published_N_per_m", "flexshaft_N_per_m"),
    ],
)
def test_the_json_value_keys_carry_the_unit_and_none_without_one(computes, unit, published_key, flexshaft_key):
    """The JSON keys name their unit as every command's do (docs/optimizer.md: "the unit in each
    key: driveline_mass_kg, kp_N_per_m"); a dimensionless value (a Nusselt number, unit "-") has
    no unit to name: "published" and "flexshaft", not "published_" with a dangling underscore.
    A case in rev/min keys its values ``_rpm`` (README.md, ``--json``: "the unit in each key
    (`frequency_Hz`, `wall_thickness_m`, `sigma1_Pa`, `kp_N_per_m`), except rotational speeds in
    rpm (`_rpm`)"; docs/validation.md: "values in each case's unit, in the key"), one in rad/s
    ``_rad_per_s`` and one in N/m ``_N_per_m`` by the same ``_per_`` spelling as ``kp_N_per_m``
    (assumed by analogy: no doc names a rad/s key; the N/m one is the docs' ``kp_N_per_m``).
    The key's unit is the unit of the number under it: 1 SI value of 100π rad/s shown in rpm is
    3000 under ``published_rpm`` and ``flexshaft_rpm`` (1 rev/min = 2π/60 rad/s)."""
    computes([1.0])
    (case,) = runner.report_json(ValidationReport((run_case(synthetic((1.0,), unit=unit)),), 0.0))["cases"]
    (value,) = case["values"]
    assert set(value) == {"label", published_key, flexshaft_key, "relative_difference"}


def test_the_json_rpm_keys_hold_rev_per_min(computes):
    """100π rad/s computed for a case in rpm published as 3000: both numbers sit under ``_rpm``
    keys (README.md's ``--json`` rule quoted above) and are 3000, to round-off (rel 1e-14)."""
    computes([100.0 * math.pi])
    report = ValidationReport((run_case(synthetic((3000.0,), unit="rpm", tolerance=1e-12)),), 0.0)
    (case,) = runner.report_json(report)["cases"]
    (value,) = case["values"]
    assert value["published_rpm"] == 3000.0
    assert value["flexshaft_rpm"] == pytest.approx(3000.0, rel=1e-14)


def test_an_unknown_case_id_is_an_error_not_an_empty_pass():
    """run_validation runs "the cases called case_ids", each found by case_by_id ("The case called
    case_id (ValueError listing the ids otherwise)"): a misspelt id must raise, not leave a report
    of zero cases whose verdict "every case within its tolerance" holds vacuously. The Python API
    has no --case check in front of it (the CLI's). No case is computed: the error comes first."""
    with pytest.raises(ValueError, match="no validation case 'no-such-case'"):
        runner.run_validation(["no-such-case"])
