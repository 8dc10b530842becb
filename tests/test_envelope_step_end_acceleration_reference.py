"""The run-up integrator's last stage of a step ending on a speed-table breakpoint takes its own
segment's acceleration.

The imbalance load of a changing speed is ``b (Ω² − iΩ̇)`` (docs/transient.md); a speed table is
linear between its rows, so Ω̇ jumps at each row, and the integrator lands its steps on the rows
(``breakpoints``: "Ω̇ may jump there", :func:`~flexshaft.analyses.envelope.integrate_envelope`).
Its profiles' Ω̇ is right-continuous: at a row itself it is the next segment's. Until the
twenty-fifth session the ETDRK4 stage at a step's end (t + h on the row) read that next Ω̇, an
error the step-doubling estimate sees about 1/15 of: a step into a short steep segment failed
with "step size underflow", a longer one was accepted 15 × the tolerance off (found by hunt
h55a).

Reference: one damped mode m q̈ + c q̇ + k q = (Ω² − iΩ̇) e^{iφ}, φ = ∫Ω dt (unit mass and
imbalance), written in the envelope's rotating frame Z = (q, q̇) e^{−iφ}, through the table
Ω = 5, 5, 7, 7 rad/s at t = 0, 1, 1 + ε, 3 s (a step of 2 rad/s over ε), from its steady state at
5 rad/s; against scipy's DOP853 on the fixed-frame equations, segment by segment (rtol 1e-12), φ
integrated in closed form (piecewise quadratic). ω₀ = 10 rad/s, c = 0.5 N s/m. The run's local
error is held to rtol = 1e-6 a step, but in the envelope's frame the load is a quadratic
polynomial of t on each segment and the steps take the frame's rotation exactly, so ETDRK4 (fourth
order) leaves little beyond round-off: measured 3e-12 relative over the run with Prescott's and
Haswell's kernels alike, against 7e-8 with the next segment's Ω̇ at ε = 1e-4 (and a step-size
underflow at ε = 1e-6). Asserted below 1e-9.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from flexshaft.analyses.envelope import integrate_envelope
from flexshaft.analyses.speed_profile import SpeedProfile

W0, C = 10.0, 0.5


def _system():
    J0 = np.array([[0.0, 1.0], [-W0 * W0, -C]], complex)
    matrix = lambda speed: J0 - 1j * speed * np.eye(2)  # noqa: E731 - the envelope frame turns at Ω
    b = np.array([0.0, 1.0], complex)
    return SimpleNamespace(
        n=2,
        scale=np.array([W0, 1.0]),
        frequency=W0,
        b=b,
        matrix=matrix,
        drift=lambda speeds, reference, Z: np.zeros_like(Z),
        steady_state=lambda speed: np.linalg.solve(matrix(speed), -b * speed * speed),
        norm=lambda Z: float(np.linalg.norm(np.array([W0, 1.0]) * Z)),
    )


def _reference(knots, speeds, z0, times):
    slopes = np.diff(speeds) / np.diff(knots)

    def segment(t):
        return min(int(np.searchsorted(knots, t, side="right")) - 1, knots.size - 2)

    def phase(t):
        k = segment(t)
        done = sum(0.5 * (speeds[j] + speeds[j + 1]) * (knots[j + 1] - knots[j]) for j in range(k))
        dt = t - knots[k]
        return done + speeds[k] * dt + 0.5 * slopes[k] * dt * dt

    def rhs(t, x, k):
        q, p = x[0] + 1j * x[1], x[2] + 1j * x[3]
        omega = speeds[k] + slopes[k] * (t - knots[k])
        dp = -W0 * W0 * q - C * p + (omega * omega - 1j * slopes[k]) * np.exp(1j * phase(t))
        return [p.real, p.imag, dp.real, dp.imag]

    x, pieces = [z0[0].real, z0[0].imag, z0[1].real, z0[1].imag], []
    for k in range(knots.size - 1):
        sol = solve_ivp(
            rhs, (knots[k], knots[k + 1]), x, args=(k,), method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True
        )
        pieces.append(sol)
        x = sol.y[:, -1]
    q = []
    for t in times:
        v = pieces[segment(t)].sol(t)
        q.append(v[0] + 1j * v[1])
    return np.array(q), np.array([phase(t) for t in times])


@pytest.mark.parametrize("eps", [1e-6, 1e-4])
def test_a_step_into_a_steep_speed_segment_is_integrated_to_its_tolerance(eps):
    knots, speeds = np.array([0.0, 1.0, 1.0 + eps, 3.0]), np.array([5.0, 5.0, 7.0, 7.0])
    profile = SpeedProfile.table(knots, speeds)
    system = _system()
    times = np.linspace(0.0, profile.duration, 61)
    z0 = system.steady_state(5.0)
    run = integrate_envelope(
        system, profile.speeds_at, profile.accelerations_at, profile.breakpoints, z0, times, rtol=1e-6, max_speed=7.0
    )
    q_ref, phase = _reference(knots, speeds, z0, times)
    q = run.states[0] * np.exp(1j * phase)
    assert np.abs(q - q_ref).max() < 1e-9 * np.abs(q_ref).max()
