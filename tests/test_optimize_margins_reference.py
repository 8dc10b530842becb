"""The optimizer's numbers from a verdict, against hand-made checks (no analysis is run).

* :func:`~flexshaft.verdict.result.normalised_margin` (its docstring's definition, the one
  measure the verdict, its figures, the explorer and the optimizer share): margin/|limit| for
  every kind (a speed's and a separation's too), margin over the allowed rise above ambient for
  the temperature. A design exactly at a limit has margin 0, a design 10 % above a limit of 2
  has 0.1 (not 1.1: the margin, not the value, is divided). A check passed with nothing to
  measure (no critical speed) is +inf, one not evaluated NaN.
* :func:`assessment_metrics`: each objective read from its own check (the actuator force from
  the force check in N, not the orbit check in m); the strength safety factor is the smaller of
  the ply and the metal check's; a check the verdict does not list is "not applicable" (code −2)
  with a NaN margin; the shaft's mass is ρ π (D² − d²)/4 L by hand.
* :meth:`DesignProblem.base_values` seeds the search with the base design only when every value
  lies inside its variable's bounds (the baseline's 3 mm wall against [1, 2] mm and [1, 4] mm).
* :class:`DesignVariable` (its docstring): an integer variable (a ply count) rounds to the
  nearest integer, and a decoded value never leaves [lower, upper], with or without rounding
  to significant digits.
* :func:`default_variables` (its docstring): an active bearing's station within ±1 m of its own
  and at least 0.3 m from its neighbours. The baseline's amb_2 moved to 7.4 m, 0.65 m below the
  aft hanger at 8.05 m: [max(6.4, 3.21 + 0.3), min(8.4, 8.05 − 0.3)] = [6.4, 7.75] m by hand.

A verdict is built from :class:`~flexshaft.verdict.result.Check` objects whose numbers are chosen
here; the model is the two-bay rotor of tests/test_montecarlo_bounds.py (built once, a few ms).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest
from test_montecarlo_bounds import SMALL  # a 2 m steel tube, D 50 mm, wall 5 mm, density 7850

from flexshaft.assembly import build_model
from flexshaft.design import baseline_design, loads_design, with_overrides
from flexshaft.optimize import DesignProblem, DesignVariable, default_variables
from flexshaft.optimize.evaluate import CHECK_KEYS, assessment_metrics
from flexshaft.verdict.result import Check, Verdict, normalised_margin

OMEGA = 300.0  # operating speed [rad/s]


def _check(key, kind, sense, value, limit, status="pass"):
    margin = None if value is None else (value - limit if sense == "at least" else limit - value)
    return Check(key, key, kind, sense, status, value=value, limit=limit, margin=margin)


def test_a_speed_margin_is_a_fraction_of_its_limit():
    """Whirl onset at 360 rad/s against a limit of 330 rad/s: margin 30 rad/s = 30/330 of it."""
    onset = _check("whirl_onset", "speed", "at least", 360.0, 330.0)
    assert normalised_margin(onset) == pytest.approx(30.0 / 330.0, rel=1e-15)


def test_a_ratio_margin_is_the_margin_over_the_limit_zero_at_the_limit():
    """Safety factor 2.2 against 2.0: (2.2 − 2.0)/2.0 = 0.1; exactly at the limit: 0; a
    separation of 0.05 of Ω_op against a required 0.15 fails by 0.10/0.15 = 2/3 of its limit."""
    assert normalised_margin(_check("tsai_wu", "ratio", "at least", 2.2, 2.0)) == pytest.approx(0.1, rel=1e-12)
    assert normalised_margin(_check("tsai_wu", "ratio", "at least", 2.0, 2.0)) == 0.0
    orbit = _check("actuator_orbit", "length", "at most", 3e-4, 4e-4)
    assert normalised_margin(orbit) == pytest.approx(0.25, rel=1e-12)
    separation = _check("separation", "fraction", "at least", 0.05, 0.15, status="fail")
    assert normalised_margin(separation) == pytest.approx(-0.10 / 0.15, rel=1e-12)


def test_passed_without_a_number_is_unbounded_and_not_evaluated_is_nan():
    nothing = Check("separation", "separation", "fraction", "at least", "pass", limit=0.15)
    assert normalised_margin(nothing) == math.inf
    missing = Check("whirl_onset", "onset", "speed", "at least", "not evaluated", limit=330.0)
    assert math.isnan(normalised_margin(missing))


@pytest.fixture(scope="module")
def metrics():
    """A verdict of chosen values on the two-bay rotor: ply SF 1.8, metal SF 2.4, force 900 N,
    orbit 2e-4 m, log decrement 0.3, temperature 330 K; no coupling check (no couplings)."""
    checks = (
        _check("tsai_wu", "ratio", "at least", 1.8, 2.0, status="fail"),
        _check("metal_strength", "ratio", "at least", 2.4, 2.0),
        _check("buckling", "ratio", "at least", 5.0, 3.0),
        _check("whirl_damping", "log_decrement", "at least", 0.3, 0.1),
        _check("actuator_orbit", "length", "at most", 2e-4, 4e-4),
        _check("actuator_force", "force", "at most", 900.0, 1000.0),
        _check("temperature", "temperature", "at most", 330.0, 380.0),
    )
    assessment = SimpleNamespace(verdict=Verdict(checks), operating_speed=OMEGA, model=build_model(loads_design(SMALL)))
    return assessment_metrics(assessment)


def test_each_objective_reads_its_own_check(metrics):
    assert metrics["safety_factor"] == 1.8  # min(1.8 ply, 2.4 metal)
    assert metrics["buckling_safety_factor"] == 5.0
    assert metrics["actuator_force"] == 900.0
    assert metrics["actuator_orbit"] == 2e-4
    assert metrics["min_log_decrement"] == 0.3
    assert metrics["max_temperature"] == 330.0
    assert math.isnan(metrics["spinup_deflection"])  # not listed
    assert metrics["shaft_mass"] == pytest.approx(7850.0 * math.pi / 4 * (0.05**2 - 0.04**2) * 2.0, rel=1e-12)


def test_the_strength_objective_is_the_weaker_of_ply_and_metal():
    """The docstring's rule, min(ply, metal), with the metal the weaker (1.3 against 1.8) and with
    no ply check at all (an all-metal driveline: the metal's 1.3 alone)."""
    model = build_model(loads_design(SMALL))
    ply = _check("tsai_wu", "ratio", "at least", 1.8, 1.5)
    metal = _check("metal_strength", "ratio", "at least", 1.3, 1.5, status="fail")
    for checks in ((ply, metal), (metal,)):
        assessment = SimpleNamespace(verdict=Verdict(checks), operating_speed=OMEGA, model=model)
        assert assessment_metrics(assessment)["safety_factor"] == 1.3


def test_margins_and_status_codes_of_every_check(metrics):
    """tsai_wu fails by 0.2/2.0; the force passes by 100/1000; coupling_angle is not listed:
    not applicable (−2), margin NaN."""
    assert metrics["margin_tsai_wu"] == pytest.approx(-0.1, rel=1e-12)
    assert metrics["status_tsai_wu"] == 0.0
    assert metrics["margin_actuator_force"] == pytest.approx(0.1, rel=1e-12)
    assert metrics["status_actuator_force"] == 1.0
    assert math.isnan(metrics["margin_coupling_angle"]) and metrics["status_coupling_angle"] == -2.0
    assert {f"margin_{k}" for k in CHECK_KEYS} <= set(metrics)


def test_the_base_design_seeds_the_search_only_inside_the_bounds():
    """The baseline's wall is 3 mm: inside [1, 4] mm it is read back, above [1, 2] mm not."""
    assert DesignProblem((DesignVariable("shaft.wall_thickness", 0.001, 0.004),)).base_values() == {
        "shaft_wall_thickness": 0.003
    }
    assert DesignProblem((DesignVariable("shaft.wall_thickness", 0.001, 0.002),)).base_values() is None
    assert DesignProblem((DesignVariable("shaft.wall_thickness", 0.0035, 0.004),)).base_values() is None
    assert baseline_design().shaft.wall_thickness == 0.003


def test_an_integer_variable_rounds_and_no_value_leaves_its_bounds():
    plies = DesignVariable("layup.n", 1, 4, integer=True)
    assert [plies.decode(x) for x in (2.6, 2.4, 5.2, 0.2)] == [3, 2, 4, 1]
    exact = DesignVariable("shaft.wall_thickness", 0.001, 0.004, significant_digits=None)
    assert exact.decode(0.005) == 0.004 and exact.decode(0.0005) == 0.001
    assert exact.decode(0.0023456789) == 0.0023456789


def test_an_actuator_near_the_aft_hanger_stays_0_3_m_below_it():
    design = with_overrides(baseline_design(), {"bearings[2].x": 7.4})
    found = {v.name: v for v in default_variables(design)[0]}
    assert (found["amb_2_x"].lower, found["amb_2_x"].upper) == pytest.approx((6.4, 7.75), abs=1e-12)
    assert (found["amb_1_x"].lower, found["amb_1_x"].upper) == pytest.approx((2.21, 4.21), abs=1e-12)
