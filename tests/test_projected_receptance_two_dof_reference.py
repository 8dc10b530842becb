"""The projected closed-loop receptance of LocalModels (flexshaft.analyses.local_projection)
against the closed-form receptances of a two-degree-of-freedom chain, with a non-collocated
loop (actuated at one mass, sensed at the other) beside a collocated one.

The chain (derived here): mass m₁ tied to ground by k₁, c₁ and to mass m₂ by k₂, c₂, so

    Z(ω) = K + iω C − ω² M = [[a, −b], [−b, d]],
    a = k₁ + k₂ + iω(c₁ + c₂) − ω² m₁,  b = k₂ + iω c₂,  d = k₂ + iω c₂ − ω² m₂,

and by Cramer's rule, with Δ = a d − b², the receptances are

    x₁/f₁ = d/Δ,  x₂/f₁ = x₁/f₂ = b/Δ,  x₂/f₂ = a/Δ.

A loop actuated at mass 1 and sensed at mass 2 has P_c = b/Δ; one actuated and sensed at
mass 2 has P_c = a/Δ; LocalModels.closed returns T = G(iω) P_c with each loop's own G.

The models are given the responses at two grid frequencies (50 and 200 rad/s, on either side
of the two natural frequencies √5000 ≈ 70.7 and √20000 ≈ 141.4 rad/s, ω² the roots of
2λ² − 5·10⁴ λ + 2·10⁸ = 0). Two independent vectors of ℂ² span ℂ², so the Galerkin model is the
full one and must reproduce the closed form at every frequency, not only at the two grid
points: probes at 30, 90, 120 and 300 rad/s. The terms are handed over through a small
stand-in of the solver's documented interface (term_weights rows [1, −ω², iω]; project and
project_pairs give Uᴴ T_k W of the terms K, M, C).

Tolerance 1e-11 relative: the basis is two well-separated responses (QR well conditioned) and
the 2×2 projected solve loses κ(Z) ≲ 1e2 of the 1e-16 working precision at these probes (the
closest, 120 rad/s, is 15 % below √20000 ≈ 141.4 rad/s; damping ratios of a few per cent);
1e-11 leaves a thousandfold margin for BLAS kernels, while a wrong sensing row (x₁/f₁ in place
of x₂/f₁) changes P_c by tens of per cent or more.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.local_projection import LocalModels

M1, M2 = 2.0, 1.0  # [kg]
K1, K2 = 2.0e4, 1.0e4  # [N/m]
C1, C2 = 4.0, 2.0  # [N s/m]


def _entries(omega):
    """a, b, d of the docstring's Z(ω) = [[a, −b], [−b, d]]."""
    a = K1 + K2 + 1j * omega * (C1 + C2) - omega**2 * M1
    b = K2 + 1j * omega * C2
    d = K2 + 1j * omega * C2 - omega**2 * M2
    return a, b, d


def _response(omega, rhs):
    """Z(ω)⁻¹ rhs by the explicit 2×2 inverse (adjugate over Δ)."""
    a, b, d = _entries(omega)
    inverse = np.array([[d, b], [b, a]]) / (a * d - b * b)
    return inverse @ rhs


class _ChainTerms:
    """The chain's terms K, M, C in the interface LocalModels reads from its solver."""

    def __init__(self):
        K = np.array([[K1 + K2, -K2], [-K2, K2]])
        M = np.diag([M1, M2])
        C = np.array([[C1 + C2, -C2], [-C2, C2]])
        self.terms = np.stack([K, M, C]).astype(complex)

    def term_weights(self, omegas, speeds):
        omegas = np.asarray(omegas, dtype=float)
        return np.column_stack([np.ones(omegas.size), -(omegas**2), 1j * omegas])

    def project_pairs(self, left, right):
        return np.einsum("mia,kij,mjb->mkab", left.conj(), self.terms, right)

    def project(self, bases):
        return self.project_pairs(bases, bases)


def _gains(omegas):
    """Loop 0 a PD law 3000 + 5 iω [N/m], loop 1 a lag 800/(1 + iω/400): different on purpose."""
    omegas = np.asarray(omegas, dtype=float)
    return np.array([3000.0 + 5.0j * omegas, 800.0 / (1.0 + 1j * omegas / 400.0)])


def test_projected_receptance_of_a_non_collocated_loop_is_the_cramer_closed_form():
    rhs = np.array([[1.0, 0.0], [0.0, 1.0]], dtype=complex)  # loop 0 pushes mass 1, loop 1 mass 2
    sense = np.array([[0.0, 1.0], [0.0, 1.0]])  # both loops sense mass 2
    grid = np.array([50.0, 200.0])  # [rad/s]
    responses = [_response(w, rhs) for w in grid]
    local = LocalModels(_ChainTerms(), 0.0, responses, [[0, 1], [0, 1]], [0, 1], rhs, sense, _gains)

    probes = np.array([30.0, 90.0, 120.0, 300.0])  # [rad/s]
    a, b, d = _entries(probes)
    delta = a * d - b * b
    G = _gains(probes)
    expected = {0: G[0] * b / delta, 1: G[1] * a / delta}  # x₂/f₁ and x₂/f₂
    for interval in (0, 1):
        got = local.closed(probes, np.full(probes.size, interval))
        assert np.all(np.abs(got - expected[interval]) <= 1e-11 * np.abs(expected[interval]))
