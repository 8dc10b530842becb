"""The run-up's envelope integrator (flexshaft.analyses.envelope) across a kink of the speed: the
steps land on the breakpoints of a speed table, where the acceleration Ω̇ jumps.

A one-state envelope system ``Ż = (iω₀ − iΩ(t)) Z`` (an undamped mode of frequency ω₀ seen in
the frame that turns with the shaft; no load, no gyroscopic or loss drift) has the exact
solution ``Z(t) = exp(iω₀t − iΦ(t)) Z(0)``, ``Φ(t) = ∫₀ᵗ Ω dt`` (derived here: the equation is
scalar and linear, so its solution is the exponential of the integral of its coefficient).
For a piecewise-linear Ω through (tₖ, Ωₖ), Φ is piecewise quadratic:
``Φ(t) = Φ(tₖ) + Ωₖ (t − tₖ) + ½ aₖ (t − tₖ)²`` with aₖ = (Ωₖ₊₁ − Ωₖ)/(tₖ₊₁ − tₖ).

On a step inside one segment the integrator's rotation (Simpson's rule on Ω − Ω_mid) and the
exact exponential of the rest are exact, so only round-off remains. A step that straddled a
breakpoint would take Simpson's rule over the kink of Ω, wrong by O(h² Δa) in the phase; the
step control (step doubling) sees part of it and shrinks the step until the estimate is below
rtol, but the phase error left is of order rtol, not of round-off. The breakpoints are not
round numbers of the step grid (1/3 s, 0.7 s), so no step lands on them by chance.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from flexshaft.analyses.envelope import integrate_envelope
from flexshaft.analyses.speed_profile import SpeedProfile


def _free_mode(w0: float) -> SimpleNamespace:
    """``Ż = i(ω₀ − Ω) Z``: one undamped mode in the frame turning with the shaft, no load."""
    return SimpleNamespace(
        n=1,
        scale=np.ones(1),
        frequency=1.0,
        b=np.zeros(1, complex),
        matrix=lambda speed: np.array([[1j * (w0 - speed)]]),
        drift=lambda speeds, reference, Z: np.zeros_like(Z),
        norm=lambda Z: float(np.linalg.norm(Z)),
        steady_state=lambda speed: np.zeros(1, complex),
    )


def test_a_free_state_turns_exactly_through_the_kinks_of_a_speed_table():
    """ω₀ = 50 rad/s; Ω up from 100 to 160 rad/s in 1/3 s, down to 60 rad/s at 0.7 s, held
    to 1 s (Ω̇ jumps from 180 to −272.7 and to 0 rad/s²); rtol 1e-6. Tolerance 1e-9 on |Z| = 1:
    the exact steps leave round-off of the phase, |Φ| ≤ 120 rad over some 60 steps,
    60 × 120 × 2.2e-16 ≈ 2e-12 (measured 1.6e-14); steps across the kinks leave a phase
    error of order rtol (measured 5e-6 with steps that straddle the breakpoints)."""
    w0 = 50.0
    knots = np.array([0.0, 1.0 / 3.0, 0.7, 1.0])
    speeds = np.array([100.0, 160.0, 60.0, 60.0])
    profile = SpeedProfile.table(knots, speeds)
    times = np.linspace(0.0, 1.0, 41)
    run = integrate_envelope(
        _free_mode(w0),
        profile.speeds_at,
        profile.accelerations_at,
        profile.breakpoints,
        np.ones(1, complex),
        times,
        rtol=1e-6,
        max_speed=160.0,
    )
    slopes = np.diff(speeds) / np.diff(knots)
    k = np.clip(np.searchsorted(knots, times, side="right") - 1, 0, knots.size - 2)
    phi_at_knots = np.concatenate([[0.0], np.cumsum(0.5 * (speeds[:-1] + speeds[1:]) * np.diff(knots))])
    dt = times - knots[k]
    phi = phi_at_knots[k] + speeds[k] * dt + 0.5 * slopes[k] * dt**2
    exact = np.exp(1j * w0 * times - 1j * phi)
    assert np.abs(run.states[0] - exact).max() <= 1e-9
