"""The run-up's speed law Ω(t) against its closed forms (no model, no integration).

References (derived here):

* a constant-acceleration run from Ω₀ to Ω₁ at |a| ramps for T = |Ω₁ − Ω₀| / |a|, with
  Ω(t) = Ω₀ + a t on [0, T], then holds Ω₁ for the dwell: the run ends at t = T + dwell;
* a piecewise-linear table through (tₖ, Ωₖ) has on segment k the slope (Ωₖ₊₁ − Ωₖ)/(tₖ₊₁ − tₖ)
  and Ω(t) = Ωₖ + slope (t − tₖ) (every value below is that sum typed out by hand);
* Ω(t) = c t² has dΩ/dt = 2 c t; the one-sided difference of a quadratic over h, the only one
  available at the ends of [0, T], is 2 c t ± c h, so at h = 1e-6 T it is within 1e-6 relative
  of 2 c T at t = T (and c h ≈ 0 at t = 0).

Tolerances: the values are sums of a few doubles (rel 1e-12), except the differenced
acceleration (1e-5, from the c h term above and the difference's round-off, ~1e-10/1e-6).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.speed_profile import SpeedProfile


def test_constant_acceleration_ramp_then_dwell():
    # 10 → 110 rad/s at 20 rad/s²: a 5 s ramp, then 3 s held: the run ends at 8 s
    p = SpeedProfile.constant_acceleration(10.0, 110.0, 20.0, dwell=3.0)
    assert p.duration == pytest.approx(8.0, rel=1e-12)
    t = np.array([0.0, 1.0, 2.5, 4.9, 5.0, 6.0, 7.9, 8.0])
    expected = np.where(t <= 5.0, 10.0 + 20.0 * t, 110.0)
    assert p.speeds_at(t) == pytest.approx(expected, rel=1e-12)
    assert [p.speed(x) for x in t] == pytest.approx(expected, rel=1e-12)
    # right-continuous at the breakpoint: the dwell's zero acceleration from t = 5 s on
    assert p.accelerations_at(np.array([0.0, 4.9, 5.0, 7.0])) == pytest.approx([20.0, 20.0, 0.0, 0.0], abs=1e-12)


def test_dwell_longer_than_the_ramp_ends_at_their_sum():
    # 0 → 100 rad/s at 50 rad/s² (2 s), then 10 s held: 12 s in all, at 100 rad/s from 2 s
    p = SpeedProfile.constant_acceleration(0.0, 100.0, 50.0, dwell=10.0)
    assert p.duration == pytest.approx(12.0, rel=1e-12)
    assert p.breakpoints == pytest.approx([0.0, 2.0, 12.0], rel=1e-12)
    assert p.speed(11.0) == pytest.approx(100.0, rel=1e-12)


def test_run_down_decelerates():
    # 300 → 100 rad/s at |−40| rad/s²: a 5 s ramp, Ω = 300 − 40 t
    p = SpeedProfile.constant_acceleration(300.0, 100.0, -40.0)
    assert p.duration == pytest.approx(5.0, rel=1e-12)
    assert p.speed(2.0) == pytest.approx(220.0, rel=1e-12)
    assert p.acceleration(2.0) == pytest.approx(-40.0, rel=1e-12)


def test_table_segments_ramp_from_their_own_start():
    # (0, 0) → (2, 100) → (5, 160) → (6, 160): slopes 50, 20, 0 rad/s²
    p = SpeedProfile.table([0.0, 2.0, 5.0, 6.0], [0.0, 100.0, 160.0, 160.0])
    t = np.array([1.0, 3.0, 4.5, 5.5])
    expected = [50.0, 100.0 + 20.0 * 1.0, 100.0 + 20.0 * 2.5, 160.0]
    assert [p.speed(x) for x in t] == pytest.approx(expected, rel=1e-12)
    assert p.speeds_at(t) == pytest.approx(expected, rel=1e-12)
    assert [p.acceleration(x) for x in t] == pytest.approx([50.0, 20.0, 20.0, 0.0], abs=1e-12)
    assert p.accelerations_at(t) == pytest.approx([50.0, 20.0, 20.0, 0.0], abs=1e-12)


def test_callable_acceleration_by_differences_at_the_ends():
    c, T = 3.0, 4.0  # Ω = 3 t² on [0, 4] s: dΩ/dt = 6 t
    p = SpeedProfile.from_callable(lambda t: c * t * t, T)
    assert p.acceleration(T) == pytest.approx(2 * c * T, rel=1e-5)
    assert p.acceleration(0.5 * T) == pytest.approx(c * T, rel=1e-5)
    assert abs(p.acceleration(0.0)) < 1e-4  # 2 c · 0 + c h, h = 4e-6 s
    assert p.max_speed == pytest.approx(c * T * T, rel=1e-12)
