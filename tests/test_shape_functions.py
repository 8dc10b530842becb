"""Exact properties of the beam shape functions (:mod:`flexshaft.elements.shape`).

Every reference is a closed form written here, never a number the code produced:

* a rigid translation and a rigid rotation (v = a + b x with the section rotation b, zero shear
  strain) are interpolated exactly for any shear parameter φ: the partition of unity of the
  interdependent interpolation (Reddy 1997);
* with φ = 0 the deflection functions are the Hermite cubics, which reproduce any cubic
  v(x) from its end values and slopes exactly, with γ = dv/dx;
* with φ > 0 they reproduce the exact Timoshenko solution of a cantilever under an end shear
  force P (Timoshenko & Gere, or by integrating EI ψ'' = −P and κGA (v' − ψ) = P):
  ψ(x) = P (L x − x²/2) / EI, v(x) = P (L x²/2 − x³/6) / EI + P x / (κGA),
  so that EI ψ' = P (L − x) and the shear strain v' − ψ = P/(κGA) is constant;
* u and θ are linear, with the strain d/dx per metre;
* the w-plane uses the right-hand rotation about y, β = −dw/dx (docs/model.md);
* Gauss-Legendre on [0, 1] with n points integrates ξᵏ exactly, ∫ξᵏ dξ = 1/(k + 1), k ≤ 2n − 1.

Tolerance: the functions are polynomials of degree ≤ 3 in ξ ∈ [0, 1] with O(1) coefficients
(φ ≤ 4, lengths O(1) m), evaluated in a few dozen operations: round-off is a few 1e-16 of the
largest term; ``TOL`` = 1e-12 relative to the field's scale leaves a wide margin.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.elements.shape import beam_shape, gauss_points

TOL = 1e-12
XI = np.linspace(0.0, 1.0, 7)
L = 0.7


def _dofs(**values) -> np.ndarray:
    """The 12 element DOFs [u1 v1 w1 θ1 β1 γ1 u2 v2 w2 θ2 β2 γ2] from named node values."""
    order = ("u1", "v1", "w1", "theta1", "beta1", "gamma1", "u2", "v2", "w2", "theta2", "beta2", "gamma2")
    return np.array([values.get(name, 0.0) for name in order])


@pytest.mark.parametrize("phi", [0.0, 0.3, 4.0])
def test_rigid_motion_is_exact_at_any_shear_parameter(phi):
    """v = a + b x with γ = b, w = c + d x with β = −d: interpolated exactly, no shear, no curvature."""
    a, b, c, d = 0.3, -1.7, -0.4, 2.1
    q = _dofs(v1=a, v2=a + b * L, gamma1=b, gamma2=b, w1=c, w2=c + d * L, beta1=-d, beta2=-d)
    s = beam_shape(XI, L, phi)
    x = XI * L
    np.testing.assert_allclose(s.N["v"] @ q, a + b * x, atol=TOL)
    np.testing.assert_allclose(s.N["gamma"] @ q, b, atol=TOL)
    np.testing.assert_allclose(s.N["w"] @ q, c + d * x, atol=TOL)
    np.testing.assert_allclose(s.N["beta"] @ q, -d, atol=TOL)
    for strain in (s.shear_v, s.shear_w, s.dgammadx, s.dbetadx):
        np.testing.assert_allclose(strain @ q, 0.0, atol=TOL)


def test_hermite_cubics_reproduce_any_cubic():
    """φ = 0: v(x) = c0 + c1 x + c2 x² + c3 x³ from its end values and slopes, exactly."""
    c0, c1, c2, c3 = 0.2, -0.5, 1.3, -2.2

    def v(x):
        return c0 + c1 * x + c2 * x**2 + c3 * x**3

    def dv(x):
        return c1 + 2 * c2 * x + 3 * c3 * x**2

    def d2v(x):
        return 2 * c2 + 6 * c3 * x

    q = _dofs(v1=v(0.0), v2=v(L), gamma1=dv(0.0), gamma2=dv(L), w1=v(0.0), w2=v(L), beta1=-dv(0.0), beta2=-dv(L))
    s = beam_shape(XI, L, 0.0)
    x = XI * L
    np.testing.assert_allclose(s.N["v"] @ q, v(x), atol=TOL)
    np.testing.assert_allclose(s.dvdx @ q, dv(x), atol=TOL)
    np.testing.assert_allclose(s.N["gamma"] @ q, dv(x), atol=TOL)
    np.testing.assert_allclose(s.dgammadx @ q, d2v(x), atol=TOL)
    np.testing.assert_allclose(s.N["w"] @ q, v(x), atol=TOL)
    np.testing.assert_allclose(s.N["beta"] @ q, -dv(x), atol=TOL)
    np.testing.assert_allclose(s.dbetadx @ q, -d2v(x), atol=TOL)


def test_timoshenko_cantilever_under_end_shear_is_exact():
    """The exact Timoshenko cantilever (clamped at x = 0, shear force P at x = L) interpolated
    from its end values by one element with φ = 12 EI / (κGA L²)."""
    EI, kGA, P = 3.0, 40.0, 1.0
    phi = 12 * EI / (kGA * L**2)

    def psi(x):
        return P * (L * x - x**2 / 2) / EI

    def v(x):
        return P * (L * x**2 / 2 - x**3 / 6) / EI + P * x / kGA

    q = _dofs(v2=v(L), gamma2=psi(L), w2=v(L), beta2=-psi(L))
    s = beam_shape(XI, L, phi)
    x = XI * L
    scale = v(L)
    np.testing.assert_allclose(s.N["v"] @ q, v(x), atol=TOL * scale)
    np.testing.assert_allclose(s.N["gamma"] @ q, psi(x), atol=TOL * scale)
    np.testing.assert_allclose(s.dgammadx @ q, P * (L - x) / EI, atol=TOL * scale)
    np.testing.assert_allclose(s.shear_v @ q, P / kGA, atol=TOL * scale)
    np.testing.assert_allclose(s.N["w"] @ q, v(x), atol=TOL * scale)
    np.testing.assert_allclose(s.dbetadx @ q, -P * (L - x) / EI, atol=TOL * scale)
    np.testing.assert_allclose(s.shear_w @ q, P / kGA, atol=TOL * scale)


def test_axial_and_twist_are_linear_with_strain_per_metre():
    """u = a + b x and θ = c + d x: du/dx = b [1/m·m], dθ/dx = d [rad/m]."""
    a, b, c, d = 0.1, 0.02, -0.3, 0.5
    q = _dofs(u1=a, u2=a + b * L, theta1=c, theta2=c + d * L)
    s = beam_shape(XI, L, 0.2)
    np.testing.assert_allclose(s.N["u"] @ q, a + b * XI * L, atol=TOL)
    np.testing.assert_allclose(s.N["theta"] @ q, c + d * XI * L, atol=TOL)
    np.testing.assert_allclose(s.dudx @ q, b, atol=TOL)
    np.testing.assert_allclose(s.dthetadx @ q, d, atol=TOL)


@pytest.mark.parametrize("n", [1, 2, 4])
def test_gauss_points_integrate_monomials_on_the_unit_interval(n):
    """∫₀¹ ξᵏ dξ = 1/(k + 1) for k ≤ 2n − 1 (k = 0: the weights sum to the interval's length 1)."""
    x, w = gauss_points(n)
    assert np.all((x > 0) & (x < 1))
    for k in range(2 * n):
        assert w @ x**k == pytest.approx(1.0 / (k + 1), rel=TOL)
