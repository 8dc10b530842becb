"""The projected spin-up sweep (:mod:`flexshaft.analyses.sweep_projection`) on the Jeffcott rotor.

Reference (closed form): the Jeffcott rotor of tests/rotors.py (a 20 kg midspan disk on a
near-massless pinned-pinned tube, k = 48 E I/L³, a dashpot c at the disk, no loss) under a
forward rotating imbalance U Ω² at the disk, Q₁ = U (1, −i) on (v, w), whirls in a forward
circle, v = U Ω²/(k − mΩ² + icΩ), w = −i v (the tube's own modes are far above: its mass,
3.5e-6 of the disk's, changes the answer by about that, so rtol 1e-4).

The scan's rules (module docstring): a scan of fewer than ``_SMALLEST_SCAN`` = 40 speeds is
solved in full; from 40 speeds on the greedy basis is tried, and on this rotor, whose response
lies in one shape at every speed, the 13 initial full solves span it: the scan is accepted
without a round and the other 27 speeds come from the reduced model, with an error estimate
of 0 where solved in full. ζ = 0.05, speeds over 0.5-1.5 ω_n. CPU: about 50 ms.
"""

from __future__ import annotations

import numpy as np
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.sweep_projection import imbalance_sweep

U = 1e-4  # imbalance [kg m]


def _scan(n: int):
    c = 2 * 0.05 * np.sqrt(K_SHAFT * M_DISK)
    model = jeffcott(0.0, c)
    v, w = disk_dofs(model)
    loads = np.zeros((model.dofs.size, 1), complex)
    loads[v, 0], loads[w, 0] = U, -1j * U
    speeds = np.linspace(0.5, 1.5, n) * WN
    expected = U * speeds**2 / (K_SHAFT - M_DISK * speeds**2 + 1j * c * speeds)
    sweep = imbalance_sweep(model, speeds, loads)
    q = np.asarray(sweep.response)
    return sweep, q[v, 0], q[w, 0], expected


def test_from_forty_speeds_the_scan_is_projected_and_matches_the_closed_form():
    sweep, v, w, expected = _scan(40)
    assert sweep.basis_size >= 1 and 13 <= sweep.full_solves < 40
    assert sweep.rounds == 0 and sweep.full_solves == 13  # accepted on the initial solves alone
    np.testing.assert_allclose(v, expected, rtol=1e-4)
    np.testing.assert_allclose(w, -1j * expected, rtol=1e-4)
    assert np.all(sweep.error_estimate[sweep.full] == 0.0)
    assert sweep.error_estimate.max() <= 1e-8


def test_below_forty_speeds_every_speed_is_solved_in_full():
    sweep, v, _, expected = _scan(39)
    assert sweep.full.all() and sweep.basis_size == 0
    np.testing.assert_allclose(v, expected, rtol=1e-4)
