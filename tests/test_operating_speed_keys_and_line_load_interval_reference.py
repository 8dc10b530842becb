"""The operating speed's keys and a line load's interval against what they mean, derived here.

* **One speed.** ``[operating]`` takes the shaft speed as ``speed_rpm`` n [rev/min] or as
  ``speed`` Ω [rad/s], Ω = 2πn/60. Given both, the point is defined twice: 4800 rev/min and
  4800 rad/s differ by the factor 60/(2π) ≈ 9.55, so the torque P/Ω, the gyroscopic terms and
  the imbalance force e m Ω² would follow whichever one the code happened to read. The only
  physical answer is to refuse the pair; the test gives two that disagree and two that agree
  (the agreeing pair is still a second, redundant statement of the same number: refused too).
* **The speed range** (docs/limits.md: "Also bounded: the speed (0 to 1e6 rev/min)"): a shaft
  turning backwards is not an operating point (a negative Ω flips the sense of the gyroscopic
  coupling and of every whirl label), so Ω = −1 rad/s is refused in rad/s as in rev/min; and
  2e5 rev/min, inside the documented range, is accepted in both spellings with
  Ω = 2π·2e5/60 = 20943.95... rad/s (one multiplication and one division: relative 1e-15,
  compared at 1e-14). The top of the range, 1e6 rev/min, is accepted as Ω = 2π·1e6/60 rad/s.
* **A line load's interval.** A uniform line load q on [x_start, x_end] has the resultant
  q (x_end − x_start) (docs/testing.md's row for test_static_and_boom_line_loads_reference.py):
  an interval given backwards has a negative length, so its resultant would point against the
  load written, or vanish if the assembly found no element between the ends. It is refused;
  the same load with its ends in order is accepted.

Written for the mutations h57f-loads-both-speeds-accepted, h57f-loads-max-speed-1e5-rpm and
h57f-loads-reversed-line-load-accepted of scripts/mutations.toml (h57f-loads-negative-rad-s-accepted
is marked equivalent there: the torque check P ≤ T_max Ω refuses every Ω < 0 since P ≥ 0; the
backward-shaft test holds the refusal whichever check gives it). Only the pydantic models are
built (no model is assembled).
"""

from __future__ import annotations

import math

import pydantic
import pytest

from flexshaft.design.loads import LineLoad, Operating


@pytest.mark.parametrize("speed", [4800.0, 4800.0 * 2.0 * math.pi / 60.0])
def test_a_speed_given_both_in_rpm_and_in_rad_s_is_refused(speed):
    with pytest.raises(pydantic.ValidationError):
        Operating(speed_rpm=4800.0, speed=speed, power=300.0e3)


def test_either_spelling_alone_gives_the_same_operating_point():
    """Ω = 2πn/60 and T = P/Ω: 300 kW at 4800 rev/min give 300e3·60/(2π·4800) N m."""
    by_rpm = Operating(speed_rpm=4800.0, power=300.0e3)
    by_rad = Operating(speed=4800.0 * 2.0 * math.pi / 60.0, power=300.0e3)
    omega = 4800.0 * 2.0 * math.pi / 60.0
    for point in (by_rpm, by_rad):
        assert point.speed_rad_s == pytest.approx(omega, rel=1e-14)
        assert point.torque == pytest.approx(300.0e3 * 60.0 / (2.0 * math.pi * 4800.0), rel=1e-14)


def test_a_backward_spinning_shaft_is_refused_in_rad_s_as_in_rpm():
    with pytest.raises(pydantic.ValidationError):
        Operating(speed=-1.0, power=0.0)
    with pytest.raises(pydantic.ValidationError):
        Operating(speed_rpm=-1.0, power=0.0)
    assert Operating(speed=0.0, power=0.0).speed_rad_s == 0.0


@pytest.mark.parametrize("rpm", [2.0e5, 1.0e6])
def test_speeds_up_to_one_million_rpm_are_accepted_in_both_spellings(rpm):
    omega = rpm * 2.0 * math.pi / 60.0
    assert Operating(speed_rpm=rpm, power=0.0).speed_rad_s == pytest.approx(omega, rel=1e-14)
    assert Operating(speed=omega, power=0.0).speed_rad_s == pytest.approx(omega, rel=1e-14)


def test_a_line_load_given_backwards_is_refused():
    q = (0.0, -250.0, 0.0)  # N/m
    with pytest.raises(pydantic.ValidationError):
        LineLoad(name="q", on="shaft", x_start=1.5, x_end=0.5, force_per_length=q)
    forward = LineLoad(name="q", on="shaft", x_start=0.5, x_end=1.5, force_per_length=q)
    assert forward.force_per_length[1] * (forward.x_end - forward.x_start) == pytest.approx(-250.0, rel=1e-15)
