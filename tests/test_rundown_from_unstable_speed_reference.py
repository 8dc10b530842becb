"""A run-down that starts above the whirl onset and leaves it is integrated, not refused.

:func:`~flexshaft.analyses.transient.transient_response` refuses before integrating only a run
that HOLDS an unstable speed long enough for a free whirl to grow more than MAX_GROWTH-fold
(its ``_refuse_growth_at_constant_speed``: "a dwell ... at an unstable speed"); a ramp through
unstable speeds is left to the integrator, which counts the growth it meets step by step.

Rotor and growth rate as in tests/test_runup_unstable_dwell_reference.py: the Jeffcott disk of
tests/rotors.py with a rotating-frame loss factor η = 0.02 and no external damping; its causal
loss D = kη/(ω_n + Ω) on the velocity relative to the spin gives the forward whirl, to first
order in D, the growth rate (derived: s = iω_n + δ in m s² + D(s − iΩ) + k = 0)

    Re s = η ω_n (Ω − ω_n) / (2 (ω_n + Ω)),

positive only above ω_n and at most η ω_n / 6 (= 1.0 1/s) up to Ω = 2 ω_n. A run-down from
2 ω_n to rest in 10 s spends 5 s above ω_n, so a free whirl grows at most e^{5 × 1.01} =
e^{5.05}-fold over it, below MAX_GROWTH = 1e3 = e^{6.91}: the run is handed to the integrator
(a stand-in here that records the call; the run itself is not this test's subject). Counting
the whole 10 s ramp at the start speed's rate would give e^{10}: a refusal. The rate at 2 ω_n
is checked against the exact root of the quadratic (np.roots) to 2 % (its first-order form).

CPU: one two-mode setup and a 4×4 eigen-solve, no integration.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

import flexshaft.analyses.transient as transient_module
from flexshaft.analyses.envelope import MAX_GROWTH
from flexshaft.analyses.transient import SpeedProfile, transient_response

ETA = 0.02
TOP = 2.0 * WN
DURATION = 10.0


class _Reached(Exception):
    pass


def _integrator(*args, **kwargs):
    raise _Reached


def test_a_rundown_through_the_unstable_range_reaches_the_integrator(monkeypatch):
    monkeypatch.setattr(transient_module, "integrate_envelope", _integrator)
    D = K_SHAFT * ETA / (WN + TOP)
    rate = np.roots([M_DISK, D, K_SHAFT - 1j * D * TOP]).real.max()
    assert rate == pytest.approx(ETA * WN / 6, rel=0.02)
    above = DURATION * (TOP - WN) / TOP  # time spent above the onset ω_n
    assert above * rate < np.log(MAX_GROWTH) < DURATION * rate  # the ramp is fine; its length at top rate is not
    with pytest.raises(_Reached):
        transient_response(
            jeffcott(ETA, 0.0, "rotating"),
            SpeedProfile.table([0.0, DURATION], [TOP, 0.0]),
            basis_size=2,
            initial="rest",
            output_step=0.5,
        )
