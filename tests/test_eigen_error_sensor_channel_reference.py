"""The eigenvalue error estimate of a non-collocated PD magnet, and of a basis holding rigid-body modes (hunt h39a).

References.

1. A non-collocated channel. The rotor of tests/jeffcott_bearing.py with a steel tube (density
   7800 kg/m³: the tube's mass couples the disk's mode to the higher ones) and, at the disk, a
   magnetic bearing whose sensor is 0.125 m further on, ideal PD law i = −(k_p + k_d s) d_s:
   the full closed loop on every free DOF is, as derived in
   tests/test_eigen_newton_and_sensor_reference.py from the linearised magnet f = k_s d_a + k_i i,

       [M s² + (C + ΩG + k_i k_d B_aᵀB_s) s + K + k_i k_p B_aᵀB_s − k_s B_aᵀB_a] q = 0,

   solved here as a dense pencil of its first-order form at Ω = 300 rad/s. On a 4-mode basis the
   disk's two roots err by 5e-6 and 6e-6 relative; the estimate δ of eigenvalue_corrections must
   be s* − s to first order: within 3 times its neglected terms, (|s|/ω_c)⁴ + |s* − s|/gap
   (the bar of tests/test_eigen_error_reference.py; ω_c the lowest undamped frequency left out,
   gap the distance to the next full root), 0.03 of |s* − s| here (measured: 1e-5). The same
   with the tube's twist free at both ends (a rigid-body twist, ω² = 0, in a 5-mode basis).

2. Rigid-body modes in the basis. The estimate removes the basis part of K_σ⁻¹ r with
   (Λ + σ)⁻¹ (σ = 1 rad²/s², the shift that keeps K_σ regular); the Galerkin condition makes
   that part round-off, but a basis mode with ω² = 0 (a free rigid-body motion) must not turn
   it into 1/0. The rigid rotor of tests/test_amb.py (steel shaft, E = 2.1e11) held only by its
   two PID magnets with k_p = 0: the basis stiffness K_p is zero, so the rotor's lateral
   translations and tilts are free in the basis (ω² within 3e-7 of 0), while the closed loop
   holds them through the integral and derivative paths. Reference: each full root by Newton's
   method on the dense T(s) = s²M + s(ΩG + C) + K + Σ B_aᵀ(G_a(s) − k_s)B_a (the model's
   controller matrix, as tests/test_eigen_error_reference.py does for this rotor with k_p > 0),
   at 300 rad/s, started from the reduced root of an 8-mode basis. Three of its four lowest
   roots err by 8e-5 to 2e-3 relative (the fourth, 4e-11, is at Newton's round-off and left
   out); δ must be s* − s to 1 %: the neglected terms' bar of test 1 needs the gap to the
   nearest other full root, which is not known here, and 1 % is 4 times the largest measured
   deviation (2.3e-3), 30 times below what a wrong basis part gives (300-1200 times |s* − s|).
CPU: two 6-element models and their dense pencils, the AMB rotor's Newton solves: about 0.15 s.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from jeffcott_bearing import ACTIVE, KD, KI, KP, KS
from rotors import jeffcott_text
from test_amb import KP as AMB_KP
from test_amb import PID_KEYS, rotor
from test_eigen_error_reference import _full_root

from flexshaft.analyses.campbell import track_modes
from flexshaft.analyses.eigen import candidates, reduce
from flexshaft.analyses.eigen_error import eigenvalue_corrections
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import loads_design

SPEED = 300.0


def _steel(text: str) -> str:
    return text.replace("density = 0.1", "density = 7800.0")


def _pencil(M, D, K):
    n = M.shape[0]
    I, O = np.eye(n), np.zeros((n, n))
    lam = la.eig(np.block([[O, I], [-K, -D]]), np.block([[I, O], [O, M]]), right=False)
    return lam[np.isfinite(lam) & (lam.imag > 0)]


def _check(model, red, full, s, Y, speed=SPEED):
    delta = eigenvalue_corrections(red, speed, s, Y)
    assert np.all(np.isfinite(delta))
    free = model.dofs.free
    K = restrict((model.K + model.Kp).tocsr(), free).toarray()
    M = restrict(model.M.tocsr(), free).toarray()
    omega_c = np.sqrt(la.eigh(K, M, eigvals_only=True)[red.size])
    for k, sk in enumerate(s):
        nearest = full[np.argmin(np.abs(full - sk))]
        true = nearest - sk
        gap = np.sort(np.abs(full - nearest))[1]
        assert abs(true) > 1e-9 * abs(sk)  # a real error, far above the pencil's round-off (~1e-12)
        neglected = (abs(sk) / omega_c) ** 4 + abs(true) / gap
        assert abs(delta[k] - true) <= 3 * neglected * abs(true)


@pytest.mark.parametrize("twist_free", [False, True])
def test_the_estimate_of_a_non_collocated_pd_magnet_is_the_true_error(twist_free):
    text = _steel(jeffcott_text(0.0, 0.0, elements=6))
    if twist_free:
        text = text.replace('fixed_start = ["u", "v", "w", "theta"]', 'fixed_start = ["u", "v", "w"]')
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    bearing = f'[[bearings]]\nname = "b"\nx = 0.5\n{ACTIVE}\nsensor_offset = 0.125\n'
    model = build_model(loads_design(head + bearing + tail))
    free = model.dofs.free

    def dense(matrix):
        return restrict(matrix.tocsr(), free).toarray()

    a = model.actuators[0]
    Ba, Bs = a.lateral_rows.toarray()[:, free], a.sensing_rows.toarray()[:, free]
    assert np.abs(Ba - Bs).max() > 0  # the sensor is not at the magnet
    stiffness = dense(model.K) + KI * KP * Ba.T @ Bs - KS * Ba.T @ Ba
    damping = dense(model.C) + SPEED * dense(model.G) + KI * KD * Ba.T @ Bs
    red = reduce(model, 5 if twist_free else 4)
    assert (np.min(np.abs(red.w2)) < 1e-6) == twist_free  # the free twist: ω² = 0 in the basis
    s, Y = candidates(red, SPEED)
    whirl = np.flatnonzero(s.imag > 1.0)[:2]  # the disk's pair (a free twist's root, s ≈ 0, left out)
    _check(model, red, _pencil(dense(model.M), damping, stiffness), s[whirl], Y[:, whirl])


def test_the_estimate_with_free_rigid_body_modes_in_the_basis():
    keys = PID_KEYS.replace(f"kp = {AMB_KP}", "kp = 0.0")
    assert keys != PID_KEYS
    model = rotor(keys, 0.0, 2.1e11)
    free = model.dofs.free

    def dense(A):
        return restrict(A.tocsr(), free).toarray()

    M, G, C, K = dense(model.M), dense(model.G), dense(model.C), dense(model.K)

    def T(z):
        return z * z * M + z * (SPEED * G + C) + K + dense(model.controller_matrix(z))

    red = reduce(model, 8)
    assert np.sum(np.abs(red.w2) < 1e-3) == 4  # two translations and two tilts, free in the basis
    tracked = track_modes(model, red, np.array([SPEED]), 4)
    s, Y = tracked.eigenvalues[0], tracked.states[0]
    delta = eigenvalue_corrections(red, SPEED, s, Y)
    X = red.Phi @ Y
    checked = 0
    for k, sk in enumerate(s):
        true = _full_root(T, sk, X[:, k] / np.linalg.norm(X[:, k])) - sk
        if abs(true) > 1e-6 * abs(sk):
            assert abs(delta[k] - true) <= 1e-2 * abs(true)
            checked += 1
    assert checked == 3
