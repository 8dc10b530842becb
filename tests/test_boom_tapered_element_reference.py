"""A linearly tapered tailboom element against the exact energy integrals of a cubic deflection.

Reference: a thin-walled circular tube (both semi-axes r) of wall t has A = 2π r t and
I_z = π r³ t (the thin-ring second moment). With r(x) = r₀ + s x tapering linearly, A is a
polynomial of degree 1 and I_z of degree 3 in x. The cubic deflection v = x³ (slope
γ = dv/dx = 3x², curvature 6x) lies in the element's cubic Hermite space, so the element's
energies of its nodal values are the exact integrals (Euler-Bernoulli beam with rotary inertia,
the element's model, elements/boom.py):

    ½ qᵀ K q = ½ ∫₀ᴸ E I_z (6x)² dx,    ½ qᵀ M q = ½ ∫₀ᴸ ρ (A x⁶ + I_z 9x⁴) dx,

integrands of degree 5 and 7, integrated here exactly as polynomials (numpy.polynomial).
The section comes from ``ellipse_section`` with a = b = r, whose trapezoidal perimeter sums are
exact to round-off for a circle (the integrands are trigonometric polynomials of degree 2).
Agreement 1e-12 relative: a few roundings in sums of 10 terms.

Numbers: r from 0.15 m to 0.075 m over L = 2 m, t = 2 mm, E = 70 GPa, ρ = 2700 kg/m³.
"""

from __future__ import annotations

import numpy as np
from numpy.polynomial import Polynomial as P

from flexshaft.elements.boom import boom_element_matrices, ellipse_section

R0, R1, T_WALL, L = 0.15, 0.075, 0.002, 2.0
E, RHO = 70e9, 2700.0


def _radius(x):
    return R0 + (R1 - R0) * np.asarray(x) / L


def test_tapered_element_energies_of_a_cubic_deflection_are_exact():
    def section_at(x):
        r = _radius(x)
        return ellipse_section(r, r, T_WALL)

    M, K = boom_element_matrices([0.0, L], section_at, E, E / 2.6, RHO)
    # DOFs [v, w, θ, β, γ] at each node, γ = dv/dx: v = x³ gives v₂ = L³, γ₂ = 3L² (zero at x = 0)
    q = np.zeros(10)
    q[5], q[9] = L**3, 3 * L**2
    r = P([R0, (R1 - R0) / L])
    area, I_z = 2 * np.pi * T_WALL * r, np.pi * T_WALL * r**3
    x = P([0.0, 1.0])
    strain = (E * I_z * (6 * x) ** 2).integ()(L)
    kinetic = (RHO * (area * x**6 + I_z * 9 * x**4)).integ()(L)
    assert abs(q @ K[0] @ q - strain) <= 1e-12 * strain
    assert abs(q @ M[0] @ q - kinetic) <= 1e-12 * kinetic
