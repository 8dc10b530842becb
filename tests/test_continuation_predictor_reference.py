"""Newton's starting point of a continuation step reproduces the curves it extrapolates exactly.

:func:`flexshaft.analyses.continuation.predicted_start` (its docstring states the rule) takes
the eigenvalues at speeds[k] from Lagrange's quadratic through the last three speeds (the line
through the last two at k = 2) and each mode's shape from the line through its last two
shapes, the older one turned first to the phase of the newer (``Y_old`` times
``Y_oldᴴ Y_prev / |Y_oldᴴ Y_prev|``), where the two agree with a MAC of at least
EXTRAPOLATED_SHAPE_MAC (else the last shape alone).

References derived here (interpolation is exact on its own polynomial degree):

* the quadratic through three points of a quadratic ``s(Ω) = a + bΩ + cΩ²`` is that quadratic,
  so the predicted eigenvalue at a fourth, unevenly spaced speed is ``s(Ω_k)``; the line
  through two points of a line is that line;
* a shape ``Y(Ω) = e^{iθ(Ω)} (y₀ + Ω y₁)`` with real ``y₀, y₁`` and an arbitrary phase per
  speed (an eigenvector's phase is arbitrary): ``Y_oldᴴ Y_prev = e^{i(θ₂−θ₁)} (y₀ + Ω₁y₁)ᵀ(y₀ +
  Ω₂y₁)``, whose real factor is positive for the small ``y₁`` taken here, so the turned old
  shape is ``e^{iθ₂}(y₀ + Ω₁y₁)`` and the line through it and ``Y_prev`` at Ω_k is
  ``e^{iθ₂}(y₀ + Ω_k y₁)``;
* two shapes of MAC 0 (orthogonal) are not extrapolated: the start is the last shape.

Tolerance 1e-12 relative: a few multiplications of numbers of order 1-10 (double precision
round-off ~1e-15 each, amplified at most by the Lagrange weights, |l_j| ≤ 3.4 at these speeds).
CPU: microseconds.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.continuation import EXTRAPOLATED_SHAPE_MAC, predicted_start

SPEEDS = np.array([0.0, 1.0, 3.0, 4.5])  # uneven steps: a wrong Lagrange weight shows
A = np.array([-0.3 + 10.0j, -1.0 + 25.0j])
B = np.array([0.05 + 1.5j, 0.2 - 0.7j])
C = np.array([-0.01 + 0.4j, 0.03 + 0.25j])


def _eigenvalues(speed: float) -> np.ndarray:
    return A + B * speed + C * speed**2


def _shapes(speed: float, phase: float, y0: np.ndarray, y1: np.ndarray) -> np.ndarray:
    return np.exp(1j * phase) * (y0 + speed * y1)


def test_the_predicted_eigenvalues_lie_on_the_quadratic_and_the_line():
    eig = [_eigenvalues(x) for x in SPEEDS]
    states = [np.eye(2, dtype=complex) for _ in SPEEDS]
    predicted, _ = predicted_start(SPEEDS, eig, states, 3)  # quadratic through speeds 0, 1, 3
    np.testing.assert_allclose(predicted, _eigenvalues(SPEEDS[3]), rtol=1e-12)
    line = [A + B * x for x in SPEEDS]
    predicted, _ = predicted_start(SPEEDS, line, states, 2)  # line through speeds 0, 1
    np.testing.assert_allclose(predicted, A + B * SPEEDS[2], rtol=1e-12)


def test_the_start_shape_is_the_line_through_the_last_two_shapes_in_the_newer_phase():
    rng = np.random.default_rng(57)
    y0 = rng.standard_normal((6, 2))
    y1 = 0.02 * rng.standard_normal((6, 2))  # the shape changes slowly: MAC near 1
    phases = [0.3, -1.1, 2.4, 0.0]  # each speed's eigenvector phase, arbitrary
    states = [_shapes(x, p, y0, y1) for x, p in zip(SPEEDS, phases)]
    # the second mode's shape at the last speed is orthogonal to its shape before: no extrapolation
    turned = states[2].copy()
    turned[:, 1] = np.exp(0.7j) * np.linalg.svd(states[1][:, 1:2].conj().T)[2][-1].conj()
    assert abs(np.vdot(states[1][:, 1], turned[:, 1])) < 1e-12
    assert EXTRAPOLATED_SHAPE_MAC > 0  # orthogonal shapes are below the gate
    eig = [_eigenvalues(x) for x in SPEEDS]
    _, start = predicted_start(SPEEDS, eig, [states[0], states[1], turned], 3)
    expected = _shapes(SPEEDS[3], phases[2], y0[:, 0], y1[:, 0])
    np.testing.assert_allclose(start[:, 0], expected, rtol=0, atol=1e-12 * np.abs(expected).max())
    np.testing.assert_allclose(start[:, 1], turned[:, 1], rtol=0, atol=1e-12)
    # the same two shapes at k = 2 extrapolate from speed 1 to speed 3
    _, start = predicted_start(SPEEDS, eig, states, 2)
    expected = _shapes(SPEEDS[2], phases[1], y0, y1)
    np.testing.assert_allclose(start, expected, rtol=0, atol=1e-12 * np.abs(expected).max())
