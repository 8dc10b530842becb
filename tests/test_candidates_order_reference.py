"""The oscillatory roots of :func:`flexshaft.analyses.eigen.candidates` in increasing |s|, on an
anisotropic Jeffcott rotor whose heavily damped direction has the larger |s| but the lower
damped frequency (mutation hunt h52d).

The rotor of tests/jeffcott_bearing.py (20 kg disk at midspan of a near-massless tube, lateral
stiffness k = 48EI/L³ there) with a contact bearing at the disk: stiffness 2e6 N/m and a
dashpot of damping ratio 0.9 in v, no stiffness and a light dashpot in w. At rest the two
directions decouple (no gyroscopic term) and each is a single degree of freedom, derived here:

    m s² + c_v s + (k + k_b) = 0,     m s² + c_w s + k = 0,

|s_v| = √((k + k_b)/m) = 437 rad/s with Im s_v = 0.44 |s_v| = 191 rad/s, and s_w of
|s_w| = √(k/m) = 302 rad/s, Im s_w ≈ |s_w|. The documented order of candidates (its
docstring: "sorted by |s|") puts s_w first; an order by damped frequency would put s_v first.

Tolerance 1e-5 relative: the tube carries 3.5e-6 of the disk's mass and its own modes lie
orders of magnitude higher (the 8-mode basis holds the disk's static shapes).

CPU: one 4-element model and a 16 × 16 eig, milliseconds.
"""

from __future__ import annotations

import numpy as np
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.eigen import candidates, reduce

KB_V = 2.0e6  # N/m
C_V = 2 * 0.9 * np.sqrt((K_SHAFT + KB_V) * M_DISK)  # N s/m: damping ratio 0.9
C_W = 100.0  # N s/m


def _root(c: float, k: float) -> complex:
    roots = np.roots([M_DISK, c, k])
    return complex(roots[np.argmax(roots.imag)])


def test_candidates_come_in_increasing_modulus():
    model = model_with(f'kind = "contact"\nstiffness = {{ v = {KB_V}, w = 0.0 }}\ndamping = {{ v = {C_V}, w = {C_W} }}')
    s_v, s_w = _root(C_V, K_SHAFT + KB_V), _root(C_W, K_SHAFT)
    assert s_v.imag < s_w.imag < abs(s_w) < abs(s_v)  # the two orders differ
    s, Y = candidates(reduce(model, 8), 0.0)
    assert np.all(np.diff(np.abs(s)) >= 0)
    np.testing.assert_allclose(s[:2], [s_w, s_v], rtol=1e-5)
    assert Y.shape == (8, s.size)
