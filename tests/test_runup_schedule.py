"""``run_up``'s speed schedule: it ends at t = T at the requested speed, at the requested
constant acceleration, with the imbalance phase φ = ∫Ω dt of that schedule.

Reference (kinematics of a constant-acceleration ramp, derived here): from Ω₀ to Ω₁ in T,
α = (Ω₁ − Ω₀)/T, Ω(t) = Ω₀ + α t and φ(t) = Ω₀ t + ½ α t² for 0 ≤ t ≤ T; during a dwell
after T, Ω = Ω₁, α = 0 and φ = φ(T) + Ω₁ (t − T). These are polynomials, so the reported
schedule must match them to round-off (1e-12 relative; φ is summed over ~10² output intervals).
The rotor is the cheap Jeffcott rotor of tests/rotors.py (ω_n ≈ 302 rad/s, ζ = 0.05) on the basis
of its two disk modes (the near-massless tube's own modes, at 1e4-1e6 rad/s, would only make
the envelope integration stiff; tests/test_transient.py does the same).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.transient import SpeedProfile, run_up
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

C_E = 2 * 0.05 * math.sqrt(K_SHAFT * M_DISK)


def jeffcott_with_imbalance(speed_rpm: float = 0.0):
    # an eccentricity, so that the imbalance load is not zero (with none the envelope
    # integrator's step control shrinks the step to 0: reported, not tested here)
    text = jeffcott_text(0.0, C_E).replace("speed_rpm = 0.0", f"speed_rpm = {speed_rpm}")
    return build_model(loads_design(text + "[loads]\neccentricity = 1.0e-3\n"))


@pytest.fixture(scope="module")
def model():
    return jeffcott_with_imbalance()


def schedule(t, start, stop, duration, dwell=0.0):
    """(Ω, α, φ) of the ramp and dwell at times t."""
    t = np.asarray(t, dtype=float)
    alpha = (stop - start) / duration
    ramp = t <= duration * (1 + 1e-12)  # run_up's ramp time (Ω₁ − Ω₀)/α may differ from T by an ulp
    tr = np.minimum(t, duration)
    speed = start + alpha * tr
    phase = start * tr + 0.5 * alpha * tr**2 + stop * (t - tr)
    accel = np.where(ramp, alpha, 0.0)
    return speed, accel, phase


@pytest.mark.parametrize("start, stop, duration", [(0.0, 1.5 * WN, 0.4), (0.2 * WN, 1.3 * WN, 0.25)])
def test_run_up_ends_at_t_equals_T_at_the_requested_speed_and_acceleration(model, start, stop, duration):
    r = run_up(model, duration, start=start, stop=stop, basis_size=2)
    assert r.time[0] == 0.0 and r.time[-1] == pytest.approx(duration, rel=1e-15)
    assert r.speed[0] == pytest.approx(start, abs=1e-12 * stop) and r.speed[-1] == pytest.approx(stop, rel=1e-12)
    speed, accel, phase = schedule(r.time, start, stop, duration)
    assert r.speed == pytest.approx(speed, rel=1e-12, abs=1e-12 * stop)
    assert r.acceleration == pytest.approx(accel, rel=1e-12)
    assert r.acceleration[0] == pytest.approx((stop - start) / duration, rel=1e-12)
    assert r.phase == pytest.approx(phase, rel=1e-12, abs=1e-12)
    # the envelope outputs exist at every output instant and the response is finite
    assert r.shaft_orbit.shape[1] == r.time.size and np.all(np.isfinite(r.shaft_orbit))


def test_run_up_with_a_dwell_holds_the_top_speed(model):
    start, stop, duration, dwell = 0.5 * WN, 1.2 * WN, 0.2, 0.1
    r = run_up(model, duration, start=start, stop=stop, dwell=dwell, basis_size=2)
    assert r.time[-1] == pytest.approx(duration + dwell, rel=1e-15)
    speed, accel, phase = schedule(r.time, start, stop, duration, dwell)
    hold = r.time > duration * (1 + 1e-12)
    assert hold.any() and np.all(r.speed[hold] == pytest.approx(stop, rel=1e-12))
    assert np.all(r.acceleration[hold] == 0.0)
    assert r.acceleration[~hold][:-1] == pytest.approx(accel[~hold][:-1], rel=1e-12)
    # φ is exact up to the last output of the ramp; in the dwell it grows by Ω₁ Δt per output
    # interval. The one interval that contains the end of the ramp (t = 0.2 s is not an output
    # time) is summed by the two-point Gauss rule across the kink of Ω(t): its error is below
    # α Δt²/4 (a slope jump α inside an interval Δt).
    assert r.phase[~hold] == pytest.approx(phase[~hold], rel=1e-12)
    dt = np.diff(r.time)
    assert np.diff(r.phase)[hold[1:] & hold[:-1]] == pytest.approx(stop * dt[hold[1:] & hold[:-1]], rel=1e-9)
    alpha = (stop - start) / duration
    assert np.abs(r.phase - phase).max() <= alpha * dt.max() ** 2 / 4


def test_run_down_decelerates_to_the_requested_speed(model):
    start, stop, duration = 1.4 * WN, 0.6 * WN, 0.3
    r = run_up(model, duration, start=start, stop=stop, basis_size=2)
    assert r.time[-1] == pytest.approx(duration, rel=1e-15) and r.speed[-1] == pytest.approx(stop, rel=1e-12)
    speed, accel, phase = schedule(r.time, start, stop, duration)
    assert np.all(r.acceleration == pytest.approx((stop - start) / duration, rel=1e-12))
    assert r.acceleration[0] < 0
    assert r.phase == pytest.approx(phase, rel=1e-12)


def test_default_stop_is_the_operating_speed_and_the_profile_matches():
    # a model spinning at 2000 rpm: run_up without stop ends there
    model = jeffcott_with_imbalance(2000.0)
    omega = 2000.0 * 2 * math.pi / 60
    r = run_up(model, 0.3, basis_size=2)
    assert r.speed[-1] == pytest.approx(omega, rel=1e-12) and r.time[-1] == pytest.approx(0.3, rel=1e-15)
    profile = SpeedProfile.constant_acceleration(0.0, omega, omega / 0.3)
    assert profile.duration == pytest.approx(0.3, rel=1e-15)
    assert profile.acceleration(0.1) == pytest.approx(omega / 0.3, rel=1e-12)
    assert profile.speed(0.15) == pytest.approx(omega / 2, rel=1e-12)


def test_the_static_correction_carries_the_tangential_imbalance_force():
    # An accelerating eccentric mass pushes the shaft by U (Ω² cos φ + Ω̇ sin φ, Ω² sin φ − Ω̇ cos φ)
    # (the mass's acceleration −e(φ̇² cos φ + φ̈ sin φ, φ̇² sin φ − φ̈ cos φ) reversed; U = m e).
    # Stiffen the w plane (a spring at the disk, 9k) and keep only the v-plane disk mode in the
    # basis: the w motion then comes from the static correction alone, and far below its
    # natural frequency (ω_w = √10 ω_n ≈ 955 rad/s) it is quasi-static,
    # w = U (Ω² sin φ − Ω̇ cos φ)/(10 k). A fast start (Ω̇ = 1000 rad/s², Ω ≤ 20 rad/s) makes the
    # Ω̇ term dominate. Neglected: the w plane's dynamics, (Ω/ω_w)² + 2ζ_w Ω/ω_w < 1e-3 of the
    # response; 2e-3 of its peak asserted.
    from flexshaft.assembly.balance import rotating_mass
    from flexshaft.assembly.loads import imbalance_loads

    text = jeffcott_text(0.0, C_E).replace("stiffness = {}", f"stiffness = {{ w = {9 * K_SHAFT} }}")
    assert f"w = {9 * K_SHAFT}" in text
    model = build_model(loads_design(text + "[loads]\neccentricity = 1.0e-3\n"))
    # e times the whole rotating mass (ISO 21940-11: shaft and disk) at the one bay's middle
    U = float(np.abs(imbalance_loads(model)[:, 0]).max())
    assert U == pytest.approx(1.0e-3 * rotating_mass(model), rel=1e-12)
    r = run_up(model, 0.02, start=0.0, stop=20.0, basis_size=1, output_step=1e-4)
    node = model.dofs.node_at("shaft", 0.5)
    w = (r.shaft_envelope[1, node] * np.exp(1j * r.phase)).real
    expected = U * (r.speed**2 * np.sin(r.phase) - r.acceleration * np.cos(r.phase)) / (10 * K_SHAFT)
    assert np.abs(w - expected).max() <= 2e-3 * np.abs(expected).max()


def test_a_tables_speed_and_acceleration_at_many_times_are_those_at_each_time():
    """The integrator evaluates a table's Ω and Ω̇ at many times at once (``speeds_at``,
    ``accelerations_at``): bit for bit the scalar ``speed(t)`` and ``acceleration(t)``, at random
    times, at every breakpoint and one ulp either side of it (the segment on the right of a
    breakpoint, Ω̇ right-continuous), before the start and after the end (the first and last
    speeds exactly: Ω is clamped). The numbers are the table's values on straight segments:
    checked against the line through each segment's ends to round-off."""
    profile = SpeedProfile.table([0.0, 0.7, 1.3, 2.9, 4.0], [0.0, 310.3, 310.3, 520.7, 100.1])
    knots = profile.breakpoints
    times = np.concatenate(
        [
            np.random.default_rng(1).uniform(-0.5, 4.5, 20_000),
            knots,
            np.nextafter(knots, np.inf),
            np.nextafter(knots, -np.inf),
        ]
    )
    speeds = np.array([profile.speed(t) for t in times])
    accelerations = np.array([profile.acceleration(t) for t in times])
    np.testing.assert_array_equal(profile.speeds_at(times), speeds)
    np.testing.assert_array_equal(profile.accelerations_at(times), accelerations)
    # the line through each segment's ends (clamped outside [0, 4]): 1e-12 of the largest speed
    # covers the round-off of the slope times a time of order 1
    np.testing.assert_allclose(speeds, np.interp(times, knots, [0.0, 310.3, 310.3, 520.7, 100.1]), atol=1e-12 * 520.7)
    assert profile.speed(4.0) == 100.1 and profile.speed(5.0) == 100.1 and profile.speed(-1.0) == 0.0
    assert profile.acceleration(1.3) == (520.7 - 310.3) / (2.9 - 1.3)  # right-continuous at 1.3
