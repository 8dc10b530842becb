"""Every undamped mode of a model at once: the dense modal bases of one model share one solve.

:func:`~flexshaft.analyses.reduced_basis.modal_basis` (dense) reads the lowest modes off
:func:`dense_spectrum`, cached per model, instead of solving LAPACK's subset problem for each
basis size (tests/test_dense_basis.py compares the two).
"""

from __future__ import annotations

import functools

import numpy as np
import scipy.linalg as la

from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import restrict

__all__ = ["WHOLE_DENSE_BASIS_UP_TO", "dense_spectrum"]

#: Up to this many free DOFs a dense modal basis is read off the model's whole dense spectrum,
#: computed once (:func:`dense_spectrum`): at 343 DOFs (the tuned design) the whole solution
#: takes 10.5 ms, one of the 60 or 84 lowest modes 11.5-13.8 ms (LAPACK's tridiagonal reduction
#: dominates both), and an assessment asks for two such bases (the every-root check's). At 435
#: DOFs (the current design) the whole solution takes 35 ms where an assessment's point solved
#: six bases apart for 101 ms (the every-root check's two dense subsets, 25 and 30 ms, and the
#: modes' and the whirl stability's four sparse ones of 20-44 modes, 7-16 ms each; CPU medians);
#: one sparse basis alone (``flexshaft modes``) is 7 ms, so the limit stays near the designs'.
WHOLE_DENSE_BASIS_UP_TO = 500


@functools.lru_cache(maxsize=4)  # the models of one assessment's points
def dense_spectrum(model: Model, shift: float) -> tuple[np.ndarray, np.ndarray, int]:
    """Every eigenpair ``(μ ascending, Φ)`` of ``M φ = μ (K + K_a + σ M) φ`` on the free DOFs,
    σ = ``shift`` [rad²/s²] (the shift-inverted problem of
    :func:`~flexshaft.analyses.reduced_basis.modal_basis`), read-only, and how many of the lowest
    modes a basis may take from it: the lowest 128 when they are M-orthogonal to
    :data:`_ORTHOGONALITY` after mass normalisation, else none (LAPACK's divide-and-conquer
    solution of every mode is 10-100 times less M-orthogonal than its subset solution: 1e-10
    over the lowest 128 modes of the embedded designs, 9e-8 on the near-massless Jeffcott
    shaft)."""
    free = model.dofs.free
    dense_M = restrict(model.M, free).toarray()
    K = restrict((model.K + model.Kp).tocsr(), free).toarray()
    mu, Phi = la.eigh(dense_M, K + shift * dense_M)
    low = Phi[:, -min(128, free.size) :]
    low = low / np.sqrt(np.einsum("ij,ij->j", low, dense_M @ low))
    usable = low.shape[1] if np.abs(low.T @ dense_M @ low - np.eye(low.shape[1])).max() <= _ORTHOGONALITY else 0
    for array in (mu, Phi):
        array.setflags(write=False)
    return mu, Phi, usable


#: Largest departure of the whole solution's lowest modes' mass matrix from the identity for a
#: basis to be taken from them: an eigenvalue of the reduced
#: model moves by about as much relative, 1000 times below the modal analyses' tolerance
#: (1e-6); the embedded designs' reach 1e-10, the near-massless Jeffcott shaft's 9e-8.
_ORTHOGONALITY = 1e-9
