"""The controller laws' constructors against their textbook transfer functions, evaluated by hand.

References (written out here, no polynomial code shared with the package):

* long division of an improper law into ``E s + D + C(sI − A)⁻¹B`` (its realization);
* filtered PD law ``C(s) = k_p + k_d s/(1 + s/ω_d)`` with the derivative filter's corner ω_d
  in rad/s (the derivative filter of Åström & Murray, *Feedback Systems*, 2008, ch. 10): its
  pole is at s = −ω_d and C(s) → k_p + k_d ω_d as s → ∞ (the realization's feedthrough D);
* first-order amplifier lag ``1/(1 + s/ω_a)``: −3 dB and −45° at s = iω_a.

Each value is a few floating-point operations on numbers of order one to 1e8: they agree to a
relative 1e-12 (round-off of about ten operations, ε ≈ 2e-16, with margin).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly.controller import Controller

KP, KD, WD = 2.0e6, 1.5e3, 2 * np.pi * 900.0
S = np.array([3.0 + 40.0j, 1j * 250.0, 1j * WD, -7.0 + 1.0j, 1j * 2.0e4])


def test_filtered_pd_law_is_kp_plus_a_first_order_filtered_derivative():
    law = Controller.pid(KP, 0.0, KD, WD)
    np.testing.assert_allclose(law(S), KP + KD * S / (1 + S / WD), rtol=1e-12)
    assert np.roots(law.denominator) == pytest.approx([-WD], rel=1e-12)  # the filter pole at −ω_d
    assert law.kp == pytest.approx(KP, rel=1e-12)
    A, B, C, D, E = law.realization()  # proper: no ideal derivative, the filter's one state
    assert E == 0.0 and A.shape == (1, 1) and A[0, 0] == pytest.approx(-WD, rel=1e-12)
    assert D == pytest.approx(KP + KD * WD, rel=1e-12)  # the high-frequency gain


def test_amplifier_lag_is_minus_3_db_and_minus_45_degrees_at_its_bandwidth():
    wa = 2 * np.pi * 1500.0
    lag = Controller.lag(wa)
    np.testing.assert_allclose(lag(S), 1.0 / (1 + S / wa), rtol=1e-12)
    at_corner = lag(1j * wa)
    assert abs(at_corner) == pytest.approx(1 / np.sqrt(2), rel=1e-12)
    assert np.angle(at_corner) == pytest.approx(-np.pi / 4, rel=1e-12)


def test_improper_law_splits_into_its_ideal_derivative_and_a_proper_remainder():
    """``(s² + 3s + 2)/(s + 5) = s − 2 + 12/(s + 5)`` by long division (done by hand): the
    realization's E = 1, D = −2, one state with pole −5 and residue C·B = 12."""
    law = Controller((1.0, 3.0, 2.0), (1.0, 5.0))
    A, B, C, D, E = law.realization()
    assert (E, D) == pytest.approx((1.0, -2.0), rel=1e-12)
    assert A.shape == (1, 1) and A[0, 0] == pytest.approx(-5.0, rel=1e-12)
    assert (C @ B).item() == pytest.approx(12.0, rel=1e-12)
    realized = [E * s + D + (C @ np.linalg.solve(s * np.eye(1) - A, B)).item() for s in S]
    np.testing.assert_allclose(realized, S - 2 + 12 / (S + 5), rtol=1e-12)
