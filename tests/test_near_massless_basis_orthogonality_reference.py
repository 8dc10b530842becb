"""The modal basis of a near-massless tube stays M-orthonormal (a dense product, derived here).

An invariant check. The reduced model takes the basis Φ as M-orthonormal (ΦᵀMΦ = I, the module
docstring (code) of :mod:`flexshaft.analyses.reduced_basis`): a departure Δ = ΦᵀMΦ − I moves
the eigenvalues of the modes it touches by about as much, relative.

The rotor: the Jeffcott rotor of tests/rotors.py (a 20 kg disk at mid-span of a pinned-pinned
steel tube of density 0.1 kg/m³, 3.5e-6 of the disk mass) on 16 elements (96 free DOFs), whose
tube modes lie 1e8 above the Jeffcott mode in ω², an ill-conditioned pencil. Reference: Δ from
a dense product of the returned Φ with the assembled M, independent of how Φ was computed.
Tolerance from conditioning: the round-off of an M-orthonormal eigenbasis is about
n ε ‖M‖ ‖K_σ⁻¹‖, amplified here by the 1e8 spread of the pencil, and differs between BLAS
kernels; measured 3.8e-9 to 4.3e-9 on the OpenBLAS Prescott, Haswell and SkylakeX kernels,
asserted at 3e-8 (a factor 7 of headroom for other kernels and LAPACK versions).
"""

from __future__ import annotations

import numpy as np
from rotors import jeffcott_text

from flexshaft.analyses.reduced_basis import modal_basis
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import loads_design

ORTHONORMAL = 3e-8


def test_a_near_massless_tubes_basis_is_m_orthonormal():
    model = build_model(loads_design(jeffcott_text(0.0, 0.0, elements=16)))
    M = restrict(model.M, model.dofs.free).toarray()
    w2, Phi = modal_basis(model, 16)
    departure = np.abs(Phi.T @ M @ Phi - np.eye(16)).max()
    assert departure <= ORTHONORMAL, departure
    assert np.all(np.diff(w2) >= 0)
