"""Enriching a modal basis that already spans every free DOF adds nothing.

Reference (linear algebra, derived here). With nb = n the undamped modes Φ (M-orthonormal,
n × n) span Rⁿ, so every static-correction vector ``K_σ⁻¹ X φ`` already lies in their span:

* the enriched basis V of :func:`~flexshaft.analyses.reduced_basis.enrich_basis` must stay
  M-orthonormal (what the reduced model assumes), and Rⁿ holds at most n M-orthonormal
  vectors, so V has exactly n columns;
* every Ritz value of (K + K_a, M) on any subspace lies within the full problem's spectrum
  [ω_1², ω_n²] (Rayleigh quotient bounds), so no returned ω² is below the lowest undamped
  ω_1² of the full problem, here computed by LAPACK's subset solve of the shift-inverted pencil
  of the model's own matrices: the largest μ of (M, K + K_a + M) is 1/(ω_1² + 1) (a different
  driver from the module's whole-spectrum solve; the direct (K + K_a, M) solve reduces on M's
  Cholesky factor and is the inaccurate one for the lowest modes, the notes of reduced_basis.modal_basis).

A correction projected out of a complete basis is round-off; kept, it would enter V with a
Ritz value near 0 (a spurious rigid-body-like mode below ω_1²).

Model: tests/test_amb.py's rotor on two PID magnetic bearings made flexible (E = 210 GPa,
52 free DOFs) and spinning at 6000 rpm, so G is non-zero and both actuators add their static
flexibility: the enrichment has couplings and actuator columns to add. Tolerances: both
shift-inverted solves of the lowest ω² are accurate to about ε κ(K_σ) = 2.2e-16 × 5.6e5 ≈ 1e-10
relative (κ from tests/test_static_correction_span_reference.py), so 1e-8 is asserted; a
spurious vector sits at round-off ω² (1e-12 to 1e-8 rad²/s² against ω_1² = 4.7e4 rad²/s²).
M-orthonormality: the module normalises each column exactly and the modes are M-orthogonal to
round-off, within the whole-spectrum gate of dense_spectrum (1e-9); 1e-9 as in
tests/test_static_correction_span_reference.py.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from test_amb import PID_KEYS, rotor

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.reduced_basis import BASIS_SHIFT, enrich_basis, full_operators, modal_basis
from flexshaft.assembly.sparse import restrict

N_TARGETS = 4


@pytest.fixture(scope="module")
def flexible():
    model = rotor(PID_KEYS, speed_rpm=6000.0, modulus=2.1e11)
    free = model.dofs.free
    M = restrict(model.M.tocsr(), free).toarray()
    K = restrict((model.K + model.Kp).tocsr(), free).toarray()
    n = free.size
    mu = float(la.eigh(M, K + M, eigvals_only=True, subset_by_index=[n - 1, n - 1])[0])
    w2_lowest = 1.0 / mu - 1.0  # the shift σ = -1 (K + M is positive definite)
    return model, M, w2_lowest


def test_enriching_a_complete_basis_adds_no_vector(flexible):
    """enrich_basis on every mode: n columns, M-orthonormal, no Ritz value below ω_1²."""
    model, M, w2_lowest = flexible
    free = model.dofs.free
    n = free.size
    rows = [np.asarray(a.lateral_rows.tocsr()[:, free].toarray()) for a in model.actuators]
    w2, Phi = modal_basis(model, n, "auto")
    assert Phi.shape == (n, n)
    w2_all, V = enrich_basis(full_operators(model, BASIS_SHIFT), w2, Phi, N_TARGETS, rows)
    assert V.shape == (n, n)
    assert w2_all.shape == (n,)
    np.testing.assert_allclose(V.T @ M @ V, np.eye(n), rtol=0, atol=1e-9)
    assert w2_all.min() >= w2_lowest * (1 - 1e-8)


def test_reduce_of_every_mode_with_corrections_is_the_full_problem(flexible):
    """reduce(model, n, enrich=4): n vectors and the lowest ω² of the full problem."""
    model, _, w2_lowest = flexible
    n = model.dofs.free.size
    red = reduce(model, n, enrich=N_TARGETS)
    assert red.size == n
    assert red.w2.min() == pytest.approx(w2_lowest, rel=1e-8)
