"""``Controller.derivative``: dC/ds of a bearing's transfer function, which the Newton
refinement of the closed-loop roots uses (a wrong derivative slows or stops the convergence).

References: the quotient rule done by hand for three laws (no polynomial code shared with the
package). Each is a few floating-point operations on numbers of order one to 1e8, so they agree
to a relative 1e-12 (round-off of about ten operations, ε ≈ 2e-16, with margin).
"""

from __future__ import annotations

import numpy as np

from flexshaft.assembly.controller import Controller

S = 1j * np.geomspace(1.0, 1e4, 40) + np.linspace(-50.0, 50.0, 40)  # around the imaginary axis


def test_pd_law_has_the_derivative_gain_as_its_slope():
    kp, kd = 1e6, 1250.0
    np.testing.assert_allclose(Controller((kd, kp), (1.0,)).derivative(S), kd, rtol=1e-12)


def test_first_order_lead_lag_by_the_quotient_rule():
    """C = (a s + b)/(c s + 1): C' = (a − b c)/(c s + 1)²."""
    a, b, c = 2e3, 1e7, 1.0 / 6000.0
    expected = (a - b * c) / (c * S + 1) ** 2
    np.testing.assert_allclose(Controller((a, b), (c, 1.0)).derivative(S), expected, rtol=1e-12)


def test_ideal_pid_with_a_leading_zero_in_its_numerator():
    """C = (k_d s² + k_p s + k_i)/s = k_d s + k_p + k_i/s: C' = k_d − k_i/s² (the numerator
    written with a leading zero coefficient, as a design file may give it)."""
    kd, kp, ki = 1e3, 1e6, 1e8
    expected = kd - ki / S**2
    law = Controller((0.0, kd, kp, ki), (1.0, 0.0))
    np.testing.assert_allclose(law.derivative(S), expected, rtol=1e-12)
