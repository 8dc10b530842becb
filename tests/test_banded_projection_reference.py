"""The Galerkin projections of the banded solver's terms against ``Uᴴ Z(ω, Ω) W`` formed densely.

:meth:`~flexshaft.analyses.banded.BandedHarmonicSolver.project_pairs` returns ``Uᴴ T_k W`` for
each non-zero term T_k of the dynamic stiffness, so that with the weights ``w`` of
:meth:`~flexshaft.analyses.banded.BandedHarmonicSolver.term_weights` at (ω, Ω),
``Σ_k w_k Uᴴ T_k W = Uᴴ Z(ω, Ω) W`` (the reduced models of the loop margins and the peak
projections are built this way, on complex bases: solutions and eigenvectors).

Reference (the module docstring's definition, formed here from the model's assembled matrices,
not the solver's permuted band storage): a Jeffcott rotor of tests/rotors.py with a dashpot and
no material loss, so ``Z(ω, Ω) = K − ω²M + iω(ΩG + C)`` on the free DOFs, at a non-synchronous
point (ω ≠ Ω, so that a weight written with the wrong frequency shows). U and W are random
complex bases (seeded); the Hermitian transpose Uᴴ carries the conjugate, which a real basis
would not test. Both sides are sums of the same O(n) products in a different order: they agree
to round-off, about ε n ≈ 1e-14 of the largest entry (measured 3e-16); 1e-11 is
asserted, while a dropped conjugate changes the result at order one.
"""

from __future__ import annotations

import numpy as np
from rotors import K_SHAFT, M_DISK, jeffcott

from flexshaft.analyses.banded import solver_for
from flexshaft.assembly.sparse import restrict

OMEGA, SPEED = 350.0, 200.0  # rad/s


def test_projections_of_complex_bases_are_the_hermitian_products():
    model = jeffcott(0.0, 2 * 0.02 * np.sqrt(K_SHAFT * M_DISK))
    solver = solver_for(model)
    free = model.dofs.free
    M, K, G, C = (restrict(A.tocsr(), free).toarray() for A in (model.M, model.K, model.G, model.C))
    Z = K - OMEGA**2 * M + 1j * OMEGA * (SPEED * G + C)
    rng = np.random.default_rng(23)
    n = free.size
    U = rng.standard_normal((2, n, 3)) + 1j * rng.standard_normal((2, n, 3))
    W = rng.standard_normal((2, n, 4)) + 1j * rng.standard_normal((2, n, 4))
    weights = solver.term_weights([OMEGA], [SPEED])[0]
    projected = np.einsum("k,mkab->mab", weights, solver.project_pairs(U, W))
    for j in range(2):
        expected = U[j].conj().T @ Z @ W[j]
        assert np.abs(projected[j] - expected).max() <= 1e-11 * np.abs(expected).max()
    square = np.einsum("k,mkab->mab", weights, solver.project(U))
    for j in range(2):
        expected = U[j].conj().T @ Z @ U[j]
        assert np.abs(square[j] - expected).max() <= 1e-11 * np.abs(expected).max()
