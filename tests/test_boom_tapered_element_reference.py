"""A tapered tailboom element against the exact energy integrals of cubic deflections and a twist.

Reference: the element's model (elements/boom.py) is an Euler-Bernoulli beam with rotary
inertia in two planes plus St Venant torsion, so for a deflection f of the cubic Hermite space
(and a twist linear in x) the element's energies of its nodal values are exact integrals:

    v-plane (γ = dv/dx):   qᵀKq = ∫₀ᴸ E I_z (v'')² dx,   qᵀMq = ∫₀ᴸ ρ (A v² + I_z γ²) dx
    w-plane (β = −dw/dx):  qᵀKq = ∫₀ᴸ E I_y (w'')² dx,   qᵀMq = ∫₀ᴸ ρ (A w² + I_y β²) dx
    torsion:               qᵀKq = ∫₀ᴸ G J (θ')² dx,      qᵀMq = ∫₀ᴸ ρ (I_y + I_z) θ² dx

With f = (c + x)³: f'' = 6(c + x), so for c = 0 the stiffness is ∫E I 36x² dx (nodal values
f₂ = L³ and slope 3L², zero at node 1) and for c = 1 the deflection and slope at node 1 are
1 and 3 as well. With θ = x (θ₁ = 0, θ₂ = L): ∫G J dx and ∫ρ(I_y + I_z) x² dx. The integrands
are polynomials, integrated here exactly by numpy.polynomial (coefficient arithmetic, no
quadrature, no shape functions).

Two sections. (1) A thin circular tube r(x) = r₀ + s x from ``ellipse_section`` (a = b = r):
A = 2πrt, I_z = πr³t, exact to round-off in its trapezoidal perimeter sums (integrands are
trigonometric polynomials of degree 2). A circle cannot tell I_y from I_z, so (2) a section of
our own (the element accepts any ``section_at``) with distinct polynomials on [0, L = 2 m]:
A = A₀(1 − x/4), I_z = I₀(1 − x/4)³, I_y = I₀(2 − x/2 + x²/8) (twice I_z at x = 0, twelve
times at x = L), J = J₀(1 − x/4)²: I_y in place of I_z (or back) changes the bending strain
energies 4.7- to 5.9-fold, and ∫J dx is 0.82 ∫(I_y + I_z) dx.

Tolerance 1e-12 relative. Basis: the element integrates with 6-point Gauss-Legendre, exact to
degree 11; the integrands here have degree ≤ 7 (section degree ≤ 3, mass f² degree 6), so the
only error is round-off: each matrix entry carries a few ulps (sums of 6 products), and the
quadratic form qᵀKq of 2 or 4 nodal values cancels by at most ~×20 (Σ|qᵢKᵢⱼqⱼ| / qᵀKq: about
9 for x³, 20 for (1 + x)³), so about 1e-14 at worst; measured ≤ 2e-15.

Numbers: r from 0.15 m to 0.075 m over L = 2 m, t = 2 mm, E = 70 GPa, G = E/2.6,
ρ = 2700 kg/m³; the own section A₀ = 2e-3 m², I₀ = 1e-5 m⁴, J₀ = 3e-5 m⁴.
"""

from __future__ import annotations

import numpy as np
import pytest
from numpy.polynomial import Polynomial as P

from flexshaft.elements.boom import EllipseSection, boom_element_matrices, ellipse_section

R0, R1, T_WALL, L = 0.15, 0.075, 0.002, 2.0
E, G, RHO = 70e9, 70e9 / 2.6, 2700.0
TOL = 1e-12
X = P([0.0, 1.0])

# the section of our own: distinct polynomials in x [m]
AREA = 2e-3 * (1 - X / 4)
I_Z = 1e-5 * (1 - X / 4) ** 3
I_Y = 1e-5 * (2 - X / 2 + X**2 / 8)
J = 3e-5 * (1 - X / 4) ** 2

# node DOFs [v, w, θ, β, γ], two nodes: 0..4 and 5..9
V, W, THETA, BETA, GAMMA = 0, 1, 2, 3, 4


def _polynomial_section(x):
    x = np.asarray(x, dtype=float)
    return EllipseSection(area=AREA(x), I_z=I_Z(x), I_y=I_Y(x), torsion_constant=J(x), perimeter=np.zeros_like(x))


def _bending_q(plane: str, f: P) -> np.ndarray:
    """Nodal values of the deflection f in one plane: (v, γ = f') or (w, β = −f')."""
    q = np.zeros(10)
    d, r, sign = (V, GAMMA, 1.0) if plane == "v" else (W, BETA, -1.0)
    for node, x in ((0, 0.0), (5, L)):
        q[node + d], q[node + r] = f(x), sign * f.deriv()(x)
    return q


def _rel(a: float, b: float) -> float:
    return abs(a - b) / abs(b)


def test_tapered_tube_energies_of_a_cubic_deflection_are_exact():
    def section_at(x):
        r = R0 + (R1 - R0) * np.asarray(x) / L
        return ellipse_section(r, r, T_WALL)

    M, K = boom_element_matrices([0.0, L], section_at, E, G, RHO)
    q = _bending_q("v", X**3)
    r = P([R0, (R1 - R0) / L])
    area, I_z = 2 * np.pi * T_WALL * r, np.pi * T_WALL * r**3
    strain = (E * I_z * (6 * X) ** 2).integ()(L)
    kinetic = (RHO * (area * X**6 + I_z * 9 * X**4)).integ()(L)
    assert _rel(q @ K[0] @ q, strain) <= TOL
    assert _rel(q @ M[0] @ q, kinetic) <= TOL


@pytest.mark.parametrize("c", [0.0, 1.0])
@pytest.mark.parametrize("plane", ["v", "w"])
def test_each_bending_plane_uses_its_own_second_moment(plane, c):
    M, K = boom_element_matrices([0.0, L], _polynomial_section, E, G, RHO)
    f = (c + X) ** 3
    q = _bending_q(plane, f)
    inertia = I_Z if plane == "v" else I_Y
    strain = (E * inertia * f.deriv(2) ** 2).integ()(L)
    kinetic = (RHO * (AREA * f**2 + inertia * f.deriv() ** 2)).integ()(L)
    assert _rel((q @ K[0] @ q).real, strain) <= TOL
    assert abs((q @ K[0] @ q).imag) == 0.0  # real moduli: no damping
    assert _rel(q @ M[0] @ q, kinetic) <= TOL


def test_a_linear_twist_uses_bredt_j_and_the_polar_second_moment():
    M, K = boom_element_matrices([0.0, L], _polynomial_section, E, G, RHO)
    q = np.zeros(10)
    q[5 + THETA] = L  # θ = x
    strain = (G * J).integ()(L)
    kinetic = (RHO * (I_Y + I_Z) * X**2).integ()(L)
    assert _rel((q @ K[0] @ q).real, strain) <= TOL
    assert _rel(q @ M[0] @ q, kinetic) <= TOL
