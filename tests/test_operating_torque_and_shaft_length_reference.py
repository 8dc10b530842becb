"""The operating torque and the shaft's length, from their definitions, worked by hand.

* Torque from power: T = P/Ω with Ω in rad/s. A shaft speed given in rev/min is converted
  first, Ω = 2π n/60: 6000 rev/min = 100 rev/s = 200π rad/s = 628.3185 rad/s, so 300 kW give
  T = 300 000/(200π) = 477.4648 N m (1500/π). Dividing by the rpm figure instead would give
  50 N m, a factor 60/(2π) = 9.55 too small.
* The shaft's length is x_end − x_start: a shaft from x = 0.5 m to x = 2.0 m is 1.5 m long
  (the stations of ``[shaft]`` are on the driveline axis, x = 0 at the boom root, so a
  shaft need not start at 0).

Tolerance: each value is one or two floating-point operations on binary-exact or once-rounded
inputs, so ``REL`` = 1e-14 (some 50 ulp) is ample and 1e12 times smaller than either mistake.
Pure schema objects (no model is built): a few ms.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.design.components import Shaft
from flexshaft.design.loads import Operating

REL = 1e-14


def test_torque_is_power_over_omega_in_rad_s_when_speed_is_given_in_rpm() -> None:
    op = Operating(speed_rpm=6000.0, power=300.0e3)
    assert op.torque == pytest.approx(1500.0 / math.pi, rel=REL)  # 477.46 N m
    same = Operating(speed=200.0 * math.pi, power=300.0e3)
    assert same.torque == pytest.approx(1500.0 / math.pi, rel=REL)


def test_shaft_length_is_end_minus_start_station() -> None:
    shaft = Shaft(x_start=0.5, x_end=2.0, outer_diameter=0.1, wall_thickness=0.002, material="steel")
    assert shaft.length == pytest.approx(1.5, rel=REL)
