"""The static gain and the modal-basis stiffness of controller laws, against their limits at s = 0.

References (by hand, no polynomial code shared with the package):

* PI law ``C(s) = k_p + k_I/s = (k_p s + k_I)/s``: as s → 0⁺ along the real axis
  C(s) → sign(k_I) · ∞ (the integral term dominates), so the static gain is +∞ for k_I > 0 and
  −∞ for k_I < 0 (a wrong-signed integrator pushes the displacement away statically);
* a first-order law ``C(s) = k/(1 + s/ω)``: C(0) = k, its proportional gain; the basis
  stiffness (:attr:`Controller.basis_stiffness`) is that gain when positive and 0 when negative
  (the basis problem K + Σ k_a BᵀB must stay positive semi-definite; the negative part enters
  through the state matrix), so k = −3e4 N/m gives 0, k = +3e4 gives 3e4;
* a filtered PD law ``k_p + k_d s/(1 + s/ω_d)`` with k_p < 0: C(0) = k_p < 0, basis stiffness 0.

The values are exact in binary (inf, 0) or one division of numbers of order 1e4 (rel 1e-12).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly.controller import Controller


@pytest.mark.parametrize("k_integral", [2.0e5, -2.0e5])
def test_a_pi_laws_static_gain_has_the_sign_of_its_integral_gain(k_integral):
    law = Controller((1.5e4, k_integral), (1.0, 0.0))
    assert law.integrates
    assert law.static_gain == np.sign(k_integral) * np.inf
    small = 1e-9  # C(s) on the positive real axis near 0 has the same sign (hand check)
    assert np.sign(law(small).real) == np.sign(k_integral)


@pytest.mark.parametrize("k", [3.0e4, -3.0e4])
def test_a_first_order_laws_basis_stiffness_is_its_positive_static_gain(k):
    law = Controller((k,), (1.0 / 800.0, 1.0))  # k/(1 + s/800), not a PD law
    assert not law.is_pd
    assert law.proportional_gain == pytest.approx(k, rel=1e-12)
    assert law.basis_stiffness == (pytest.approx(k, rel=1e-12) if k > 0 else 0.0)


def test_a_filtered_pd_law_with_negative_kp_adds_nothing_to_the_basis():
    law = Controller.pid(-2.0e4, 0.0, 12.0, 2 * np.pi * 500.0)
    assert not law.is_pd and law.proportional_gain == pytest.approx(-2.0e4, rel=1e-12)
    assert law.basis_stiffness == 0.0


def test_a_common_factor_at_megaradians_per_second_cancels():
    """``C(s) = k (s + p₁)(s + p₂)/((s + p₁)(s + p₂)(s + a))`` is ``k/(s + a)`` (cancelled by
    hand): one state, pole −a, residue k. With p₁ = 3e6, p₂ = 5.1e6 rad/s and a = 2.7e6 rad/s the
    computed roots of numerator and denominator differ by about 1e-8 rad/s (round-off ε|p| times
    the conditioning of three close roots): the pole-zero match must be relative to |p| (the
    code's 1e-9 |p| ≈ 3e-3 rad/s), not absolute. rel 1e-9 on the state's pole and residue: a
    root of a cubic with roots of order 1e6, computed to ~1e-14 relative."""
    k, p1, p2, a = 4.0e9, 3.0e6, 5.1e6, 2.7e6
    num = k * np.polymul([1.0, p1], [1.0, p2])
    law = Controller(tuple(num), tuple(np.polymul(np.polymul([1.0, p1], [1.0, p2]), [1.0, a])))
    A, B, C, D, E = law.realization()
    assert A.shape == (1, 1) and (D, E) == (0.0, 0.0)
    assert A[0, 0] == pytest.approx(-a, rel=1e-9)
    assert (C @ B).item() == pytest.approx(k, rel=1e-9)
