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

References: the observed order (ratios of successive differences, 16 for fourth order; measured
16.007, 16.002, 16.000, asserted within ±2, where second order gives 4) and the end state of the
same ODE integrated independently by SciPy's DOP853 at rtol 1e-12 (agreement 1e-8: the finest
fixed step, 1/128 s, leaves a fourth-order error of about the last difference over 15, ~1e-10).
CPU: five runs of 8-128 steps on one state, about 0.05 s.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from flexshaft.analyses.envelope import integrate_envelope

A, S0, RAMP = -0.3 + 4.0j, 0.5, 1.5


def _speed(t):
    return S0 + RAMP * np.asarray(t, dtype=float)


def _end_state(h: float) -> complex:
    system = SimpleNamespace(
        n=1,
        scale=np.ones(1),
        b=np.ones(1, complex),
        matrix=lambda speed: np.array([[A - 1j * speed]]),  # the mode and the frame rotation −iΩ
        drift=lambda speeds, reference, Z: np.zeros_like(Z),  # no gyroscopic or loss drift
        norm=lambda Z: float(np.linalg.norm(Z)),
        steady_state=lambda speed: np.zeros(1, complex),
    )
    run = integrate_envelope(
        system,
        _speed,
        lambda t: np.full_like(np.asarray(t, dtype=float), RAMP),
        np.array([0.0, 1.0]),
        np.ones(1, complex),
        np.array([1.0]),
        rtol=1e9,  # no error reaches it: fixed steps h
        max_step=h,
        max_speed=S0 + RAMP,
    )
    assert run.steps == round(1.0 / h) and run.rejected == 0
    return complex(run.states[0, 0])


def test_fixed_steps_converge_at_fourth_order_under_a_fast_ramp():
    ends = np.array([_end_state(2.0**-k) for k in range(3, 8)])
    differences = np.abs(np.diff(ends))
    ratios = differences[:-1] / differences[1:]
    assert ratios == pytest.approx([16.0, 16.0, 16.0], abs=2.0), ratios

    def rhs(t, y):
        z = y[0] + 1j * y[1]
        s = S0 + RAMP * t
        dz = (A - 1j * s) * z + (s * s - 1j * RAMP)
        return [dz.real, dz.imag]

    exact = solve_ivp(rhs, (0.0, 1.0), [1.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14).y[:, -1]
    assert abs(ends[-1] - complex(exact[0], exact[1])) <= 1e-8
