"""The projected spin-up sweep solves in full the speed where the response is set by a sharp
resonance, against the Jeffcott rotor's closed-form resonance sensitivity and a direct solve.

:func:`~flexshaft.analyses.sweep_projection.imbalance_sweep` accepts a reduced model whose error
estimate is below the tolerance, then measures ``κ_ω = ω ‖Z⁻¹ (∂Z/∂ω) q‖ / ‖q‖`` at the peaks of
the response and solves in full every speed where κ_ω exceeds ``0.1 / RESONANCE_TOLERANCE``
(1e4): there a change of ω below the natural frequencies' accuracy changes the response
completely, and the full solver's checks must decide (module docstring).

Reference (closed form, derived in tests/test_resonance_sensitivity_reference.py): the Jeffcott
rotor of tests/rotors.py with a dashpot c at the disk (ζ = c / 2√(km)) responds to a forward load
at the disk in one shape, the tube's static deflection (its own modes are far above), times
``f Ω² / (k − mΩ² + icΩ)``, so

    κ_ω = ω |−2mω + ic| / |k − mω² + icω|,

which is 1/ζ at ω = √(k/m) and about ``1/(2|δ|)`` at a relative distance δ from it. With
ζ = 3e-5 the scan point at √(k/m) has κ_ω ≈ 3.3e4 (above 1e4: solved in full; below the full
solver's own warning at 1e5, so no warning), and its neighbours, 1.5 % away, κ_ω ≈ 33. Because
the response is one shape, the 13 initial full solves span it exactly and the scan is accepted
without a round (``rounds == 0``): the resonant speed is solved in full only by the κ_ω rule,
the neighbours not at all.

The response at every speed is also checked against a dense direct solve of the full
``(K − Ω²M + iΩ(ΩG + C)) q = Ω² Q₁`` on the free DOFs, within 1e-7 of the scan's peak (the
tolerance tests/test_spinup_projection.py holds the projection to; the dense solve's own error at
the resonance, ε times its condition ≈ 1/(2ζ) times the tube's stiffness spread, is far below).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as la
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.banded import RESONANCE_TOLERANCE
from flexshaft.analyses.sweep_projection import imbalance_sweep
from flexshaft.assembly.sparse import restrict

ZETA = 3e-5


def test_the_resonant_speed_alone_is_sent_to_a_full_solve():
    c = 2 * ZETA * np.sqrt(K_SHAFT * M_DISK)
    model = jeffcott(0.0, c)
    speeds = np.sort(np.append(np.linspace(0.6, 1.5, 60) * WN, WN))
    k = int(np.searchsorted(speeds, WN))
    v, w = disk_dofs(model)
    Q = np.zeros((model.dofs.size, 1), complex)
    Q[v, 0], Q[w, 0] = 1.0, -1j  # a forward rotating unit load per Ω²
    kappa = speeds * np.abs(-2 * M_DISK * speeds + 1j * c) / np.abs(K_SHAFT - M_DISK * speeds**2 + 1j * c * speeds)
    sharp = kappa * RESONANCE_TOLERANCE > 0.1
    assert np.flatnonzero(sharp).tolist() == [k]
    assert kappa[k] * RESONANCE_TOLERANCE < 1  # the full solver does not warn

    sweep = imbalance_sweep(model, speeds, Q)

    assert sweep.rounds == 0 and sweep.basis_size > 0  # accepted on the initial snapshots
    assert sweep.full[k]
    assert not sweep.full[k - 1] and not sweep.full[k + 1]

    free = model.dofs.free
    M, K, G, C = (restrict(A.tocsr(), free).toarray() for A in (model.M, model.K, model.G, model.C))
    q = np.asarray(sweep.response)[free, 0, :]
    direct = np.column_stack([la.solve(K - s * s * M + 1j * s * (s * G + C), s * s * Q[free, 0]) for s in speeds])
    assert np.abs(q - direct).max() <= 1e-7 * np.abs(direct).max()
