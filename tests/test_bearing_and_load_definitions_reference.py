"""Definitions a design file is held to before any analysis: a controller's leading
coefficient, a point load's station, and a controller's static gain as a support stiffness.

References, from the documentation and worked by hand:

* **Controller.** docs/design-reference.md and :class:`flexshaft.design.bearings.Controller`:
  the denominator's *leading* coefficient (highest power first) must be non-zero. An integrating
  law C(s) = (2e6 s + 1e4)/s, denominator [1, 0], has a zero constant term and is a valid
  proper law (the PID keys produce the same form, over ``s``); a denominator [0, 1] has no
  leading term and is refused.
* **Point load.** docs/design-reference.md, ``[[loads.point]]`` ``x``: "Station [m] on the boom
  or shaft; omitted for on = "end_mass"": a load on the boom or the shaft without ``x`` is
  refused, naming ``x``.
* **Static gain as a support.** :mod:`flexshaft.assembly.checks`' docstring: "The law's static
  gain counts as a support stiffness", refused above 1e8 times one shaft element's bending
  stiffness E I/h³. On the two-bay rotor of tests/test_montecarlo_bounds.py (steel E = 210 GPa,
  tube 50 × 40 mm, 2 m in 6 elements): I = π(0.05⁴ − 0.04⁴)/64 = 1.8113e-7 m⁴, h = 1/3 m,
  E I/h³ = 1.0271e6 N/m, limit 1.03e14 N/m. A law C(s) = 1e90/(s + 1e-250) has every
  coefficient within the schema's ±1e100, but C(0) = 1e340 overflows to inf: far above the
  limit, so refused as a support, naming the controller's static gain.
"""

from __future__ import annotations

import math

import pytest
from test_montecarlo_bounds import SMALL

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, loads_design
from flexshaft.design.bearings import Controller
from flexshaft.design.loads import PointLoad


def test_an_integrating_controller_is_proper_and_a_zero_leading_term_is_not():
    law = Controller(numerator=(2.0e6, 1.0e4), denominator=(1.0, 0.0))
    assert law.denominator == (1.0, 0.0) and law.numerator_degree == 1
    with pytest.raises(ValueError, match="leading coefficient"):
        Controller(numerator=(1.0,), denominator=(0.0, 1.0))


@pytest.mark.parametrize("on", ["boom", "shaft"])
def test_a_point_load_on_a_member_needs_its_station(on):
    with pytest.raises(ValueError, match="the station"):
        PointLoad(name="p", on=on, force=(0.0, -100.0, 0.0))
    assert PointLoad(name="p", on=on, x=0.5, force=(0.0, -100.0, 0.0)).x == 0.5
    assert PointLoad(name="p", on="end_mass", force=(0.0, -100.0, 0.0)).x is None


def test_an_overflowing_static_gain_is_refused_as_a_support():
    inertia = math.pi * (0.05**4 - 0.04**4) / 64.0
    limit = 1e8 * 210e9 * inertia / (2.0 / 6.0) ** 3
    assert limit == pytest.approx(1.0271e14, rel=1e-4)
    text = SMALL.replace("kp = 2e6\nkd = 200.0\n", "controller = { numerator = [1e90], denominator = [1.0, 1e-250] }\n")
    with pytest.raises(DesignError) as refused:
        build_model(loads_design(text))
    (problem,) = refused.value.problems
    assert problem.path == "bearings[1].controller"
    assert "static gain of C(s)" in problem.message and f"at most {limit:.3g} N/m" in problem.message


def test_an_overflowing_static_gain_with_an_integrator_is_refused_as_a_support():
    """The same overflow behind an integrator: C(s) = 1e90 (s + 1)/(s (s + 1e-250)). The law's
    frequency check finds nothing wrong at s = iω ≠ 0 (finite there), so only the support rule
    (k_i C(0) ≤ 1e8 E I/h³, the checks module's docstring) refuses it: a design accepted with
    an infinite support stiffness would be solved with an overflowed matrix."""
    limit = 1e8 * 210e9 * (math.pi * (0.05**4 - 0.04**4) / 64.0) / (2.0 / 6.0) ** 3
    law = "controller = { numerator = [1e90, 1e90], denominator = [1.0, 1e-250, 0.0] }\n"
    with pytest.raises(DesignError) as refused:
        build_model(loads_design(SMALL.replace("kp = 2e6\nkd = 200.0\n", law)))
    (problem,) = refused.value.problems
    assert problem.path == "bearings[1].controller"
    assert "static gain of C(s)" in problem.message and f"at most {limit:.3g} N/m" in problem.message
