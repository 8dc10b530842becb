"""A spin speed given as one number is a one-speed sweep: the imbalance response at a scalar Ω
equals the Jeffcott rotor's closed form at that speed.

The rule: ``imbalance_response`` takes ``speeds : array_like``, and numpy's glossary defines an
array_like as anything ``numpy.array`` accepts, scalars included (a 0-d array); the guard turns
it into a 1-D float array. Reference (closed form, as in tests/test_forward_imbalance_load_reference.py): the
Jeffcott-like rotor of tests/rotors.py (disk m at midspan of a near-massless pinned-pinned tube,
k = 48EI/L³, a dashpot c_e at the disk, rotating loss η) under the forward imbalance load
``Q_v = 1, Q_w = −i`` per Ω² whirls at

    |r| = Ω² / |k − mΩ² + i c_e Ω|         (the rotating loss drops out of a forward whirl),

at Ω = 0.8 ω_n with ζ = 0.02 and k = m ω_n²: |r| = 0.64/(m |1 − 0.64 + 2ζ·0.8 i|)
= 0.64/(m |0.36 + 0.032 i|) = 1.7708/m per unit imbalance. Tolerance 1e-4 relative: the tube's own mass
(3.5e-6 of the disk's) moves the response by about 2e-5 (tests/rotors.py). About 50 ms.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.response import imbalance_response, orbit_amplitude

ZETA, ETA = 0.02, 0.2
C_E = 2 * ZETA * np.sqrt(K_SHAFT * M_DISK)
SPEED = 0.8 * WN


def test_a_scalar_speed_is_a_one_speed_sweep_on_the_closed_form():
    model = jeffcott(ETA, C_E)
    v, w = disk_dofs(model)
    Q = np.zeros((model.dofs.size, 1), complex)
    Q[v, 0], Q[w, 0] = 1.0, -1j
    response = imbalance_response(model, float(SPEED), Q)
    q = np.asarray(response)
    assert q.shape == (model.dofs.size, 1, 1)
    np.testing.assert_array_equal(response.spin_speeds, [SPEED])
    expected = SPEED**2 / abs(K_SHAFT - M_DISK * SPEED**2 + 1j * C_E * SPEED)
    # by hand: 0.64 / (0.36 + 0.032 i) / M_DISK in units of the disk's mass
    # by hand; only rounding separates the two (k - m (0.8 w_n)^2 with w_n^2 = k/m), hence 1e-12
    assert expected * M_DISK == pytest.approx(0.64 / abs(0.36 + 0.032j), rel=1e-12)
    np.testing.assert_allclose(orbit_amplitude(q[v, 0, 0], q[w, 0, 0]), expected, rtol=1e-4)
