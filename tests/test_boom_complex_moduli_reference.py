"""The tailboom element carries the loss factors of E* and G* into its bending and twist stiffness.

Reference: the element (elements/boom.py) is an Euler-Bernoulli beam plus St Venant torsion
with complex moduli E* = E(1 + iη_E), G* = G(1 + iη_G) (structural damping of the boom). For a
uniform thin circular tube of radius r and wall t (``ellipse_section`` with a = b = r) the
section constants are closed forms: I_z = I_y = π r³ t and Bredt's J = 4 (π r²)² t / (2π r)
= 2π r³ t. The energies of two exact fields of the element's (Hermite cubic, linear twist)
space are then, by hand:

    twist θ = x (θ₁ = 0, θ₂ = L):          qᵀKq = ∫₀ᴸ G* J (θ')² dx = G* J L
    v-bending v = x³ (v₂ = L³, γ₂ = 3L²):   qᵀKq = ∫₀ᴸ E* I_z (6x)² dx = 12 E* I_z L³

so Im(qᵀKq)/Re(qᵀKq) is η_G for the twist and η_E for the bending: the two loss factors are
chosen different (0.02 and 0.05) so that either one taken for the other, or either one
dropped, is seen.

Tolerance 1e-12 relative. Basis: the element integrates with 6-point Gauss-Legendre, exact for
these constant-section integrands of degree ≤ 4; the trapezoidal perimeter sums of a circle are
exact to round-off (trigonometric polynomials of degree 2), so only a few ulps remain (the
quadratic forms of 2 nodal values cancel by at most ~×10).

Numbers: r = 0.1 m, t = 2 mm, L = 1.5 m, E = 70 GPa, G = E/2.6, ρ = 2700 kg/m³.
"""

from __future__ import annotations

import numpy as np

from flexshaft.elements.boom import boom_element_matrices, ellipse_section

R, T_WALL, L = 0.1, 0.002, 1.5
E, G, RHO = 70e9, 70e9 / 2.6, 2700.0
ETA_E, ETA_G = 0.05, 0.02
TOL = 1e-12

# node DOFs [v, w, θ, β, γ], two nodes: 0..4 and 5..9
V, THETA, GAMMA = 0, 2, 4


def _stiffness():
    def section_at(x):
        x = np.asarray(x, dtype=float)
        return ellipse_section(np.full(x.shape, R), np.full(x.shape, R), np.full(x.shape, T_WALL))

    _, K = boom_element_matrices([0.0, L], section_at, E * (1 + 1j * ETA_E), G * (1 + 1j * ETA_G), RHO)
    return K[0]


def test_twist_energy_carries_the_shear_loss_factor():
    q = np.zeros(10)
    q[5 + THETA] = L
    energy = q @ _stiffness() @ q
    expected = G * (1 + 1j * ETA_G) * (2 * np.pi * R**3 * T_WALL) * L
    assert abs(energy - expected) <= TOL * abs(expected)


def test_bending_energy_carries_the_youngs_loss_factor():
    q = np.zeros(10)
    q[5 + V], q[5 + GAMMA] = L**3, 3 * L**2
    energy = q @ _stiffness() @ q
    expected = 12 * E * (1 + 1j * ETA_E) * (np.pi * R**3 * T_WALL) * L**3
    assert abs(energy - expected) <= TOL * abs(expected)
