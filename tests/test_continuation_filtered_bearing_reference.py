"""The continuation's batched Newton step with a magnetic bearing whose law has a state,
against the closed-loop Jeffcott rotor's closed form (mutation hunt 33d).

:func:`flexshaft.analyses.continuation.mode_roots` refines each mode by Newton's method on
``T(s) y = 0``; a law with controller states enters it as ``L(s) − k_a − s E`` (k_a, the law's
basis stiffness, and the collocated E already sit in the modal stiffness and damping). The
rotor: the Jeffcott rotor of tests/jeffcott_bearing.py (disk m at mid-span of a pinned steel
tube of bending stiffness k = 48EI/L³, tests/rotors.py) with its magnetic bearing at the disk
(k_i, k_p, k_d, k_s there), the derivative filtered at f_d = 50 Hz (ω_d = 2π f_d):

    C(s) = k_p + k_d s/(1 + s/ω_d),   f = k_s d − k_i C(s) d   (collocated, ideal amplifier).

Reference (derived): the disk's lateral motion in either plane (isotropic, no spin) obeys

    m s² + k − k_s + k_i C(s) = 0,

times (ω_d + s) the cubic m s³ + ω_d m s² + (k − k_s + k_i (k_p + k_d ω_d)) s
+ ω_d (k − k_s + k_i k_p) = 0, whose root with Im s > 0 (numpy.roots) is the disk mode's; the
third root, −309 rad/s, is the filter's real pole. The continuation starts 1 % off on the
modal shapes of the reduced model's two disk roots (a pair: isotropic) and must come back to
it. (Without the filter the same closed form, m s² + k_i k_d s + k − k_s + k_i k_p, gives
−5 + 325.98i rad/s: the filter moves the root by 0.8 %, and a k_a = k_i k_p − k_s = 3e5 N/m
counted twice by 7 %.)

Tolerance 5e-6 relative: the tube carries 3.5e-6 of the disk's mass (density 0.1 kg/m³), which
moves the root by about half that (measured: 9e-7); Newton stops at 1e-10 |s|.
CPU: one small model, a few ms.
"""

from __future__ import annotations

import math

import numpy as np
from jeffcott_bearing import ACTIVE, KD, KI, KP, KS, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.continuation import mode_roots
from flexshaft.analyses.eigen import candidates, reduce

F_D = 50.0  # Hz
W_D = 2.0 * math.pi * F_D


def test_continuation_with_a_filtered_pd_bearing_gives_the_closed_loop_cubic_root():
    k = K_SHAFT - KS
    roots = np.roots([M_DISK, W_D * M_DISK, k + KI * (KP + KD * W_D), W_D * (k + KI * KP)])
    expected = roots[np.argmax(roots.imag)]  # -2.406 + 328.54i rad/s
    model = model_with(ACTIVE + f"\nderivative_cutoff = {F_D}")
    red = reduce(model, 8)
    assert red.actuators[0].law is not None  # the filtered law has a state: T(s) takes L(s)
    s0, Y0 = candidates(red, 0.0)
    s, _, found = mode_roots(red, 0.0, s0[:2] * (1 + 0.01 - 0.01j), Y0[:, :2])
    assert np.all(found)
    np.testing.assert_allclose(s, [expected, expected], rtol=5e-6)
