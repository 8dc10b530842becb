"""A run-down that starts above the whirl onset and leaves it is integrated, not refused.

Documented rule (docs/limits.md, section 6, hand-written): the run-up "refuses, before
integrating, ... a dwell at a speed where the system is unstable long enough for a free whirl
to grow more than ``MAX_GROWTH`` = 1e3-fold", and "while integrating it refuses a free whirl
grown 1e3-fold". Only a dwell (a segment held at one speed) is judged before integrating; a
ramp through unstable speeds is left to the integrator, which meets the growth step by step.

Rotor and growth rate as in tests/test_runup_unstable_dwell_reference.py: the Jeffcott disk of
tests/rotors.py with a rotating-frame loss factor η = 0.02 and no external damping; its causal
loss D = kη/(ω_n + Ω) on the velocity relative to the spin gives the forward whirl the exact
root of m s² + D (s − iΩ) + k = 0 and, to first order in D, the growth rate (derived: s = iω_n
+ δ, 2imω_nδ + D(iω_n − iΩ) = 0)

    Re s = η ω_n (Ω − ω_n) / (2 (ω_n + Ω)),

positive only above ω_n, rising with Ω, and η ω_n / 6 (= 1.0071 1/s; the exact root's 1.00711
1/s) at the top speed Ω = 2 ω_n. A run-down from 2 ω_n to rest in 10 s spends 5 s above ω_n,
so a free whirl grows at most e^{5 × 1.0071} = e^{5.04}-fold over it, below MAX_GROWTH = 1e3
= e^{6.91}: the run is integrated and returned (measured: 60 steps, none rejected, no
refusal). Counting the whole 10 s ramp at the start speed's rate would give e^{10}: a refusal.

The run's ``max_growth_rate`` (largest Re λ at its reference speeds, the top one among them)
is the exact root's real part at 2 ω_n, to 1e-5 relative: the root is well conditioned (a
simple root, Re s changes by ~1e-14 |s| under round-off) and the model differs from the
two-parameter quadratic only by the tube's mass, 3.5e-6 of the disk's, and its polar inertia
(measured 2.8e-7). The first-order form agrees with the exact root to 1e-4: the terms it drops
are O((D/(m ω_n))²) = (η/3)² = 4.4e-5 relative at 2 ω_n (measured 3.3e-5).

CPU: one Jeffcott build, a two-mode setup and a 60-step integration, about 0.06 s (0.3 s on a
first call, which loads the modules).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.envelope import MAX_GROWTH
from flexshaft.analyses.transient import SpeedProfile, transient_response

ETA = 0.02
TOP = 2.0 * WN
DURATION = 10.0


def test_a_rundown_through_the_unstable_range_is_integrated():
    D = K_SHAFT * ETA / (WN + TOP)
    rate = np.roots([M_DISK, D, K_SHAFT - 1j * D * TOP]).real.max()
    assert rate == pytest.approx(ETA * WN / 6, rel=1e-4)
    above = DURATION * (TOP - WN) / TOP  # time spent above the onset ω_n
    assert above * rate < np.log(MAX_GROWTH) < DURATION * rate  # the ramp is fine; its length at top rate is not
    run = transient_response(
        jeffcott(ETA, 0.0, "rotating"),
        SpeedProfile.table([0.0, DURATION], [TOP, 0.0]),
        basis_size=2,
        initial="rest",
        output_step=0.5,
    )
    assert run.steps > 0
    assert run.time[-1] == pytest.approx(DURATION)
    assert run.max_growth_rate == pytest.approx(rate, rel=1e-5)
