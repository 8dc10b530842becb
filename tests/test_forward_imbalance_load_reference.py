"""The imbalance load rotates forward in every path of the synchronous response: the banded
sweep, the projected spin-up scan and the projected peak model, against the Jeffcott rotor's
closed form with rotating internal damping.

Reference (closed form). The Jeffcott-like rotor of tests/rotors.py (a disk of mass m at the
middle of a near-massless pinned-pinned tube, k = 48EI/L³, a dashpot c_e at the disk) with a
rotating loss factor η of the shaft material obeys, in complex coordinates r = v + i w at the
disk, ``m r̈ + c_e ṙ + k(1 + iη sgn(ω − Ω)) r = f`` for a whirl r ∝ e^{iωt} (η acts in the
rotating frame, at the frequency ω − Ω there). An imbalance force turns with the shaft:
``Q_v = 1, Q_w = −i`` per Ω² (v = cos Ωt, w = sin Ωt: from v towards w, the spin's sense), a
forward whirl at ω = Ω, seen by the rotating shaft as a static bend, so the loss drops out:

    |r| = Ω² / |k − mΩ² + i c_e Ω|            (forward, independent of η)

whereas the conjugate load (Q_w = +i, a backward turning force, ω = −Ω in complex
coordinates, cycled at −2Ω in the rotating frame) would give ``Ω²/|k(1 − iη) − mΩ² − i c_e Ω|``,
which with η = 0.2 is a factor up to 6 smaller near ω_n ((η + 2ζ)/(2ζ) = 0.24/0.04 at ω_n).
The orbit's major semi-axis of a circular whirl is |r|.

Tolerance 1e-4 relative: the tube's own mass (3.5e-6 of the disk's, tests/rotors.py) moves the
response by 2.1e-5 relative at ζ = 0.02 (measured; the same allowance as
tests/test_orbit_amplitude.py); the backward mistake is at least 1e-2 at every speed asserted.
"""

from __future__ import annotations

import numpy as np
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.peak_projection import ProjectedOrbit
from flexshaft.analyses.response import imbalance_response, orbit_amplitude
from flexshaft.analyses.sweep_projection import imbalance_sweep

ZETA, ETA = 0.02, 0.2
C_E = 2 * ZETA * np.sqrt(K_SHAFT * M_DISK)
SPEEDS = np.linspace(0.5, 1.5, 41) * WN  # 41 >= the sweep's smallest projected scan (40)


def _setup():
    model = jeffcott(ETA, C_E)
    v, w = disk_dofs(model)
    Q = np.zeros((model.dofs.size, 1), complex)
    Q[v, 0], Q[w, 0] = 1.0, -1j  # forward: v = cos Ωt, w = sin Ωt
    return model, v, w, Q


def _forward(s):
    return s * s / np.abs(K_SHAFT - M_DISK * s * s + 1j * C_E * s)


def _backward(s):
    return s * s / np.abs(K_SHAFT * (1 - 1j * ETA) - M_DISK * s * s - 1j * C_E * s)


def test_the_forward_and_backward_closed_forms_differ_where_asserted():
    assert np.all(np.abs(_backward(SPEEDS) / _forward(SPEEDS) - 1) > 1e-2)


def test_banded_imbalance_response_whirls_forward_undamped_by_the_rotating_loss():
    model, v, w, Q = _setup()
    q = np.asarray(imbalance_response(model, SPEEDS, Q))
    np.testing.assert_allclose(orbit_amplitude(q[v, 0], q[w, 0]), _forward(SPEEDS), rtol=1e-4)


def test_projected_spinup_scan_whirls_forward_and_is_synchronous():
    model, v, w, Q = _setup()
    sweep = imbalance_sweep(model, SPEEDS, Q)
    assert sweep.basis_size > 0  # the projected path, not the all-full fallback
    q = np.asarray(sweep.response)
    np.testing.assert_allclose(orbit_amplitude(q[v, 0], q[w, 0]), _forward(SPEEDS), rtol=1e-4)
    # synchronous: excited at ω = Ω, at the spin speed Ω of the scan
    np.testing.assert_array_equal(sweep.response.frequencies, SPEEDS)
    np.testing.assert_array_equal(sweep.response.spin_speeds, SPEEDS)


def test_projected_peak_model_whirls_forward():
    model, v, w, Q = _setup()
    near = SPEEDS[15:26]  # across ω_n (sample 20)
    orbit = ProjectedOrbit(model, Q[:, 0], (v, w), near[3:8])
    np.testing.assert_allclose(orbit(near), _forward(near), rtol=1e-4)
    # the projected model alone (no full solve), between the starting speeds
    between = 0.5 * (near[4:7] + near[5:8])
    np.testing.assert_allclose(orbit.projected(between), _forward(between), rtol=1e-4)
