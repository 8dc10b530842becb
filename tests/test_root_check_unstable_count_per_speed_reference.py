"""The every-root check's unstable roots, counted speed by speed, against the Jeffcott closed form.

Reference (docs/model.md, *Whirl stability*, Jeffcott rotor: "the two forward roots are s₊ and
`s₋ = −c_e/m − s̄₊`: one frequency ω_d, real parts −(ηω_n + c_e/m)/2 and +(ηω_n − c_e/m)/2 to
first order in η"; also derived in the module docstring of flexshaft.analyses.hysteretic_roots
and in tests/test_damping.py). The Jeffcott rotor of tests/rotors.py (disk mass m, shaft stiffness k,
loss factor η, external damping c_e at the disk) with the rotating-frame loss: the forward
whirl's root below the spin solves the conjugate of ``m s² + c_e s + k(1 + iη) = 0``, i.e. it
is ``s₋ = −c_e/m − s̄₊`` with s₊ the root with Im s > 0 of that quadratic, real part
``(ηω_n − c_e/m)/2`` to first order: unstable once the spin exceeds its frequency Im s₊ ≈ ω_n
when ηω_n > c_e/m. The backward whirl and every root above the spin keep the loss sgn(ω) η > 0
and are stable. At η = 0.02 and c_e/m = 1 /s (ηω_n = 6.0 /s) the rotor has no unstable root at
rest and exactly one, s₋, at each of 1.5 ω_n and 2 ω_n: the count of unstable roots at those
speeds is 1 at each (``RootStability.unstable_counts``: "Unstable roots found at each analysed
speed"), not the running total of the speeds up to it.

Tolerance: the tube's mass (3.5e-6 of the disk's, tests/rotors.py) moves the disk roots from the
lumped closed form: measured 8.5e-7 relative at both speeds (the passive check here ends on the
full 48-DOF basis, whose error estimate is 0); 1e-5 is asserted on s₋. The counts are integers:
no tolerance.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.root_stability import root_stability

ETA, C_E = 0.02, 20.0


def backward_branch_root() -> complex:
    """s₋ = −c_e/m − s̄₊, s₊ the root with Im s > 0 of m s² + c_e s + k(1 + iη) = 0."""
    roots = np.roots([M_DISK, C_E, K_SHAFT * (1 + 1j * ETA)])
    s_plus = complex(roots[np.argmax(roots.imag)])
    return -C_E / M_DISK - s_plus.conjugate()


def test_each_supercritical_speed_counts_its_own_unstable_forward_whirl():
    """Speeds 0, 1.5 ω_n, 2 ω_n: counts (0, 1, 1); each unstable root is s₋ (module docstring)."""
    speeds = np.array([0.0, 1.5 * WN, 2.0 * WN])
    result = root_stability(jeffcott(ETA, C_E), speeds)
    want = backward_branch_root()
    assert want.real == pytest.approx((ETA * WN - C_E / M_DISK) / 2, rel=1e-3)  # the first-order form
    assert list(result.unstable_counts) == [0, 1, 1]
    assert len(result.unstable) == 2
    for root, speed in zip(result.unstable, speeds[1:]):
        assert root.speed == speed
        assert root.root == pytest.approx(want, rel=1e-5)
