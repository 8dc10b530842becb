"""Without a loss, the every-root check's unstable roots are exact, and say so.

:mod:`flexshaft.analyses.root_stability` marks a root ``refined`` when its loss-consistent value
was solved; the verdict's onset detail (verdict/gather.py) adds "(first-order loss estimate)" to a
root that was not. A model without any loss has no loss to be consistent with: its loss-free
roots are the loss-consistent ones. Until the twenty-fifth session they were all reported
unrefined, so an exact root carried the estimate's label (found by review r54f).

Reference: tests/jeffcott_bearing.py's Jeffcott rotor with a PID bearing at the disk, derivative
gain 0, integral gain K = 3e8 A/(m s), no loss (η = 0, no dashpot). Per lateral direction the
force is −k_i(k_p x + K ∫x) + k_s x, so m x⃛ + (k + k_i k_p − k_s) ẋ + k_i K x = 0 after one
derivative: the characteristic cubic m s³ + (k + k_i k_p − k_s) s + k_i K = 0. With no s² term its
roots sum to zero: one negative real root and a complex pair with a positive real part, unstable
(556.9 ± 1018.2j 1/s), at every speed (the midspan disk does not tilt in its mode, the
near-massless tube's gyroscopic terms are 1e-6 of the disk's inertia). The tube's mass (3.5e-6
of the disk's, tests/rotors.py) moves the pair by about that much: asserted to 1e-5.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import KI, KP, KS, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.root_stability import root_stability

K_INT = 3e8


def test_the_unstable_roots_of_a_lossless_model_are_exact_and_marked_solved():
    law = f'kind = "active"\nkp = {KP}\nkd = 0.0\nintegral_gain = {K_INT}\nks = {KS}\nki = {KI}'
    result = root_stability(model_with(law), [0.0, 100.0])
    cubic = np.roots([M_DISK, 0.0, K_SHAFT + KI * KP - KS, KI * K_INT])
    (pair,) = cubic[cubic.imag > 0]
    assert pair.real > 0
    assert result.onset_speed == 0.0
    assert {r.speed for r in result.unstable} == {0.0, 100.0}
    for r in result.unstable:
        assert r.kind == "oscillatory"
        assert r.root == pytest.approx(pair, rel=1e-5)
        assert r.refined  # exact: no loss to solve for
