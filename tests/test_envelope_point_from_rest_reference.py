"""Envelope points of a design whose own operating point is at rest (0 rev/min, 0 W).

The rules (API contract: the points.py module docstring; no docs page covers a design at rest),
from flexshaft/design/points.py's module docstring (:func:`design_at_point`): "``[operating]``:
the point's ``speed_rpm`` (the main-rotor speed scales with it: the two are geared; at rest it
is dropped) and ``power`` when given" and "with no change it equals the input"; docs/thermal.md's
table of the point keys (hand-written): "`speed_rpm`, `power` | the operating point; omitted:
`[operating]` (the main-rotor speed scales with the shaft's)".

A design at rest gives no gear ratio to scale the main rotor by (its shaft turns at 0 rev/min),
so the reference is what the rules fix without one:

* **A point at the design's own speed and power** (0 rev/min, 0 W) changes nothing: the design
  at the point equals the input, its main-rotor speed of 289 rev/min included (the baseline's
  main rotor, kept as given). "At rest it is dropped" applies to a running design whose point is
  at rest; here the point changes nothing, so the no-change rule governs.
* **A point at a running speed** of 4800 rev/min is a valid design at that speed: Ω = 4800 ·
  2π/60 = 502.65 rad/s (rpm to rad/s by hand) at 0 W (the power is not given: the design's 0 W),
  hence zero torque.

Tolerances: the speed is copied, compared exactly; Ω is one product and one division of
doubles (rel 1e-12). CPU: a few milliseconds (validation only, no model).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from flexshaft.design import baseline_design, design_from_dict
from flexshaft.design.envelope import EnvelopePoint
from flexshaft.design.points import design_at_point

NO_CHANGE = SimpleNamespace(thermal={}, materials={})


def at_rest():
    """The baseline with its operating point at rest: 0 rev/min, 0 W, main rotor 289 rev/min."""
    data = baseline_design().model_dump()
    data["operating"].update(speed_rpm=0.0, speed=None, power=0.0)
    design = design_from_dict(data)
    assert design.operating.main_rotor_speed_rpm == 289.0
    return design


def test_a_point_at_the_designs_own_rest_changes_nothing():
    # "at rest it is dropped" is for a running design's point at rest; this point changes
    # nothing, so "with no change it equals the input" governs (main rotor kept)
    design = at_rest()
    at_point = design_at_point(design, EnvelopePoint(name="parked", speed_rpm=0.0, power=0.0), NO_CHANGE)
    assert at_point.operating.main_rotor_speed_rpm == 289.0
    assert at_point == design


def test_a_running_point_of_a_design_at_rest_is_a_design_at_that_speed():
    at_point = design_at_point(at_rest(), EnvelopePoint(name="run", speed_rpm=4800.0), NO_CHANGE)
    operating = at_point.operating
    assert operating.speed_rpm == 4800.0
    assert operating.speed_rad_s == pytest.approx(4800.0 * 2.0 * math.pi / 60.0, rel=1e-12)
    assert operating.power == 0.0
    assert operating.torque == 0.0
