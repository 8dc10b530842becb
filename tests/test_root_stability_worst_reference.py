"""The worst unstable root of the every-root check against a hand-built closed loop (derived there).

The rigid rotor on two PID magnetic bearings of tests/test_amb.py, whose lateral plane's closed
loop (10 states: rigid body, integrator, derivative filter, amplifier per bearing) is written out
by hand in ``hand_state_matrix``. With the destabilising integral gain 6e7 A/(m s) of
tests/test_root_stability.py that matrix has two unstable complex pairs, ζ ≈ −0.483 and −0.468
(both planes of the rotor have them). The worst unstable root at that speed
(:meth:`RootStability.worst_at`) is the hand-built root of the smallest ζ = −Re s/|s|, not the
other one; the least-damped root is the same one.

Tolerance 1e-5 relative, as tests/test_root_stability.py for these roots (the FE rotor's
flexibility error ∝ 1/E, measured 6e-6 for this fast pair at E = 2.1e15); the two pairs' ζ differ
by 3 %, their roots by 40 %. One speed, about 0.1 s of CPU.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from test_amb import F_A, F_D, KD, KI, KP, KS, hand_state_matrix, rotor

from flexshaft.analyses.root_stability import root_stability

INTEGRAL = 6.0e7


def test_worst_unstable_root_is_the_hand_built_root_of_least_damping_ratio():
    hand = la.eigvals(hand_state_matrix(integral=INTEGRAL))
    unstable = hand[(hand.real > 0) & (hand.imag > 0)]
    assert unstable.size == 2  # the reference: two unstable pairs of distinct ζ
    zeta = -unstable.real / np.abs(unstable)
    worst = unstable[np.argmin(zeta)]
    assert abs(zeta[0] - zeta[1]) > 0.01
    keys = (
        f"kp = {KP}\nkd = {KD}\nintegral_gain = {INTEGRAL}\nderivative_cutoff = {F_D}\n"
        f"amplifier_bandwidth = {F_A}\nks = {KS}\nki = {KI}"
    )
    result = root_stability(rotor(keys), [0.0])
    root = result.worst_at(0.0)
    assert root is not None and root.kind == "oscillatory"
    assert root.root == pytest.approx(worst, rel=1e-5)
    assert root.damping_ratio == pytest.approx(zeta.min(), rel=1e-4)
    assert result.least_damped[0] == pytest.approx(worst, rel=1e-5)
