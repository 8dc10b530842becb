"""A divergent (real, unstable) root is found behind a controller with states and kept in a
mode list (mutation hunt 46a).

1. A magnetic bearing at the disk of the rotor of tests/jeffcott_bearing.py with a PID law
   (an integrator: controller states) and a negative stiffness k_s = 2 (k + k_i k_p), twice
   what the shaft and the proportional gain hold. The disk's lateral motion (the tube carries
   3.5e-6 of the disk's mass) obeys, per direction,

       m s² + k_i k_d s + (k + k_i k_p − k_s) + k_i k_I / s = 0,
       i.e.  m s³ + k_i k_d s² + (k + k_i k_p − k_s) s + k_i k_I = 0,

   whose largest real root (np.roots of the cubic) is positive: an aperiodic instability. The
   static stiffness k + k_i k_p − k_s is negative, which alone tells the stability that a real
   root may lie in the right half-plane; this case checks the divergence's value, reported at
   every speed, and the onset at the first speed. Tolerance 1e-5
   relative: the tube's mass and flexibility move the disk's root by 8.5e-7 (measured against
   the cubic); the 8-mode basis holds the static shape under the magnet's force.

   The same with a transfer-function law C(s) = k (s² − 2a s + b²)/(s² + 2c s + b²) (complex
   zeros in the right half-plane, a = 0.95 b, c = 0.5 b, b = 300 rad/s), k = 3 k_shaft against
   k_s = 2 k_shaft: statically stiff (k + k_shaft − k_s = 2 k_shaft > 0), C(∞) = C(0) (its
   feedthrough is all the basis stiffness: no channel stiffness is left negative), but on the
   real axis C(s) dips to k/30 at s = b, where the magnet's −k_s wins: the cubic's
   counterpart (m s² + k_shaft − k_s)(s² + 2c s + b²) + k (s² − 2a s + b²) = 0 has two positive
   real roots; the larger is the divergence. Here only the controller's states tell the
   stability that a real root can lie there (mutation h46a-eigen-states-never-diverge).

2. :func:`~flexshaft.analyses.eigen.lowest_modes` keeps a divergent root: eigenvalues of three
   uncoupled single-DOF oscillators m s² + c s + k = 0 (m = 1): k = 100 and 400 with c = 2
   (s = −1 + i√99, −1 + i√399) and k = −25, c = 0 (s = ±5: the divergent +5 and the stable −5,
   which is overdamped). Two modes asked for: the divergent root (Im s = 0: first in damped
   frequency) and the 100-oscillator; the stable real root (ζ = 1, no vibration mode) is left
   out. The function's docstring: a divergent root (Re s > 0) is never overdamped.

CPU: two 4-element models, stability sweeps of two speeds on 8-mode bases: about 0.05 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import K_INT, KD, KI, KP, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.eigen import lowest_modes
from flexshaft.analyses.stability import stability

KS_DIVERGENT = 2 * (K_SHAFT + KI * KP)


def test_a_pid_bearing_too_weak_for_its_magnet_diverges():
    law = f'kind = "active"\nkp = {KP}\nkd = {KD}\nintegral_gain = {K_INT}\nks = {KS_DIVERGENT}\nki = {KI}'
    model = model_with(law)
    roots = np.roots([M_DISK, KI * KD, K_SHAFT + KI * KP - KS_DIVERGENT, KI * K_INT])
    real = roots[np.abs(roots.imag) < 1e-9 * np.abs(roots)].real
    expected = real.max()
    assert expected > 0  # the closed form diverges
    res = stability(model, [0.0, 10.0], n_modes=4, basis_size=8, estimate=False)
    np.testing.assert_allclose(res.divergence, expected, rtol=1e-5)
    assert res.onset_kind == "divergence"
    assert res.onset_speed == 0.0


def test_a_law_with_right_half_plane_zeros_diverges_though_statically_stiff():
    b, a, c = 300.0, 0.95 * 300.0, 0.5 * 300.0
    ks, k = 2 * K_SHAFT, 3 * K_SHAFT
    num, den = [k / KI, -2 * a * k / KI, b * b * k / KI], [1.0, 2 * c, b * b]
    model = model_with(
        f'kind = "active"\nks = {ks}\nki = {KI}\ncontroller = {{ numerator = {num}, denominator = {den} }}'
    )
    roots = np.roots(np.polyadd(np.polymul([M_DISK, 0.0, K_SHAFT - ks], den), KI * np.array(num)))
    expected = roots[np.abs(roots.imag) < 1e-9 * np.abs(roots)].real.max()
    assert expected > 0 and K_SHAFT + k - ks > 0  # diverges, though statically stiff
    res = stability(model, [0.0, 10.0], n_modes=4, basis_size=8, estimate=False)
    np.testing.assert_allclose(res.divergence, expected, rtol=1e-5)
    assert res.onset_kind == "divergence"


def test_a_divergent_root_is_kept_in_the_mode_list():
    s = np.array([5.0 + 0j, -1 + 1j * np.sqrt(99.0), -1 + 1j * np.sqrt(399.0), -5.0 + 0j])
    assert list(lowest_modes(s, 2)) == [0, 1]
    assert list(lowest_modes(s, 3)) == [0, 1, 2]


@pytest.mark.parametrize("n", [1, 2])
def test_the_stable_real_root_comes_after_the_vibration_modes(n):
    s = np.array([-5.0 + 0j, -1 + 1j * np.sqrt(99.0), -1 + 1j * np.sqrt(399.0)])
    assert list(lowest_modes(s, n)) == [1, 2][:n]
