"""The envelope integrator stays fourth order when the frame turns within a step (a fast ramp).

The run-up's envelope turns with the shaft: a mode of rate ``a`` seen from the spinning frame
obeys ``Ż = (a − iΩ(t)) Z + b (Ω² − iΩ̇)`` (:mod:`flexshaft.analyses.transient`). The integrator
(:mod:`flexshaft.analyses.envelope`) takes the frame rotation since each step's midpoint speed,
``θ(τ) = ∫ (Ω − Ω_mid)``, exactly, at each stage's own time: the half-step stages at τ = h/2, the
last at τ = h. Under a constant acceleration α, θ(h/2) = −αh²/8 and θ(h) = 0, so a stage rotated
by the wrong angle errs by αh²/8 in phase, which drops ETDRK4 (Cox & Matthews 2002, fourth order
for a smooth remainder) to second order: successive differences of the end state under fixed
steps H, H/2, ... then fall by 4 a halving instead of 16. tests/test_envelope_integrator.py checks
the order under a ramp of 0.015 rad/s², too slow for the rotation within a step to show; here
the speed runs from 0.5 to 2 rad/s in 1 s (α = 1.5 rad/s²), a = −0.3 + 4i 1/s, b = 1.
The angle is taken by Simpson's rule, exact for Ω up to cubic in t; under a constant
acceleration the trapezoid rule is exact too, so a second case adds a quadratic term,
Ω = 0.5 + 1.5 t + β t² with β = 2 rad/s³ (to 3.5 rad/s at 1 s): there a trapezoid rule errs by
β τ³/6 in each stage's angle, again second order (ratios 4.06, 4.03, 4.02 measured).

References: the observed order (ratios of successive differences, 16 for fourth order; measured
16.007, 16.002, 16.000 at β = 0 and 16.001, 16.000, 15.998 at β = 2, asserted within ±2, where
second order gives 4) and the end state of the same ODE integrated independently by SciPy's
DOP853 at rtol 1e-12 (its own error about 1e-13: it moves by 6e-14 and 2.5e-13 at rtol 1e-13).
The step is fixed at H by ``max_step`` (the error control is off), and each accepted step is the
step-doubling pair: two ETDRK4 steps of H/2, which give the end state. On the finest H, 1/128 s
at β = 0 and 1/256 s at β = 2 (0.25/max Ω caps H at 1/16 s when Ω reaches 3.5 rad/s), the
remaining fourth-order error is about the last difference over 15, 9e-12; measured 9.3e-12 and
8.4e-12 against DOP853, asserted within 1e-10.
CPU: ten runs of 8-256 steps on one state and two DOP853 runs, about 0.3 s.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from flexshaft.analyses.envelope import integrate_envelope

A, S0, RAMP = -0.3 + 4.0j, 0.5, 1.5


def _end_state(h: float, beta: float) -> complex:
    system = SimpleNamespace(
        n=1,
        scale=np.ones(1),
        frequency=1.0,
        b=np.ones(1, complex),
        matrix=lambda speed: np.array([[A - 1j * speed]]),  # the mode and the frame rotation −iΩ
        drift=lambda speeds, reference, Z: np.zeros_like(Z),  # no gyroscopic or loss drift
        norm=lambda Z: float(np.linalg.norm(Z)),
        steady_state=lambda speed: np.zeros(1, complex),
    )
    run = integrate_envelope(
        system,
        lambda t: S0 + RAMP * np.asarray(t, dtype=float) + beta * np.asarray(t, dtype=float) ** 2,
        lambda t: RAMP + 2.0 * beta * np.asarray(t, dtype=float),
        np.array([0.0, 1.0]),
        np.ones(1, complex),
        np.array([1.0]),
        rtol=1e9,  # no error reaches it: fixed steps h
        max_step=h,
        max_speed=S0 + RAMP + beta,
    )
    assert run.steps == round(1.0 / h) and run.rejected == 0
    return complex(run.states[0, 0])


@pytest.mark.parametrize(("beta", "first"), [(0.0, 3), (2.0, 4)])  # Ω̈ = 2β; the first H = 2^-first s
def test_fixed_steps_converge_at_fourth_order_under_a_fast_ramp(beta, first):
    ends = np.array([_end_state(2.0**-k, beta) for k in range(first, first + 5)])
    differences = np.abs(np.diff(ends))
    ratios = differences[:-1] / differences[1:]
    assert ratios == pytest.approx([16.0, 16.0, 16.0], abs=2.0), ratios

    def rhs(t, y):
        z = y[0] + 1j * y[1]
        s = S0 + RAMP * t + beta * t * t
        dz = (A - 1j * s) * z + (s * s - 1j * (RAMP + 2.0 * beta * t))
        return [dz.real, dz.imag]

    exact = solve_ivp(rhs, (0.0, 1.0), [1.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14).y[:, -1]
    assert abs(ends[-1] - complex(exact[0], exact[1])) <= 1e-10
