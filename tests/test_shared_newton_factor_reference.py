"""Newton's first step on the LU factors its caller holds, and the vectors of a double root
(hunt h32e: one factorisation of T(s) a root for its vector and its first Newton step).

1. :func:`flexshaft.analyses.eigen.newton` with ``factor``: its first step solves with the LU
   factors of T(s₀) that the caller holds (:func:`~flexshaft.analyses.hysteretic_roots._polish`
   after its inverse iteration), and factors T(s) afresh from the second step on. Reference: the
   hysteretic Jeffcott rotor's forward root above the spin, ``m s² + c_e s + k(1 + iη) = 0``
   (derived in tests/test_stability.py's docstring; as in
   tests/test_eigen_newton_and_sensor_reference.py), tolerance 1e-5 relative (the tube's 3.5e-6
   of the disk's mass, as there). And a convergence rate: started 20 % off the root, Newton's
   method converges quadratically (errors about 0.2, 4e-2, 2e-3, 4e-6, 2e-11: five steps at most
   to the step test of 1e-10), where a step that kept the first factor (the chord method: linear,
   the error times |s₀ − s*|/|2s* + c/m| ~ 0.1 a step) needs about ten: with at most six steps
   allowed it must still converge. Its result is that of the same iteration without the factor,
   to the bit (getrf then getrs is what gesv does).

2. The isotropic Jeffcott rotor at rest: v and w are decoupled and identical, so its root
   ``m s² + c_e s + k(1 + iη) = 0`` (at Ω = 0 the loss has one sign for every ω > 0: module
   docstring of :mod:`flexshaft.analyses.hysteretic_roots`) is double, with a two-dimensional
   eigenspace (derived). The two modes :func:`~flexshaft.analyses.hysteretic_roots.damped_modes`
   returns for it must be two independent shapes of that plane: unit vectors with |y₁ᴴy₂|² below
   0.5 (any basis a dense solve picks is far from parallel; 4e-8 measured), where inverse
   iteration from one start returns one vector twice (|y₁ᴴy₂|² = 0.9999 measured), which the
   separation test before the deferred vectors prevents. Root tolerance 1e-5 as in 1.

CPU: a 48-DOF Jeffcott rotor on a 6-mode basis, a few hundredths of a second.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

import flexshaft.analyses.eigen as eigen
from flexshaft.analyses.eigen import newton, reduce
from flexshaft.analyses.hysteretic_roots import branches, damped_modes
from flexshaft.assembly.sparse import restrict

ETA, C_E = 0.05, 2 * 0.01 * M_DISK * WN


def _forward_root() -> complex:
    """Root with Im s > 0 of m s² + c_e s + k(1 + iη) (the forward whirl above the spin)."""
    roots = np.roots([M_DISK, C_E, K_SHAFT * (1 + 1j * ETA)])
    return roots[np.argmax(roots.imag)]


def test_newton_on_a_given_factor_converges_quadratically(monkeypatch):
    model = jeffcott(ETA, C_E)
    red = reduce(model, 6)
    speed = 0.5 * WN
    weights = branches(red, speed)[-1].weights  # above the spin: k(1 + iη)
    v, w = disk_dofs(model)
    forward = np.zeros(model.dofs.size, complex)
    forward[v], forward[w] = 1.0, -1j
    y0 = red.Phi.T @ (restrict(model.M.tocsr(), model.dofs.free) @ forward[model.dofs.free])
    y0 = y0 / np.linalg.norm(y0)
    s0 = 1.2 * _forward_root()
    T, _ = red.newton_terms(s0, speed, weights, y0)
    lu, piv, info = la.lapack.zgetrf(T)
    assert info == 0
    monkeypatch.setattr(eigen, "NEWTON_MAX_STEPS", 6)
    s, y, converged = newton(red, speed, s0, y0, weights=weights, factor=(lu, piv))
    assert converged
    assert s == pytest.approx(_forward_root(), rel=1e-5)
    plain = newton(red, speed, s0, y0, weights=weights)
    assert plain[0] == s and np.array_equal(plain[1], y)
    with pytest.raises(ValueError, match="factor"):
        newton(red, speed, s0, y0, factor=(lu, piv))  # no weights: the factor's are unknown


def test_a_double_root_at_rest_keeps_two_independent_shapes():
    red = reduce(jeffcott(ETA, C_E), 6)
    s, Y = damped_modes(red, 0.0, 2)
    np.testing.assert_allclose(s, [_forward_root()] * 2, rtol=1e-5)
    Y = Y / np.linalg.norm(Y, axis=0)
    assert abs(np.vdot(Y[:, 0], Y[:, 1])) ** 2 < 0.5
