"""An envelope point that gives only a speed keeps the design's power: the torque is P/Ω at it.

docs/thermal.md (the envelope's points: "``speed_rpm``, ``power`` … omitted: ``[operating]`` (the
main-rotor speed scales with the shaft's)"), as :class:`~flexshaft.design.envelope.EnvelopePoint`'s
attributes state it: ``speed_rpm`` omitted takes the ``[operating]`` speed, ``power`` omitted
takes the ``[operating]`` power, and the main-rotor speed scales with the shaft speed (the two are
geared). The reference is that
rule applied by hand to the baseline design (4800 rev/min, 246 kW, main rotor 289 rev/min) at
an overspeed point of 5280 rev/min (110 %) that gives no power:

* the power stays 246 kW (not 246 kW × 1.1 as a constant-torque reading would give);
* the transmitted torque is therefore T = P/Ω = 246 000 / (5280 · 2π/60) N m, 1/1.1 of the
  design's own 246 000 / (4800 · 2π/60) N m;
* the main rotor turns at 289 × 5280/4800 = 317.9 rev/min.

The power is copied, so it is compared exactly; the torque and the main-rotor speed are a
division or product of a few doubles, a few ulp: rel 1e-12 is well above that and far below
the 10 % a wrong rule would change them by. CPU: a few milliseconds.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from flexshaft.design import baseline_design
from flexshaft.design.envelope import EnvelopePoint
from flexshaft.design.points import design_at_point

NO_CHANGE = SimpleNamespace(thermal={}, materials={})


def test_an_overspeed_point_keeps_the_power_and_lowers_the_torque():
    design = baseline_design()
    assert (design.operating.speed_rpm, design.operating.power) == (4800.0, 246000.0)
    assert design.operating.main_rotor_speed_rpm == 289.0
    at_point = design_at_point(design, EnvelopePoint(name="overspeed", speed_rpm=5280.0), NO_CHANGE)
    operating = at_point.operating
    assert operating.speed_rpm == 5280.0
    assert operating.power == 246000.0
    torque = 246000.0 / (5280.0 * 2.0 * math.pi / 60.0)
    assert operating.torque == pytest.approx(torque, rel=1e-12)
    assert operating.torque == pytest.approx(design.operating.torque / 1.1, rel=1e-12)
    assert operating.main_rotor_speed_rpm == pytest.approx(289.0 * 1.1, rel=1e-12)


def test_a_point_with_its_own_power_and_speed_takes_both():
    """A point giving both sets both: 120 kW at 2400 rev/min, T = 120 000 / (2400 · 2π/60) N m."""
    at_point = design_at_point(
        baseline_design(), EnvelopePoint(name="idle", speed_rpm=2400.0, power=120000.0), NO_CHANGE
    )
    assert (at_point.operating.speed_rpm, at_point.operating.power) == (2400.0, 120000.0)
    assert at_point.operating.torque == pytest.approx(120000.0 / (2400.0 * 2.0 * math.pi / 60.0), rel=1e-12)
