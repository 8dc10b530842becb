"""A modal basis of one mode is the Jeffcott mode (closed form, derived here).

Reference. The Jeffcott rotor of tests/rotors.py: a disk of mass m = 20 kg at the midspan of a
pinned-pinned Euler-Bernoulli tube of length L = 1 m, k = 48 E I / L³ at the disk, the tube's
own mass m_t = ρ π (D_o² − D_i²)/4 L = 7.07e-5 kg (ρ = 0.1 kg/m³). With the static deflection
shape of a midspan load as Rayleigh's trial function, the tube adds 17/35 of its mass at the
disk (the classical factor of the simply supported beam, derived from ∫ (y/y_mid)² dx/L with
y ∝ 3xL² − 4x³ on each half), so the lowest undamped ω² is

    ω² = k / (m + 17/35 m_t)          (1.72e-6 below k/m).

The Rayleigh quotient of the static shape differs from the finite-element eigenvalue by the
square of the shape error times the tiny tube mass; the tube's rotary inertia adds about
r_g² (π/L)² = 2.5e-3 (r_g² = (D_o² + D_i²)/16) to the tube's share, so lowers ω² by 2.5e-3 of
the 1.72e-6 effect, 4.3e-9. Measured offset from 17/35: −4.35e-9 relative at 4, 8 and 16 elements
(the same on the OpenBLAS Prescott and Haswell kernels), the rotary-inertia term. Asserted at
1e-8: 2.3 times above that offset, and 4.6 times below the +4.6e-8 of the factor 1/2 (the
tube's mass lumped half at the disk), which the assertion must tell from 17/35.

Documented behaviour (API contract: modal_basis refuses a basis_size below one with
"basis_size must be an integer >= 1 (got {basis_size!r})", so one is valid input): a basis of one mode returns that
mode alone, mass-normalised (φᵀMφ = 1: a dense product with the assembled M, round-off 1e-15,
asserted at 1e-12).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import DI, DO, K_SHAFT, M_DISK, L, jeffcott_text

from flexshaft.analyses.reduced_basis import modal_basis
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import loads_design

DENSITY = 0.1  # kg/m³, the tube of tests/rotors.py
M_TUBE = DENSITY * np.pi * (DO**2 - DI**2) / 4 * L
W2 = K_SHAFT / (M_DISK + 17 / 35 * M_TUBE)


@pytest.mark.parametrize("elements", [4, 8])
def test_a_one_mode_basis_is_the_jeffcott_mode(elements):
    model = build_model(loads_design(jeffcott_text(0.0, 0.0, elements=elements)))
    w2, Phi = modal_basis(model, 1)
    assert w2.shape == (1,)
    assert Phi.shape == (model.dofs.free.size, 1)
    assert w2[0] == pytest.approx(W2, rel=1e-8)
    M = restrict(model.M.tocsr(), model.dofs.free).toarray()
    assert float(Phi[:, 0] @ M @ Phi[:, 0]) == pytest.approx(1.0, abs=1e-12)
