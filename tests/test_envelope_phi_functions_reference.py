"""Reference: the φ functions of the envelope's exponential integrator (hunt h40a).

ETDRK4 (Cox & Matthews 2002, J. Comput. Phys. 176, eq. 26; Kassam & Trefethen 2005) weighs its
stages with e^z and

    φ_k(z) = ∫₀¹ e^{(1−θ) z} θ^{k−1}/(k−1)! dθ,   k = 1, 2, 3

(Hochbruck & Ostermann 2010, Acta Numerica, eq. 2.10). The reference integrates that definition
with 40-point Gauss-Legendre quadrature, exact to round-off for an integrand this smooth
(|z| ≤ 4: the error bound (|z|^80/80!)·… is far below 1e-16), at points inside and outside the
Taylor series' disc (|z| < 0.25 in :func:`flexshaft.analyses.envelope.phi_functions`), on both
sides of the imaginary axis and on it (the envelope's undamped modes: z = λh with Re λ ≈ 0).
Tolerance 1e-12 relative to max(1, |φ_k|): the direct formula's cancellation loses about
|z|^{-k} ε near the disc's edge (0.25^{-3} × 1.1e-16 ≈ 7e-15); a 12-term series used out to
|z| = 3.5 would be off by its first omitted term, 3.5¹²/(12 + k)!: 5.4e-4 for φ₁, 2.6e-6
for φ₃.
"""

from __future__ import annotations

import math

import numpy as np

from flexshaft.analyses.envelope import phi_functions

Z = np.array([0.0, 0.1, 0.2 + 0.1j, -0.24j, 0.3 - 0.2j, 1.0, -2.0 + 1.5j, 3.5j, -3.9, 2.5 + 2.5j])


def _quadrature(z: complex, k: int) -> complex:
    x, w = np.polynomial.legendre.leggauss(40)
    theta = 0.5 * (x + 1.0)
    return complex(0.5 * np.sum(w * np.exp((1.0 - theta) * z) * theta ** (k - 1)) / math.factorial(k - 1))


def test_the_phi_functions_are_their_integral_definition():
    e, *phis = phi_functions(Z)
    np.testing.assert_allclose(e, np.exp(Z), rtol=1e-15)
    for k, phi in enumerate(phis, start=1):
        expected = np.array([_quadrature(z, k) for z in Z])
        error = np.abs(phi - expected) / np.maximum(1.0, np.abs(expected))
        assert error.max() < 1e-12, (k, Z[np.argmax(error)], error.max())
