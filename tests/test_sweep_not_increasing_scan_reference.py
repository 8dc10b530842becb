"""A scan not in increasing speed order is solved in full, and matches the Jeffcott closed form.

The documented rule (module docstring of :mod:`flexshaft.analyses.sweep_projection`, API
contract): "a scan of fewer than ``_SMALLEST_SCAN`` speeds, or one not increasing, is solved in
full". So a 60-speed run-down (decreasing) and a shuffled scan report every speed solved in full
and no reduced basis (``full``, ``full_solves``, ``basis_size``). The values agree either way: a
not-increasing scan sent through the projection gives the same responses to 5e-13 of the peak
(4.7e-13 and 4.8e-13 measured on these two scans), so only that bookkeeping tells the two
paths apart; the values are checked below against the closed form all the same.

Reference (closed form) for the values: the Jeffcott rotor of tests/rotors.py (20 kg midspan
disk on a near-massless pinned-pinned tube, k = 48 E I/L³, dashpot c at the disk for ζ = 0.05)
under the forward imbalance U Ω² at the disk, Q₁ = U (1, −i), whirls in a forward circle,
v = U Ω²/(k − mΩ² + icΩ) (the steady amplitude e (Ω/ω_n)²/√((1 − (Ω/ω_n)²)² + (2ζΩ/ω_n)²) with
e = U/m); the tube's mass, 3.5e-6 of the disk's, moves it by about that: rtol 1e-4, as
tests/test_sweep_projection_jeffcott_reference.py. CPU: tens of milliseconds.
"""

from __future__ import annotations

import numpy as np
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.sweep_projection import imbalance_sweep

U = 1e-4  # imbalance [kg m]
ZETA = 0.05


def _check(speeds):
    c = 2 * ZETA * np.sqrt(K_SHAFT * M_DISK)
    model = jeffcott(0.0, c)
    v, w = disk_dofs(model)
    loads = np.zeros((model.dofs.size, 1), complex)
    loads[v, 0], loads[w, 0] = U, -1j * U
    sweep = imbalance_sweep(model, speeds, loads)
    assert sweep.full.all() and sweep.full_solves == speeds.size and sweep.basis_size == 0
    q = np.asarray(sweep.response)
    r = speeds / WN
    e = U / M_DISK
    amplitude = e * r**2 / np.sqrt((1 - r**2) ** 2 + (2 * ZETA * r) ** 2)
    np.testing.assert_allclose(np.abs(q[v, 0]), amplitude, rtol=1e-4)
    expected = U * speeds**2 / (K_SHAFT - M_DISK * speeds**2 + 1j * c * speeds)  # with its phase
    np.testing.assert_allclose(q[v, 0], expected, rtol=1e-4)
    np.testing.assert_allclose(q[w, 0], -1j * expected, rtol=1e-4)  # forward circle


def test_a_run_down_scan_is_solved_in_full():
    _check(np.linspace(1.5, 0.5, 60) * WN)


def test_a_shuffled_scan_is_solved_in_full():
    _check(np.random.default_rng(3).permutation(np.linspace(0.5, 1.5, 60)) * WN)
