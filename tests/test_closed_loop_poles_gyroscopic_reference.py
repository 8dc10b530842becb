"""The loss-free closed-loop poles at a speed carry the gyroscopic split of the tilt whirl.

Reference (derived here). The near-rigid rotor of tests/test_amb.py (a steel-like tube with
E = 2.1e15 Pa and a central disk, held only by two collocated PD magnetic bearings at ±l from
the centre, l = 0.4 m) has, per bearing, the stiffness k = k_i K_p − k_s and damping
c = k_i K_d. Its translation obeys m s² + 2c s + 2k = 0 in each plane, unchanged by the spin.
Its tilt, in the complex coordinate φ = θ_v + iθ_w, obeys

    I_t φ̈ + (2c l² ∓ iΩ I_p) φ̇ + 2k l² φ = 0,

so the roots with Im s > 0 of the real closed loop are those of the two quadratics
I_t s² + (2c l² ∓ iΩ I_p) s + 2k l² = 0 (numpy.roots), one forward and one backward whirl
root, which split apart with the speed (at rest both are the roots of I_t s² + 2c l² s + 2k l²).
m = ρAL + m_d, I_t = ρAL³/12 + ρIL + I_d (tests/test_amb.py) and I_p = 2ρIL + I_p,d (the
tube's polar inertia, its section's polar moment 2I, and the disk's).

At Ω = 300 rad/s the two tilt roots are 301.7 and 434.6 rad/s in frequency against 361.9 at
rest, 17-20 % away, so poles solved at the wrong speed miss them by 1e4 times the tolerance.
Tolerance: the FE rotor's flexibility leaves 1e-6 (tests/test_amb.py; measured here 9e-7 on
the translation roots, 5e-7 on the tilt roots); 5e-6 is asserted. One dense eigen-solution
of 96 states, a few hundredths of a second.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_amb import HALF_SPAN, I_T, INERTIA, IP_DISK, KI, KS, MASS, RHO, L, rotor

from flexshaft.analyses.root_stability import closed_loop_poles

KP, KD = 1.5e4, 10.0  # A/m, A s/m: k = 1e6 N/m, c = 1e3 N s/m per bearing (underdamped)
IP = IP_DISK + 2 * RHO * INERTIA * L
SPEED = 300.0  # rad/s


def upper(coefficients) -> list[complex]:
    return [complex(s) for s in np.roots(coefficients) if s.imag > 0]


def test_closed_loop_poles_hold_the_forward_and_backward_tilt_roots_at_the_speed():
    k, c = KI * KP - KS, KI * KD
    translation = upper([MASS, 2 * c, 2 * k])
    tilt = [
        s
        for sign in (-1.0, 1.0)
        for s in upper([I_T, 2 * c * HALF_SPAN**2 + sign * 1j * SPEED * IP, 2 * k * HALF_SPAN**2])
    ]
    rest = upper([I_T, 2 * c * HALF_SPAN**2, 2 * k * HALF_SPAN**2])
    assert len(translation) == 1 and len(tilt) == 2 and len(rest) == 1
    assert min(abs(s - rest[0]) for s in tilt) > 0.1 * abs(rest[0])  # the split is large
    poles = closed_loop_poles(rotor(f"kp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}"), SPEED)
    assert np.all(poles.imag > 0)
    for s in (*translation, *tilt):
        assert complex(poles[np.argmin(np.abs(poles - s))]) == pytest.approx(s, rel=5e-6)
