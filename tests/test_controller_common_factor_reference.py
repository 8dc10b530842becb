"""A control law's realization does not depend on how its transfer function is scaled: C(s) is
the ratio num(s)/den(s), so a common factor of numerator and denominator (a law typed from a
block diagram, or python-control's ``tf`` with an unnormalised denominator) changes nothing.

References, by long division done by hand (no polynomial code shared with the package):

* ``(2s² + 3s + 4)/(2s + 1) = s + 1 + 3/(2s + 1) = s + 1 + 1.5/(s + 0.5)``: the realization
  ``E s + D + C(sI − A)⁻¹B`` has E = 1, D = 1, one state with pole −0.5 and residue C·B = 1.5;
* the PD law ``k_p + k_d s`` written as ``(2 k_d s + 2 k_p)/2``: E = k_d (the damping the
  bearing adds, N s/m per unit current gain), D = k_p, no state.

Each value is a few floating-point operations on numbers of order one to 1e6: relative 1e-12
(round-off of about ten operations, ε ≈ 2e-16, with margin).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly.controller import Controller

S = np.array([3.0 + 40.0j, 1j * 250.0, -7.0 + 1.0j, 1j * 2.0e4])


def test_an_improper_law_with_a_non_monic_denominator_splits_by_long_division():
    law = Controller((2.0, 3.0, 4.0), (2.0, 1.0))
    A, B, C, D, E = law.realization()
    assert (E, D) == pytest.approx((1.0, 1.0), rel=1e-12)
    assert A.shape == (1, 1) and A[0, 0] == pytest.approx(-0.5, rel=1e-12)
    assert (C @ B).item() == pytest.approx(1.5, rel=1e-12)
    realized = [E * s + D + (C @ np.linalg.solve(s * np.eye(1) - A, B)).item() for s in S]
    np.testing.assert_allclose(realized, S + 1 + 1.5 / (S + 0.5), rtol=1e-12)


def test_a_pd_law_with_a_common_factor_keeps_its_derivative_gain():
    kp, kd = 2.0e6, 1.5e3
    law = Controller((2 * kd, 2 * kp), (2.0,))
    assert law.is_pd and law.kd == pytest.approx(kd, rel=1e-12) and law.kp == pytest.approx(kp, rel=1e-12)
    A, B, C, D, E = law.realization()
    assert A.shape == (0, 0)
    assert (E, D) == pytest.approx((kd, kp), rel=1e-12)
