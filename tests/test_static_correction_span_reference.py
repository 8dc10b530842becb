"""The enriched modal basis of :func:`~flexshaft.analyses.reduced_basis.enrich_basis` against its
defining property, checked with dense solves of the model's own matrices.

Reference (derived from the definition the module states): the basis must hold, exactly up to
round-off, the static-correction vectors ``K_σ⁻¹ X φ_j`` of each coupling X (the gyroscope G;
the dampers C + K_d and the loss matrices when non-zero) for each of the lowest ``n_targets``
modes φ_j, and each actuator's static flexibility ``K_σ⁻¹ B_aᵀ``, with ``K_σ = K + K_a + σM``
(σ = :data:`~flexshaft.analyses.reduced_basis.BASIS_SHIFT`). Those vectors are computed here by dense
LAPACK solves of ``K_σ`` assembled from the model's matrices (not the module's sparse factor),
and each must lie in the span of the basis V: its M-orthogonal residual
``x − V Vᵀ M x`` (V is M-orthonormal) relative to ``‖x‖_M``. The rotor is tests/test_amb.py's
on two PID magnetic bearings, made flexible (E = 210 GPa, 52 free DOFs) and spinning, so G is
non-zero and the actuators act at two stations in two planes (4 columns of B_aᵀ). The dense
solves are of a matrix with κ(K_σ) = 5.6e5: the residuals are of order ε κ ≈ 1e-10 at worst
(measured 4e-15); 1e-9 is asserted, while a missing vector leaves a residual of order 1 (it is
not in the span of the others).

Also the basis invariants the reduced model relies on (module docstring): V is M-orthonormal,
Vᵀ(K + K_a)V is the diagonal of the returned ω², and the first columns are Φ itself.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from test_amb import PID_KEYS, rotor

from flexshaft.analyses.reduced_basis import BASIS_SHIFT, enrich_basis, full_operators, modal_basis
from flexshaft.assembly.sparse import restrict

N_BASIS, N_TARGETS = 8, 2


@pytest.fixture(scope="module")
def enriched():
    model = rotor(PID_KEYS, speed_rpm=6000.0, modulus=2.1e11)
    free = model.dofs.free

    def dense(A):
        return restrict(A.tocsr(), free).toarray()

    rows = [np.asarray(a.lateral_rows.tocsr()[:, free].toarray()) for a in model.actuators]
    w2, Phi = modal_basis(model, N_BASIS, "auto")
    w2_all, V = enrich_basis(full_operators(model, BASIS_SHIFT), w2, Phi, N_TARGETS, rows)
    M, K = dense(model.M), dense(model.K + model.Kp)
    couplings = [X for X in (dense(model.G), dense(model.C + model.Kd)) if np.any(X)]
    return M, K, couplings, rows, w2, Phi, w2_all, V


def _residuals(M, V, x):
    res = x - V @ (V.T @ (M @ x))
    return np.sqrt(np.einsum("ij,ij->j", res, M @ res) / np.einsum("ij,ij->j", x, M @ x))


def test_the_static_corrections_of_the_target_modes_are_in_the_span(enriched):
    M, K, couplings, _, _, Phi, _, V = enriched
    assert couplings  # the gyroscope at 6000 rpm at least
    K_sigma = K + BASIS_SHIFT * M
    for X in couplings:
        x = la.solve(K_sigma, X @ Phi[:, :N_TARGETS])
        assert np.all(_residuals(M, V, x) < 1e-9)


def test_the_actuators_static_flexibility_is_in_the_span(enriched):
    M, K, _, rows, _, _, _, V = enriched
    assert len(rows) == 2
    K_sigma = K + BASIS_SHIFT * M
    for B in rows:
        assert np.all(_residuals(M, V, la.solve(K_sigma, B.T)) < 1e-9)


def test_the_basis_is_modal_and_starts_with_the_undamped_modes(enriched):
    M, K, _, _, w2, Phi, w2_all, V = enriched
    assert V.shape[1] > N_BASIS
    np.testing.assert_allclose(V.T @ M @ V, np.eye(V.shape[1]), rtol=0, atol=1e-9)
    stiffness = V.T @ K @ V
    scale = np.sqrt(np.outer(w2_all, w2_all))
    np.testing.assert_allclose(stiffness / scale, np.diag(w2_all / np.diag(scale)), rtol=0, atol=1e-9)
    np.testing.assert_allclose(np.abs(np.sum(V[:, :N_BASIS] * (M @ Phi), axis=0)), 1.0, rtol=1e-9)
    np.testing.assert_allclose(w2_all[:N_BASIS], w2, rtol=1e-12)
