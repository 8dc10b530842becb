"""The projected sweep's residual indicator, against its definition evaluated directly.

:meth:`_ReducedModel.indicator` ranks the speeds where the greedy basis solves next
(module docstring of :mod:`flexshaft.analyses.sweep_projection`, step 2): at each speed

    ‖r(Ω)‖ ‖y‖ / ‖Ω² Vᴴ Q₁‖,     r(Ω) = Ω² Q₁ − Z(Ω, Ω) V y,

the full model's residual times the reduced model's amplification (a proxy of ‖Z⁻¹‖: the
imbalance load grows as Ω², so the amplification divides by Ω²). The code gets ‖r‖ without
forming Z V y (the triangular factor of the stacked products); here the residual is formed
directly, Z = Σ_k w_k(Ω) T_k from the solver's terms and weights, on the Jeffcott rotor of
tests/rotors.py (ζ = 0.05 dashpot) with a basis that does *not* hold the response (the load
vector and a fixed pseudo-random vector), so that r ≠ 0.

Tolerance 1e-6 relative: the code's weights are the SVD of the weight table truncated at
_WEIGHT_RANK = 1e-14 of ‖Z‖, and the residual here is not small (‖r‖ ≈ 0.72 ‖Ω² Q₁‖, so no
cancellation): the two evaluations agree to round-off (1e-16 measured); a wrong power of Ω in
the amplification is off by a factor ≥ 100 (Ω ≥ 0.5 ω_n = 151 rad/s).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.banded import BandedHarmonicSolver
from flexshaft.analyses.sweep_projection import _ReducedModel, _Terms


def test_the_indicator_is_the_residual_times_the_reduced_amplification():
    model = jeffcott(0.0, 2 * 0.05 * np.sqrt(K_SHAFT * M_DISK))
    solver = BandedHarmonicSolver(model)
    free = solver.free
    v, w = disk_dofs(model)
    loads = np.zeros((model.dofs.size, 1), complex)
    loads[v, 0], loads[w, 0] = 1e-4, -1e-4j
    rhs = loads[free]
    speeds = np.array([0.5, 0.9, 1.3]) * WN
    terms = _Terms(solver, speeds)
    other = np.random.default_rng(7).standard_normal((free.size, 1))
    reduced = _ReducedModel(terms, np.hstack([rhs, other]), rhs)
    y = reduced.solve(terms.coefficients, speeds)
    got = reduced.indicator(terms.coefficients, speeds, y)

    weights = solver.term_weights(speeds, speeds)  # (n_speeds, n_terms)
    stack = solver.term_stack.tocsr()
    n = free.size
    blocks = [stack[k * n : (k + 1) * n] for k in range(len(solver.term_names))]
    for i, s in enumerate(speeds):
        Z = sum(weights[i, k] * blocks[k] for k in range(len(blocks)))
        q = reduced.V @ y[i]
        r = s * s * rhs - Z @ q
        expected = np.linalg.norm(r) * np.linalg.norm(y[i]) / (s * s * np.linalg.norm(reduced.V.conj().T @ rhs))
        assert expected > 0
        assert got[i] == pytest.approx(expected, rel=1e-6)
