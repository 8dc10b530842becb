"""The dense modal basis read off the model's whole spectrum, against LAPACK's subset solve.

:func:`~flexshaft.analyses.reduced_basis.modal_basis` (dense, up to ``WHOLE_DENSE_BASIS_UP_TO`` free
DOFs) takes the lowest modes from one solution of every mode of the model, computed once and
shared by the bases of every size. The reference is the solve of the same shift-inverted
generalised problem for the wanted modes only (``scipy.linalg.eigh(..., subset_by_index=...)``,
as the basis was computed before), written out here. Both are backward stable solutions of one
symmetric-definite problem: μ = 1/(ω² + 1) is known to ~ε relative to the largest μ, so ω²_i
to ~ε (ω²_i + 1)/(ω²_1 + 1) relative (:func:`modal_basis`'s notes; asserted with a factor
100), and the bases span the same space (every canonical angle's cosine 1
within 1e-9), the basis being cut where the spectrum has a gap (not inside a degenerate pair).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from rotors import M_DISK, WN, jeffcott

from flexshaft.analyses.dense_spectrum import WHOLE_DENSE_BASIS_UP_TO, dense_spectrum
from flexshaft.analyses.reduced_basis import modal_basis
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design.io import embedded_design


@pytest.mark.parametrize("name", ["baseline", "tuned", "current"])
def test_whole_spectrum_basis_matches_the_subset_solve(name):
    model = build_model(embedded_design(name).model_copy(update={"envelope": None}))
    free = model.dofs.free
    n = free.size
    assert n <= WHOLE_DENSE_BASIS_UP_TO
    M = restrict(model.M, free).toarray()
    K = restrict((model.K + model.Kp).tocsr(), free).toarray()
    compared = 0
    for size in (20, 60):
        w2, Phi = modal_basis(model, size, "dense")
        mu, ref = la.eigh(M, K + M, subset_by_index=[n - size - 1, n - 1])  # one more: the gap
        w2_ref = np.sort(1.0 / mu - 1.0)
        if (w2_ref[size] - w2_ref[size - 1]) < 1e-6 * w2_ref[size]:
            continue  # the cut splits a degenerate pair: the spans may differ there
        bound = 100 * np.finfo(float).eps * (w2_ref[:size] + 1.0) / (w2_ref[0] + 1.0)
        assert np.all(np.abs(w2 - w2_ref[:size]) <= bound * np.abs(w2_ref[:size]))
        ref = ref[:, 1:]  # the wanted modes (ascending μ: the extra one is first)
        ref = ref / np.sqrt(np.einsum("ij,ij->j", ref, M @ ref))
        cosines = la.svdvals(Phi.T @ M @ ref)
        assert np.all(np.abs(cosines - 1.0) < 1e-9)
        # mass-orthonormal to dense_spectrum's threshold (1e-9; the subset solve: 1e-13)
        assert np.abs(Phi.T @ M @ Phi - np.eye(size)).max() < 1e-9
        compared += 1
    assert compared


def test_an_ill_conditioned_whole_spectrum_is_not_used():
    """The near-massless Jeffcott shaft (κ ≈ 4e10): the whole-spectrum solution's lowest modes
    are M-orthogonal only to ~1e-7, so no basis is taken from it (the subset solve instead); the
    tuned design's lowest 128 to 1e-10, so they are."""
    model = jeffcott(0.02, 2 * 0.005 * M_DISK * WN)
    assert dense_spectrum(model, 1.0)[2] == 0
    tuned = build_model(embedded_design("tuned").model_copy(update={"envelope": None}))
    assert dense_spectrum(tuned, 1.0)[2] == 128
