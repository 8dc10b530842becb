"""The hysteretic loss weights against their rotating-frame derivation (Genta 2005, §4.6).

A harmonic lateral response Re(X e^{iωt}), ω ≥ 0, splits into a forward circular part P_F X and a
backward one P_B X, P_F = (I + iS)/2, P_B = (I − iS)/2 (S: the −90° rotation of each node's
lateral pair, S² = −I). The rotating material sees the forward part at ω − Ω and the backward
one at −(ω + Ω); a hysteretic loss i η k sgn(ν) at strain frequency ν gives the loss force
i K (σ_B P_B + σ P_F) X, σ = sgn(ω − Ω), σ_B = sgn(ω + Ω). Expanding the projectors,

    i (σ_B P_B + σ P_F) = a I + b S,   a = i (σ_B + σ)/2 (lateral),  b = (σ_B − σ)/2 (circulatory).

The test does that expansion numerically with a 2×2 S (no formula taken from the code) and
compares the package's weights on each side of the synchronous line and on it (σ = 0). The
fixed-frame model of the thesis (eqs. 2.39-2.40) is L(ω) = i sgn(ω)(F + K_lat): no loss at ω = 0
(a static load meets the storage stiffness only). Exact arithmetic: compared to 1e-15.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.loss import eigen_coefficients, frequency_coefficient_arrays, frequency_coefficients

S = np.array([[0.0, 1.0], [-1.0, 0.0]])  # −90° rotation of (v, w); S @ S = −I
I2 = np.eye(2)


def _rotating_weights(sigma: float, sigma_backward: float) -> tuple[complex, float]:
    """(lateral, circulatory) from i (σ_B P_B + σ P_F) = a I + b S, solved on the 2×2 matrices."""
    P_F, P_B = (I2 + 1j * S) / 2, (I2 - 1j * S) / 2
    M = 1j * (sigma_backward * P_B + sigma * P_F)
    basis = np.column_stack([I2.ravel(), S.ravel()]).astype(complex)
    (a, b), *_ = np.linalg.lstsq(basis, M.ravel(), rcond=None)
    assert np.allclose(a * I2 + b * S, M, atol=1e-15)
    assert abs(b.imag) < 1e-15
    return complex(a), float(b.real)


@pytest.mark.parametrize("sigma", [-1.0, 0.0, 1.0])
def test_eigen_weights_on_a_chosen_side_are_the_rotating_frame_projection(sigma):
    speed, omega = 300.0, 120.0  # a mode at ω > 0 on a spinning shaft: σ_B = 1
    lateral, circulatory = _rotating_weights(sigma, 1.0)
    w = eigen_coefficients("rotating", omega, speed, sigma)
    assert w.fixed == 1j
    assert w.lateral == pytest.approx(lateral, abs=1e-15)
    assert w.circulatory == pytest.approx(circulatory, abs=1e-15)


@pytest.mark.parametrize("omega", [0.5 * 300.0, 300.0, 2.0 * 300.0])
def test_frequency_weights_follow_the_whirl_side(omega):
    speed = 300.0
    sigma = float(np.sign(omega - speed))
    lateral, circulatory = _rotating_weights(sigma, 1.0)
    for w in (frequency_coefficients("rotating", omega, speed), eigen_coefficients("rotating", omega, speed)):
        assert w.lateral == pytest.approx(lateral, abs=1e-15)
        assert w.circulatory == pytest.approx(circulatory, abs=1e-15)


def test_thesis_complex_stiffness_is_i_sign_omega():
    speed = 300.0
    for omega, sign in ((0.0, 0.0), (50.0, 1.0), (900.0, 1.0)):
        w = frequency_coefficients("thesis", omega, speed)
        assert (w.fixed, w.lateral, w.circulatory) == (1j * sign, 1j * sign, 0.0)
    fixed, lateral, circulatory = frequency_coefficient_arrays("thesis", np.array([0.0, 50.0]), speed)
    np.testing.assert_array_equal(fixed, [0.0, 1j])
    np.testing.assert_array_equal(lateral, [0.0, 1j])
    np.testing.assert_array_equal(circulatory, [0.0, 0.0])
