"""The error estimate of a basis that spans every free DOF is exactly zero (hunt h32e:
``flexshaft modes --n-modes 500`` solves the tuned design on its whole 343-vector basis).

:func:`flexshaft.analyses.eigen_error.eigenvalue_errors` estimates the error of a reduced
eigenvalue from the complement Ψ of the basis Φ (its module docstring). A basis of every free DOF
(nb = n, Φ square and M-orthonormal, so invertible) leaves Ψ empty: ``Φᵀ T(s) Φ y = 0`` is
``T(s) x = 0`` itself and the estimate is exactly δ = 0 (derived). Reference for the claim that
such a reduced problem is the full one: the undamped modes at rest of the tuned design on its
coarsest mesh (50 free DOFs), ``(K + K_p) φ = ω² M φ`` solved directly by ``scipy.linalg.eigh``
on the free-DOF matrices; tolerance 1e-9 relative (the shift-invert basis is accurate to
ε(ω_i² + 1)/(ω_1² + 1), about 1e-12 for the six lowest modes; eigh's own error, ε‖K‖/ω_i² of their
ω², is below 1e-10 here; 5e-13 measured). A basis one vector short has a complement and an
estimate above zero (the damped modes at the operating speed: dampers, gyroscopic and loss terms
couple the missing vector to the others; 2.4e-8 measured, where the round-off the whole basis
computed before was below 1e-39).

CPU: one 50-DOF model solved three times, about 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la

from flexshaft.analyses.modal import modes
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import tuned_design, with_overrides


@pytest.fixture(scope="module")
def coarse():
    return build_model(with_overrides(tuned_design(), {"mesh.shaft_elements": 2, "mesh.boom_elements": 2}))


def test_a_basis_of_every_free_dof_has_no_error(coarse):
    free = coarse.dofs.free
    n = free.size
    K = restrict((coarse.K + coarse.Kp).tocsr(), free).toarray()
    M = restrict(coarse.M.tocsr(), free).toarray()
    expected = np.sqrt(la.eigh(K, M, eigvals_only=True)[:6])
    at_rest = modes(coarse, 0.0, 6, damped=False, basis_size=n)
    np.testing.assert_allclose(at_rest.eigenvalues.imag, expected, rtol=1e-9)
    np.testing.assert_array_equal(at_rest.error_estimate, 0.0)
    spinning = modes(coarse, coarse.speed, 6, basis_size=n)
    np.testing.assert_array_equal(spinning.error_estimate, 0.0)


def test_a_basis_one_short_has_an_error(coarse):
    short = modes(coarse, coarse.speed, 6, basis_size=coarse.dofs.free.size - 1)
    assert np.all(np.isfinite(short.error_estimate))
    assert np.max(short.error_estimate) > 1e-10
