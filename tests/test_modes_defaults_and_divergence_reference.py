"""``modes()``: its damped default, a divergent root of an open-loop-unstable magnet, and the
modes nearest a frequency, against closed forms (mutation hunt h35a).

1. Default ``damped=True``. tests/rotors.py's Jeffcott rotor (20 kg disk at midspan of a
   near-massless pinned-pinned tube, k = 48EI/L³) with a dashpot c_e at the disk, no loss:
   the disk obeys m s² + c_e s + k = 0, so s = −c_e/(2m) + i√(k/m − (c_e/2m)²) with ζ = 0.2
   (derived; the undamped problem would give s = i√(k/m)). Tolerance 1e-5 relative: the tube's
   3.5e-6 share of the disk's mass (measured 8.8e-7).

2. A divergent root. tests/jeffcott_bearing.py's rotor with a magnetic bearing at the disk
   whose negative stiffness k_s = 4e6 N/m beats the tube and the law's static stiffness
   k_i k_p = 5e5 N/m. Without damping (``damped=False``: the law's static stiffness stays,
   its k_d goes) the disk obeys m s² + (k + k_i k_p − k_s) = 0: a real root
   s = √((k_s − k_i k_p − k)/m) ≈ 289 1/s in each plane, a pair, first among the modes
   (Modes' docstring). With the law's damping k_i k_d it is the positive root of
   m s² + k_i k_d s + (k + k_i k_p − k_s) = 0. The estimated error of a divergent root is NaN
   (Modes.error_estimate's docstring: the estimate is of an oscillatory root). Tolerance 1e-5
   relative (the tube's mass: measured 9e-7).

3. ``Modes.nearest(f)`` picks by damped frequency Im s/2π (its docstring). Two hand-typed roots:
   a heavily damped one, ω_n = 2π·10 rad/s, ζ = 0.6 (f_d = 8 Hz, |s|/2π = 10 Hz) and an
   undamped one at 9.5 Hz: the one nearest 10 Hz is the second (0.5 Hz away against 2 Hz),
   though |s|/2π of the first is exactly 10 Hz.

CPU: two 4- and 8-element models, about 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK, jeffcott

from flexshaft.analyses.modal import Modes, modes

ZETA = 0.2
C_E = 2 * ZETA * np.sqrt(K_SHAFT * M_DISK)
KI, KP, KD, KS = 100.0, 5.0e3, 2.0, 4.0e6  # N/A, A/m, A s/m, N/m: k_s beats k + k_i k_p
MAGNET = f'kind = "active"\nkp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}'


def test_modes_are_damped_by_default():
    m = modes(jeffcott(0.0, C_E), n_modes=2)
    a = C_E / (2 * M_DISK)
    s = complex(-a, np.sqrt(K_SHAFT / M_DISK - a * a))
    assert m.eigenvalues == pytest.approx([s, s], rel=1e-5)
    assert m.damping_ratios == pytest.approx([ZETA, ZETA], rel=1e-5)


@pytest.fixture(scope="module")
def magnet():
    return model_with(MAGNET)


def test_an_undamped_divergent_pair_comes_first(magnet):
    m = modes(magnet, n_modes=4, damped=False)
    s = np.sqrt((KS - KI * KP - K_SHAFT) / M_DISK)
    assert list(m.divergent) == [True, True, False, False]
    assert m.eigenvalues[:2] == pytest.approx([s, s], rel=1e-5)
    assert np.all(m.eigenvalues[2:].imag > 0)


def test_a_divergent_root_has_no_error_estimate(magnet):
    m = modes(magnet, n_modes=4)
    c, k = KI * KD, K_SHAFT + KI * KP - KS
    s = (-c + np.sqrt(c * c - 4 * M_DISK * k)) / (2 * M_DISK)
    assert m.eigenvalues[:2] == pytest.approx([s, s], rel=1e-5)
    assert np.all(np.isnan(m.error_estimate[:2]))
    assert np.all(np.isfinite(m.error_estimate[2:]))


def test_nearest_modes_by_damped_frequency():
    wn, zeta = 2 * np.pi * 10.0, 0.6
    s = np.array([-zeta * wn + 1j * wn * np.sqrt(1 - zeta**2), 2j * np.pi * 9.5])
    m = Modes(0.0, s, None, None, None, None, None, None, None)
    assert m.frequencies == pytest.approx([8.0, 9.5], rel=1e-12)
    assert m.undamped_frequencies[0] == pytest.approx(10.0, rel=1e-12)
    assert list(m.nearest(10.0, n=1)) == [1]
    assert list(m.nearest(7.0, n=1)) == [0]
