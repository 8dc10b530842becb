"""The bounds of ``[operating]`` and ``[loads]`` at their edges, worked by hand.

Each case is a schema promise (the field's documented range in ``docs/limits.md`` and the model
docstrings) checked at the edge where a slipped unit, a flipped sign or an open/closed swap shows:

* the rad/s speed cap is the rpm cap converted, 1e6 rev/min x 2π/60 = 104 719.76 rad/s;
* the torque cap P/Ω <= 1e9 N m is closed: Ω = 0.5 rad/s and P = 5e8 W give exactly 1e9 N m;
* a speed range must bracket the operating speed, lowest <= 1 <= highest (closed at 1);
* the main-rotor speed cap 5000 rev/min is closed;
* at rest only a positive power is refused (P/Ω infinite), a zero power is the rest state;
* eccentricity and balance grade exclude each other (ISO 21940-11: e = G/Ω);
* loads, load factors and stations are signed: gravity is [0, -1, 0] g, a load in -y is a
  negative component, a driveline may start left of the origin;
* the eccentricity cap is 10 mm, so a G 40 rotor at 5000 rev/min, e = G/Ω =
  0.040 m/s / (5000 x 2π/60 rad/s) = 76.4 µm, is well inside;
* the Tsai-Wu F12 is signed: Tsai and Hahn's usual estimate -1/2 sqrt(F11 F22) is negative.

Pure schema validation (no model is built): a few ms.
"""

from __future__ import annotations

import math

import pytest
from pydantic import ValidationError

from flexshaft.design.loads import LineLoad, Loads, Operating, PointLoad
from flexshaft.design.materials import Lamina


def test_the_rad_s_speed_cap_is_the_rpm_cap_converted() -> None:
    cap = 1.0e6 * 2.0 * math.pi / 60.0  # 104 719.76 rad/s
    assert Operating(speed=0.99 * cap, power=0.0).speed_rad_s == 0.99 * cap
    with pytest.raises(ValidationError, match="speed"):
        Operating(speed=1.01 * cap, power=0.0)  # 1.06e5 rad/s: above 1e6 rev/min


def test_the_torque_cap_is_closed() -> None:
    # P/Ω = 5e8 W / 0.5 rad/s = 1e9 N m exactly (both binary-exact): allowed
    at_cap = Operating(speed=0.5, power=5.0e8)
    assert at_cap.torque == 1.0e9
    with pytest.raises(ValidationError, match="torque"):
        Operating(speed=0.5, power=5.01e8)


def test_a_speed_range_may_end_or_start_at_the_operating_speed() -> None:
    low = Operating(speed=100.0, power=0.0, speed_range=(0.9, 1.0))
    high = Operating(speed=100.0, power=0.0, speed_range=(1.0, 1.1))
    assert low.speed_limits == pytest.approx((90.0, 100.0), rel=1e-15)
    assert high.speed_limits == pytest.approx((100.0, 110.0), rel=1e-15)
    with pytest.raises(ValidationError, match="bracket"):
        Operating(speed=100.0, power=0.0, speed_range=(1.01, 1.1))


def test_the_main_rotor_speed_cap_is_closed() -> None:
    op = Operating(speed_rpm=4800.0, power=0.0, main_rotor_speed_rpm=5000.0, main_rotor_blades=2)
    # 5000 rev/min = 83.33 rev/s: 1/rev 83.33 Hz, 2/rev 166.7 Hz
    assert op.main_rotor_frequencies() == pytest.approx({"1/rev": 5000.0 / 60.0, "2/rev": 10000.0 / 60.0})
    with pytest.raises(ValidationError, match="main_rotor_speed_rpm"):
        Operating(speed_rpm=4800.0, power=0.0, main_rotor_speed_rpm=5000.5)


def test_at_rest_only_a_positive_power_is_refused() -> None:
    rest = Operating(speed_rpm=0.0, power=0.0)
    assert rest.speed_rad_s == 0.0 and rest.torque == 0.0
    with pytest.raises(ValidationError, match="infinite"):
        Operating(speed_rpm=0.0, power=1.0)


def test_eccentricity_and_balance_grade_exclude_each_other() -> None:
    assert Loads(balance_grade=6.3).balance_grade == 6.3
    with pytest.raises(ValidationError, match="at most one of eccentricity"):
        Loads(eccentricity=1e-5, balance_grade=6.3)


def test_loads_and_stations_are_signed() -> None:
    loads = Loads(
        load_factor=(0.0, -3.5, 0.0),
        point=(PointLoad(name="p", on="shaft", x=-0.5, force=(0.0, -100.0, 0.0), moment=(0.0, 0.0, -5.0)),),
        line=(LineLoad(name="w", on="shaft", x_start=-1.0, x_end=0.5, force_per_length=(0.0, -10.0, 0.0)),),
    )
    assert loads.load_factor == (0.0, -3.5, 0.0)
    assert loads.point[0].x == -0.5 and loads.point[0].force == (0.0, -100.0, 0.0)
    assert loads.line[0].x_start == -1.0 and loads.line[0].force_per_length == (0.0, -10.0, 0.0)
    with pytest.raises(ValidationError, match="load_factor"):
        Loads(load_factor=(0.0, -100.5, 0.0))  # the ±100 g bound holds on the negative side too


def test_a_g40_eccentricity_is_inside_the_cap() -> None:
    e = 0.040 / (5000.0 * 2.0 * math.pi / 60.0)  # G 40 at 5000 rev/min: 76.4 µm
    assert Loads(eccentricity=e).eccentricity == e
    assert Loads(eccentricity=1e-2).eccentricity == 1e-2  # the 10 mm cap itself
    with pytest.raises(ValidationError, match="eccentricity"):
        Loads(eccentricity=1.1e-2)


def test_a_negative_tsai_wu_interaction_is_accepted() -> None:
    strengths = {"X_t": 1.5e9, "X_c": 1.2e9, "Y_t": 50e6, "Y_c": 250e6, "S": 70e6}
    f11 = 1.0 / (strengths["X_t"] * strengths["X_c"])
    f22 = 1.0 / (strengths["Y_t"] * strengths["Y_c"])
    f12 = -0.5 * math.sqrt(f11 * f22)  # Tsai-Hahn: -3.33e-18 1/Pa²
    ply = Lamina(kind="lamina", density=1600.0, E_L=140e9, E_T=10e9, G_LT=5e9, nu_LT=0.3, F12=f12, **strengths)
    assert ply.F12 == f12
