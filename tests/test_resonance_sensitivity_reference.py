"""The resonance sensitivity κ_ω of the spin-up sweep's reduced model, against the Jeffcott rotor.

:func:`~flexshaft.analyses.sweep_projection.imbalance_sweep` measures, on its reduced model,
``κ_ω = ω ‖Z⁻¹ (∂Z/∂ω) q‖ / ‖q‖`` with ``∂Z/∂ω = −2ωM + i(ΩG + C)`` at ω = Ω, and solves in
full the speeds where κ_ω exceeds the resonance threshold (:mod:`flexshaft.analyses.banded`).

Reference (closed form): the Jeffcott rotor of tests/rotors.py with a dashpot c at the disk and no
loss, driven by a forward load at the disk, responds in the shape of the tube's static deflection
under a midspan load times ``a(ω) = f / (k − mω² + icω)`` (the tube's own modes are far above). So
``dq/dω = q · a'/a`` and

    κ_ω = ω |−2mω + ic| / |k − mω² + icω|,

about 1/ζ at resonance. The reduced model spans the response exactly (one shape), so κ_ω agrees
with the closed form to the tube's mass effect, 7e-6 of the disk's, amplified near resonance
(3e-5 measured over 0.5-1.5 ω_n); 1e-4 is asserted.
"""

from __future__ import annotations

import numpy as np
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.banded import solver_for
from flexshaft.analyses.sweep_projection import _ReducedModel, _Terms


def test_reduced_sweep_resonance_sensitivity_is_the_single_dof_closed_form():
    c = 2 * 0.01 * np.sqrt(K_SHAFT * M_DISK)  # ζ = 0.01
    model = jeffcott(0.0, c)
    v, w = disk_dofs(model)
    load = np.zeros(model.dofs.size, complex)
    load[v], load[w] = 1.0, -1j  # forward rotating unit load
    solver = solver_for(model)
    rhs = load[solver.free][:, None]
    speeds = np.linspace(0.5, 1.5, 41) * WN
    terms = _Terms(solver, speeds)
    snapshots = np.column_stack([solver.solve(s, rhs[:, 0], speed=s) * s * s for s in speeds[::10]])
    reduced = _ReducedModel(terms, snapshots, rhs)
    y = reduced.solve(terms.coefficients, speeds)
    kappa = reduced.sensitivity(terms.coefficients, speeds, y)
    expected = speeds * np.abs(-2 * M_DISK * speeds + 1j * c) / np.abs(K_SHAFT - M_DISK * speeds**2 + 1j * c * speeds)
    np.testing.assert_allclose(kappa, expected, rtol=1e-4)
