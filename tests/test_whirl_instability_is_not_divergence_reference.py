"""An oscillatory whirl instability is a whirl root, not a divergence (a real root s > 0).

Reference (tests/test_stability.py's closed form, derived there): the Jeffcott rotor of
tests/rotors.py (a 20 kg disk at the middle of a near-massless pinned-pinned tube, k = 48EI/L³,
ω_n = √(k/m) = 302.1 rad/s) with an external dashpot c_e at the disk and the viscous (Zorzi-Nelson)
rotating internal damping c_i = η k/ω_ref, ω_ref = ω_n. In complex coordinates r = v + iw the
forward whirl obeys

    m s² + (c_e + c_i) s + k − iΩ c_i = 0,

and the backward whirl is the conjugate of that equation's other root. Above the onset
Ω_s = ω_n (1 + c_e/c_i) the forward whirl's Re s > 0: with η = 0.1 and ζ_e = 0.01
(c_e = 2 ζ_e m ω_n) the onset is 1.2 ω_n; at Ω = 2 ω_n the forward root is
s = 11.99 + 303.10i rad/s, an oscillatory instability (a growing whirl at about ω_n), and the
backward one −48.25 + 303.10i is stable. The state matrix is real: its roots are s and s̄, a
conjugate pair with Re s > 0 and Im s = ±303 rad/s, never a real root. So the spectrum holds no
divergent (aperiodic) root at all: the unstable pair belongs with the whirl roots (Im s > 0),
once, with the closed-form value.

Tolerance 1e-5 of |s| on each whirl root: the closed form leaves out the tube's mass (3.5e-6 of
the disk's, rotors.py), which moves the roots by about 1e-6 relative (measured 8.7e-7 on Im s,
1.7e-8 of |s| on Re s). The forward root's Re s = 11.99 rad/s is 4e5 times that bar's
3e-3 rad/s, and 13 times the divergence threshold (DIVERGENCE_TOLERANCE × the 4-mode basis's
top frequency, 1e-6 × 9.1e5 rad/s = 0.91 1/s): counting every root with Re s > 0 as divergent
reports the pair as two divergent roots s = 11.99 1/s, far above the threshold on any basis.
"""

from __future__ import annotations

import numpy as np
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.eigen import DIVERGENCE_TOLERANCE, divergent_roots, reduce, spectrum
from flexshaft.analyses.loss import viscous_equivalent

ETA, ZETA_E = 0.1, 0.01
C_E = 2 * ZETA_E * M_DISK * WN  # N s/m
C_I = ETA * K_SHAFT / WN  # N s/m, ω_ref = ω_n
SPEED = 2.0 * WN  # rad/s, above the onset ω_n (1 + c_e/c_i) = 1.2 ω_n


def test_an_unstable_forward_whirl_is_an_oscillatory_root_and_not_a_divergence():
    assert SPEED > WN * (1 + C_E / C_I)
    closed = np.roots([M_DISK, C_E + C_I, K_SHAFT - 1j * SPEED * C_I])
    forward = closed[np.argmax(closed.real)]  # Re s > 0, Im s > 0
    backward = np.conj(closed[np.argmin(closed.real)])  # stable, Im s > 0
    assert forward.real > 0 and forward.imag > 0 and backward.real < 0
    red = reduce(jeffcott(ETA, C_E), 4)
    weights = viscous_equivalent(WN, SPEED)
    s, _, Y_div, s_div = spectrum(red, SPEED, weights)
    threshold = DIVERGENCE_TOLERANCE * np.sqrt(red.w2.max())
    assert forward.real > 10 * threshold  # a wrongly counted divergence would not hide under it
    # no divergent (aperiodic) root: the unstable pair is oscillatory
    assert s_div.size == 0 and Y_div.shape[1] == 0
    assert divergent_roots(red, SPEED, weights).size == 0
    # the unstable root is a whirl root, once, with the closed-form value
    unstable = s[s.real > 0]
    assert unstable.size == 1
    assert abs(unstable[0] - forward) <= 1e-5 * abs(forward)
    assert np.min(np.abs(s - backward)) <= 1e-5 * abs(backward)
