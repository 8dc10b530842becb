"""Static-correction vectors stay M-orthogonal to the modes they enrich (a dense product, derived here).

An invariant check. :func:`~flexshaft.analyses.reduced_basis.enrich_basis` returns V = [Φ, E]:
the lowest undamped modes Φ and the static corrections E, M-orthonormalised against Φ. The
reduced model takes V as M-orthonormal (VᵀMV = I) with Φ its exact modes; a cross term
C = ΦᵀME ≠ 0 is a mass coupling between a mode and the corrections that the reduced model
drops (its mass matrix is the identity), so the modes it touches move by about |C| relative.

Why an ill-conditioned rotor. The corrections are orthonormalised symmetrically, E U d^(-1/2)
from the eigen-decomposition (d, U) of their Gram matrix, which amplifies whatever part of E
lies along Φ by up to d_min^(-1/2) (1e5 at the module's independence threshold 1e-10). On a
well-conditioned rotor that part is round-off either way; on a near-massless tube (the
Jeffcott rotor of tests/rotors.py: a 20 kg disk on a tube of density 0.1 kg/m³, 16 elements,
96 free DOFs, with the dashpot c_e = 10 N s/m and the loss factor η = 0.01 so that the
corrections have dampers and loss to add) the M-products carry the round-off of components
over a spread of 1e8 in mass, and a correction taken before the last projection against Φ
keeps 1.4e-9 to 3.3e-4 of it, depending on the kernel (measured max |C|: 1.4e-9 on OpenBLAS
Prescott and 3.1e-8 on Haswell at 4 modes, 3.3e-4 and 1.4e-4 at 8 modes).

Reference: C from a dense product of the returned columns with the assembled M, independent of
how V was computed. Tolerance: measured max |C| 8e-17 to 1.3e-13 on the OpenBLAS Prescott and
Haswell kernels for 4 and 8 modes (the round-off of the last projection); asserted at 1e-10,
1e3 above the largest and below the 1.4e-9 to 3.3e-4 a correction not projected last keeps.
The catch margin is only 14 times at 4 modes on Prescott (1.4e-9 against 1e-10); the 8-mode
case catches it by more than 1e6 on both kernels. Also checked (API contract, enrich_basis's
docstring: "the first columns are Φ itself"): the enrichment adds columns above the kept
modes, it does not rotate them, to 1e-12 relative (measured 1e-16).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import jeffcott_text

from flexshaft.analyses.reduced_basis import BASIS_SHIFT, enrich_basis, full_operators, modal_basis
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import loads_design

CROSS = 1e-10
N_TARGETS = 4


@pytest.fixture(scope="module")
def near_massless():
    model = build_model(loads_design(jeffcott_text(0.01, 10.0, elements=16)))
    M = restrict(model.M.tocsr(), model.dofs.free).toarray()
    return model, M


@pytest.mark.parametrize("n_modes", [4, 8])
def test_corrections_are_mass_orthogonal_to_the_modes(near_massless, n_modes):
    model, M = near_massless
    w2, Phi = modal_basis(model, n_modes)
    _, V = enrich_basis(full_operators(model, BASIS_SHIFT), w2, Phi, N_TARGETS, [])
    assert V.shape[1] > n_modes  # corrections were added
    assert np.abs(V[:, :n_modes] - Phi).max() <= 1e-12 * np.abs(Phi).max()
    E = V[:, n_modes:]
    cross = np.abs(Phi.T @ M @ E).max()
    assert cross <= CROSS, cross
