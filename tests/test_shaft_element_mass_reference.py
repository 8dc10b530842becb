"""The shaft element's consistent mass matrix in one bending plane, against its closed form.

With the Hermite cubics N₁ = 1 − 3ξ² + 2ξ³, N₂ = L(ξ − 2ξ² + ξ³), N₃ = 3ξ² − 2ξ³,
N₄ = L(−ξ² + ξ³) on ξ = x/L ∈ [0, 1] for (v_a, γ_a, v_b, γ_b), γ = dv/dx, the kinetic
energy's two parts integrate by hand (polynomials of degree 6 and 4) to the classic
consistent matrices (e.g. Przemieniecki 1968, Theory of Matrix Structural Analysis, ch. 11;
the module's reference, Nelson 1980, for the rotary part):

    translation  ρA L/420 · [[156, 22L, 54, −13L], [22L, 4L², 13L, −3L²],
                              [54, 13L, 156, −22L], [−13L, −3L², −22L, 4L²]]
    rotary       ρI/(30L) · [[36, 3L, −36, 3L], [3L, 4L², −3L, −L²],
                              [−36, −3L, 36, −3L], [3L, −L², −3L, 4L²]]

The element's DOFs are (u, v, w, θ, β, γ) at each node (:data:`SHAFT_FIELDS`), so the v-plane
rows are 1, 5, 7, 11. The translational block's products are of degree 6: a Gauss rule of
fewer than four points does not integrate them exactly (three points: exact to degree 5). The
numbers (steel, D 0.1 m, wall 5 mm, L = 0.37 m) are binary-inexact, so the assertion is to
1e-13 relative to the largest entry (round-off of a 4-point sum, ~1e-16).

Written for the mutation h37c-shaft-three-gauss-points of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np

from flexshaft.elements.shaft import TubeSection, shaft_element_matrices


def test_the_v_plane_mass_is_the_consistent_translational_plus_rotary_matrix():
    L, rho = 0.37, 7800.0
    section = TubeSection(0.1, 0.09)
    A = np.pi * (0.1**2 - 0.09**2) / 4
    I = np.pi * (0.1**4 - 0.09**4) / 64
    M, _, _ = shaft_element_matrices([L], section, 210e9, 80e9, rho)
    translation = (rho * A * L / 420) * np.array(
        [
            [156, 22 * L, 54, -13 * L],
            [22 * L, 4 * L**2, 13 * L, -3 * L**2],
            [54, 13 * L, 156, -22 * L],
            [-13 * L, -3 * L**2, -22 * L, 4 * L**2],
        ]
    )
    rotary = (rho * I / (30 * L)) * np.array(
        [
            [36, 3 * L, -36, 3 * L],
            [3 * L, 4 * L**2, -3 * L, -(L**2)],
            [-36, -3 * L, 36, -3 * L],
            [3 * L, -(L**2), -3 * L, 4 * L**2],
        ]
    )
    expected = translation + rotary
    plane = [1, 5, 7, 11]
    got = M[0][np.ix_(plane, plane)]
    assert np.max(np.abs(got - expected)) <= 1e-13 * np.max(np.abs(expected))
