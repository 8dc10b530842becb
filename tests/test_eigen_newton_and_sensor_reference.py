"""Newton's method on the hysteretic Jeffcott rotor, and a non-collocated PD bearing's roots
against the unreduced model solved densely (mutation hunt 23c).

1. :func:`flexshaft.analyses.eigen.newton` without given weights takes the hysteretic loss
   weights of its starting point's own side of the synchronous line (ω = Im s₀ against the
   spin Ω). Reference (derived in tests/test_stability.py's docstring): the Jeffcott-like rotor
   of tests/rotors.py, loss factor η, dashpot c_e at the disk, whose forward whirl obeys

       m s² + c_e s + k (1 + iη sgn(ω − Ω)) = 0.

   Started at s₀ = iω_n on the forward circular shape (w = −i v at the disk), Newton must reach
   the root with k(1 + iη) at Ω = ω_n/2 (ω_n above the spin: stable) and the one with k(1 − iη)
   at Ω = 2ω_n (below the spin: Re s > 0, the internal-damping instability). The two differ by
   5 % (η = 0.05). The side is that of Im s₀, the damped frequency, not of |s₀|: started at
   s₀ = ω_n(−1 + i) (|s₀| = 1.41 ω_n) at Ω = 1.2 ω_n, Im s₀ = ω_n lies below the spin, so the
   root is the one with k(1 − iη) although |s₀| lies above it (mutation hunt 46a).
   Tolerance 1e-5 relative: the tube carries 3.5e-6 of the disk's mass; the
   loss η K' condenses onto the disk mode, which the 6-mode basis holds exactly.

2. A magnetic bearing at the disk of the rotor of tests/jeffcott_bearing.py, its sensor 0.125 m
   further on, ideal PD law i = −(k_p + k_d s) d_s (no controller states: the derivative is a
   damping from the sensed to the actuated DOFs, ``E = k_i k_d``). Reference: the full model's
   free DOFs, solved directly with dense scipy: the linearised magnet f = k_s d_a + k_i i
   (docs/magnetic-bearings.md) gives

       [M s² + C s + K + B_aᵀ k_i (k_p + k_d s) B_s − k_s B_aᵀ B_a] q = 0,

   as the pencil (A − s B) of its first-order form, with the model's M, C, K (which holds no
   actuator term) and the bearing's rows B_a, B_s. Its roots below 1e4 rad/s (the
   near-massless tube's own are far above) against the reduced model's candidates.
   Tolerance 1e-7 relative: the disk's mode condenses the static shape under the magnet's
   force, so an 8-mode basis misses only the tube's 3.5e-6 mass share of coupling (the bases
   of 4 to 12 modes give the same roots to 1e-10); LAPACK's eig errs by ε‖A‖/|s|, far below.

CPU: two small models and a 60 × 60 dense eig, about 0.03 s.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from jeffcott_bearing import ACTIVE, KD, KI, KP, KS, model_with
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.eigen import candidates, newton, reduce
from flexshaft.assembly.sparse import restrict

ETA, C_E = 0.05, 2 * 0.01 * M_DISK * WN


def _root(sign: float) -> complex:
    """Root with Im s > 0 of m s² + c_e s + k(1 + i sign η)."""
    roots = np.roots([M_DISK, C_E, K_SHAFT * (1 + sign * 1j * ETA)])
    return roots[np.argmax(roots.imag)]


@pytest.mark.parametrize(("ratio", "side", "start"), [(0.5, +1.0, 1j), (2.0, -1.0, 1j), (1.2, -1.0, -1 + 1j)])
def test_newton_takes_the_loss_of_its_own_side_of_the_spin(ratio, side, start):
    model = jeffcott(ETA, C_E)
    red = reduce(model, 6)
    v, w = disk_dofs(model)
    forward = np.zeros(model.dofs.size, complex)
    forward[v], forward[w] = 1.0, -1j
    y0 = red.Phi.T @ (restrict(model.M.tocsr(), model.dofs.free) @ forward[model.dofs.free])
    s, _, converged = newton(red, ratio * WN, start * WN, y0)
    assert converged
    assert abs(_root(+1.0) / _root(-1.0) - 1) > 0.04  # the two sides are told apart
    assert s == pytest.approx(_root(side), rel=1e-5)
    assert (s.real > 0) == (side < 0)


def test_a_non_collocated_pd_bearing_matches_the_unreduced_closed_loop():
    model = model_with(ACTIVE + "\nsensor_offset = 0.125")
    free = model.dofs.free
    n = free.size

    def dense(matrix):
        return restrict(matrix.tocsr(), free).toarray()

    M, C, K = dense(model.M), dense(model.C), dense(model.K)
    a = model.actuators[0]
    Ba, Bs = a.lateral_rows.toarray()[:, free], a.sensing_rows.toarray()[:, free]
    assert np.abs(Ba - Bs).max() > 0  # the sensor is not at the magnet
    stiffness = K + KI * KP * Ba.T @ Bs - KS * Ba.T @ Ba
    damping = C + KI * KD * Ba.T @ Bs
    I, O = np.eye(n), np.zeros((n, n))
    lam = la.eig(np.block([[O, I], [-stiffness, -damping]]), np.block([[I, O], [O, M]]), right=False)
    lam = lam[np.isfinite(lam) & (np.abs(lam) < 1e4) & (lam.imag > 0)]
    expected = lam[np.argsort(np.abs(lam))][:2]  # the disk's v and w roots (isotropic: a pair)
    assert np.all(expected.real < 0)
    s, _ = candidates(reduce(model, 8), 0.0)
    np.testing.assert_allclose(s[:2], expected, rtol=1e-7)
