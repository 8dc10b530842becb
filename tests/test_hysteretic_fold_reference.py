"""A mode in a fold of the hysteretic problem: its two consistent eigenvalues, and the one kept.

Reference (tests/test_damping.py derives it): the Jeffcott rotor's forward whirl with the
rotating-frame loss solves ``m s² + c_e s + k(1 + iησ) = 0``, σ = sgn(ω − Ω). The σ = −1
equation is the conjugate of the σ = +1 one, whose roots sum to −c_e/m, so the two branch roots
are s₊ and ``s₋ = −c_e/m − s̄₊``: one damped frequency ω_d, real parts
``Re s₊ = −(ηω_n + c_e/m)/2`` and ``Re s₋ = +(ηω_n − c_e/m)/2`` (to first order in η). At the
synchronous speed Ω = ω_d both lie on their own side of the line (σ = 0 is in [−1, 1]): the mode
has two eigenvalues, and the continuation must keep the **less stable**, s₋, whichever of the
two it starts from (the verdict may not depend on which of two valid eigenvalues a continuation reached,
:func:`~flexshaft.analyses.continuation.mode_root`).

The model's ω_d differs from the closed form's by about 1e-6 (the tube's mass, 7e-6 of the
disk's), more than the synchronous band (1e-9), so the fold speed is the model's own: the
frequency of its lower-branch forward root, iterated to a fixed point (it moves with Ω only
through the tube's tiny gyroscopic matrix). The real parts are compared with the closed form to
1e-4 relative (as tests/test_damping.py); the two candidates differ by 6 s⁻¹ in Re s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.continuation import mode_root
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import branch_roots, branches, consistent_roots

ETA = 0.02
C_E = 2 * 0.003 * M_DISK * WN


def test_a_mode_in_a_fold_keeps_its_less_stable_eigenvalue():
    red = reduce(jeffcott(ETA, C_E), 12)
    roots = np.roots([M_DISK, C_E, K_SHAFT * (1 + 1j * ETA)])
    s_plus = roots[np.argmax(roots.imag)]  # σ = +1: above the line, the stable forward root
    s_minus = -C_E / M_DISK - np.conj(s_plus)  # σ = −1: below it, destabilised by the loss
    speed = s_minus.imag
    for _ in range(4):  # the model's fold speed: its lower-branch forward root's frequency
        lower = branches(red, speed)[0]
        s, Y = branch_roots(red, speed, lower.weights)
        k = int(np.argmin(np.abs(s - complex(s_minus.real, speed))))
        speed = s[k].imag
    found, _ = consistent_roots(red, speed)
    for target in (s_plus.real, s_minus.real):  # a fold: both forward roots are eigenvalues
        assert np.min(np.abs(found - complex(target, speed))) <= 1e-4 * abs(s_plus)
    upper = branches(red, speed)[1]
    s_up, Y_up = branch_roots(red, speed, upper.weights)
    j = int(np.argmin(np.abs(s_up - complex(s_plus.real, speed))))
    # from either of the two eigenvalues: from the stable one, Newton's method on the lower branch
    # reaches the backward whirl (2.6e-6 rad/s away, no gyroscopic split), not this mode's root
    for start, vector in ((s[k], Y[:, k]), (s_up[j], Y_up[:, j])):
        root, _, ok = mode_root(red, speed, start, vector)
        assert ok
        assert root.real == pytest.approx(s_minus.real, rel=1e-4)
        assert root.real == pytest.approx((ETA * WN - C_E / M_DISK) / 2, rel=1e-3)  # first order in η
