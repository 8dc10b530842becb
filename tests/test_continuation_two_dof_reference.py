"""The batched continuation step (:mod:`flexshaft.analyses.continuation`) on a two-coordinate rotor
whose roots are closed forms.

Reference (derived). A reduced model assembled by hand: two modal coordinates y = (v, w) of unit
mass, stiffness ω₀² I, a dashpot c I, gyroscopic γ J, and the loss matrices of an isotropic
shaft, F = η_f ω₀² I (fixed-frame loss), K_lat = η ω₀² I and K_lat S = η ω₀² J, with
J = [[0, 1], [−1, 0]]. Every matrix commutes with J, whose eigenvectors are y₊ = (1, i)/√2
(J y₊ = i y₊) and y₋ = (1, −i)/√2 (J y₋ = −i y₋), so ``T(s) = s² I + s(ΩG + C) + Λ + Σ w_X X``
is diagonal on them:

    on y±:  s² + s(c ± iΩγ) + ω₀² + w_F η_f ω₀² + w_L η ω₀² ± i w_S η ω₀²,

with the hysteretic weights (w_F, w_L, w_S) of :func:`~flexshaft.analyses.loss.frequency_coefficients`:
(i, i, 0) above the spin and (i, 0, 1) below it. So on y₊ the stiffness is ω₀²(1 + iη_f + iη)
on both sides, on y₋ it is ω₀²(1 + iη_f + iη) above the spin and ω₀²(1 + iη_f − iη) below it:
y₋ is the mode the rotating loss destabilises (the Jeffcott rotor's forward whirl, tests/
test_stability.py). Each root is that of a scalar quadratic, solved here by numpy.roots.

Tolerances: the roots are exact up to round-off of a 2 × 2 problem; Newton's method stops when
a step is below 1e-10 |s| and converges quadratically, so what is left is far below 1e-12 |s|
(asserted). Each test runs a few 2 × 2 solves (milliseconds).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.continuation import mode_roots, newton_many
from flexshaft.analyses.eigen import ReducedModel
from flexshaft.analyses.loss import LossCoefficients

W0 = 100.0  # rad/s
J = np.array([[0.0, 1.0], [-1.0, 0.0]])
Y_PLUS = np.array([1.0, 1j]) / np.sqrt(2)  # J y = +i y
Y_MINUS = np.array([1.0, -1j]) / np.sqrt(2)  # J y = -i y
assert np.allclose(J @ Y_PLUS, 1j * Y_PLUS) and np.allclose(J @ Y_MINUS, -1j * Y_MINUS)


def model(c=0.0, gamma=0.0, eta=0.0, eta_f=0.0):
    loss = bool(eta or eta_f)
    return ReducedModel(
        Phi=np.eye(2),
        w2=np.full(2, W0**2),
        G=gamma * J,
        C=c * np.eye(2),
        F=eta_f * W0**2 * np.eye(2),
        L=eta * W0**2 * np.eye(2),
        S=eta * W0**2 * J,
        internal_damping="rotating",
        actuators=(),
        has_loss=loss,
    )


def quadratic_roots(damping, stiffness):
    """Both roots of s² + damping s + stiffness = 0, (upper, lower) by Im s."""
    r = np.roots([1.0, damping, stiffness])
    return tuple(sorted(r, key=lambda z: -z.imag))


def loss_free_roots(c, gamma, speed):
    """Roots on y₊ (damping c + iΩγ) and y₋ (c − iΩγ), stiffness ω₀²."""
    return quadratic_roots(c + 1j * speed * gamma, W0**2), quadratic_roots(c - 1j * speed * gamma, W0**2)


def test_every_root_converges_from_a_near_start_to_the_closed_form():
    """Four roots of the loss-free spinning rotor at once (forward and backward whirl and their
    lower-half-plane partners), each from a start 5e-5 |s| away and with a start vector mixing
    in 2 % of the other whirl: each returns its own root to 1e-12 |s|, a unit vector on its
    own whirl (the other whirl's share below 1e-9), and ``converged`` True only for Im s > 0
    (the lower-half-plane roots are no eigenvalues of the hysteretic problem: eigen.newton's
    contract). A start 5e-5 |s| off makes the first step 5e-5 |s| long: a convergence test
    looser than that stops there, 1e-9 |s| from the root (quadratic convergence)."""
    c, gamma, speed = 2 * 0.01 * W0, 0.4, 0.6 * W0
    (p_up, p_low), (m_up, m_low) = loss_free_roots(c, gamma, speed)
    want = np.array([p_up, m_up, p_low, m_low])
    vectors = [Y_PLUS, Y_MINUS, Y_PLUS, Y_MINUS]
    others = [Y_MINUS, Y_PLUS, Y_MINUS, Y_PLUS]
    start_Y = np.column_stack([v + 0.02 * o for v, o in zip(vectors, others)])
    start_s = want * (1 + 5e-5 * np.exp(0.7j))
    s, Y, converged = newton_many(model(c, gamma), speed, start_s, start_Y, weights=LossCoefficients(0, 0, 0))
    np.testing.assert_allclose(s, want, rtol=1e-12, atol=0)
    assert list(converged) == [True, True, False, False]
    np.testing.assert_allclose(np.linalg.norm(Y, axis=0), 1.0, rtol=1e-12)
    for k, other in enumerate(others):
        assert abs(np.vdot(other, Y[:, k])) < 1e-9


def test_a_far_start_converges_as_newtons_method_on_the_scalar_quadratic():
    """From 3 % off the root (the step's derivative must be the true d/ds of s² + s d + k, 2s + d:
    with s + d instead the iteration contracts by |1 − (2s + d)/(s + d)| ≈ 1 and never
    converges in the 30 steps), the damped forward root of the hysteretic rotor above the
    spin: s² + c s + ω₀²(1 + iη_f + iη) = 0."""
    c, eta, eta_f = 2 * 0.005 * W0, 0.02, 0.01
    want = quadratic_roots(c, W0**2 * (1 + 1j * (eta_f + eta)))[0]
    s, Y, converged = newton_many(
        model(c, 0.0, eta, eta_f), 0.5 * W0, [want * 1.03], Y_MINUS[:, None], weights=LossCoefficients(1j, 1j, 0)
    )
    assert converged[0]
    assert s[0] == pytest.approx(want, rel=1e-12)


@pytest.mark.parametrize("ratio", [0.8, 1.3])
def test_each_mode_takes_the_root_of_its_own_side_of_the_line(ratio):
    """mode_roots at Ω = 0.8 ω_d and 1.3 ω_d (ω_d the forward roots' common frequency: the two
    sides' roots on y₋ are s₋ = −c − s̄₊ exactly), from starts 1e-3 off: the backward whirl y₊
    has s₊ at every speed; the forward whirl y₋ has s₊ (stable) while ω_d lies above the spin
    (Ω < ω_d: the upper weights hold) and s₋ once it lies below (Ω > ω_d; Re s₋ =
    (ηω₀ − c)/2 + O(η²) > 0: unstable)."""
    c, eta = 2 * 0.005 * W0, 0.02
    s_plus = quadratic_roots(c, W0**2 * (1 + 1j * eta))[0]
    s_minus = quadratic_roots(c, W0**2 * (1 - 1j * eta))[0]
    assert s_minus == pytest.approx(-c - np.conj(s_plus), rel=1e-14)
    speed = ratio * s_plus.imag
    forward = s_plus if ratio < 1 else s_minus
    want = np.array([s_plus, forward])
    start = want * (1 + 1e-3j)
    s, Y, found = mode_roots(model(c, 0.0, eta), speed, start, np.column_stack([Y_PLUS, Y_MINUS]))
    assert found.all()
    np.testing.assert_allclose(s, want, rtol=1e-12, atol=0)
    assert (s[1].real > 0) == (ratio > 1)


def test_a_start_above_the_spin_whose_root_lies_below_it_takes_the_lower_sides_root():
    """Ω = 1.5 ω_d, the forward whirl started at 1.6 ω_d (above the spin, so the upper side is
    solved first): the upper side's root s₊ has frequency ω_d < Ω, where the upper weights do
    not hold, so it is no eigenvalue; the lower side's s₋ (unstable) is."""
    c, eta = 2 * 0.005 * W0, 0.02
    s_plus = quadratic_roots(c, W0**2 * (1 + 1j * eta))[0]
    s_minus = quadratic_roots(c, W0**2 * (1 - 1j * eta))[0]
    speed = 1.5 * s_plus.imag
    s, _, found = mode_roots(model(c, 0.0, eta), speed, [s_plus.real + 1.6j * s_plus.imag], Y_MINUS[:, None])
    assert found[0]
    assert s[0] == pytest.approx(s_minus, rel=1e-12)


def test_a_fold_reports_the_less_stable_root():
    """With fixed-frame loss η_f the two sides' forward roots no longer share a frequency:
    Im s of s² + c s + ω₀²(1 + iα) grows with α², so s₊ (α = η_f + η) lies above s₋
    (α = η_f − η). At a spin between the two, both are consistent (a fold) and the mode's
    eigenvalue is the less stable, s₋ (continuation.mode_root's rule); a start at s₊ (the
    upper side, solved first) must not stop there."""
    c, eta, eta_f = 2 * 0.002 * W0, 0.2, 0.1
    s_plus = quadratic_roots(c, W0**2 * (1 + 1j * (eta_f + eta)))[0]
    s_minus = quadratic_roots(c, W0**2 * (1 + 1j * (eta_f - eta)))[0]
    assert s_minus.imag < s_plus.imag and s_minus.real > s_plus.real
    speed = 0.5 * (s_plus.imag + s_minus.imag)
    s, _, found = mode_roots(model(c, 0.0, eta, eta_f), speed, [s_plus * (1 + 1e-4j)], Y_MINUS[:, None])
    assert found[0]
    assert s[0] == pytest.approx(s_minus, rel=1e-12)


def test_a_newton_root_of_the_other_whirl_is_not_this_modes():
    """The forward whirl started at the backward whirl's root with a vector mostly its own
    (MAC 0.92 with y₋): Newton's method reaches the backward root (its vector y₊, MAC 0.08 with
    the start: another mode). The mode's eigenvalue is its own, s₋'s side at Ω = 1.3 ω_d, found
    from the branch's exact roots, never the backward root."""
    c, eta = 2 * 0.005 * W0, 0.02
    s_plus = quadratic_roots(c, W0**2 * (1 + 1j * eta))[0]
    s_minus = quadratic_roots(c, W0**2 * (1 - 1j * eta))[0]
    speed = 1.3 * s_plus.imag
    start_y = Y_MINUS + 0.3 * Y_PLUS
    s, _, found = mode_roots(model(c, 0.0, eta), speed, [s_plus * (1 + 1e-6)], start_y[:, None])
    assert found[0]
    assert s[0] == pytest.approx(s_minus, rel=1e-12)


def test_the_viscous_method_takes_its_circulatory_stiffness():
    """The viscous internal-damping method (weights w = (a, b, d) real): damping
    ``C + a F + b K_lat`` and the circulatory stiffness ``d K_lat S``
    (:func:`~flexshaft.analyses.eigen.viscous_model`). On y± (J y = ±i y) the roots solve
    s² + s(c + a η_f ω₀² + b η ω₀² ± iΩγ) + ω₀² ± i d η ω₀² = 0 (mutation hunt 46a: without
    the circulatory term the forward root y₋'s real part moves from −1.45 to −1.93; to first
    order by d η ω₀²/|2s + c′ − iΩγ| ≈ d η ω₀²/(2 Im s − Ωγ) = 100/(268.8 − 60) = 0.48 rad/s,
    c′ the damping coefficient above)."""
    c, gamma, eta, eta_f, speed = 2 * 0.01 * W0, 0.4, 0.02, 0.01, 1.5 * W0
    viscous = LossCoefficients(2e-3, 4e-3, 0.5)
    damping = c + viscous.fixed * eta_f * W0**2 + viscous.lateral * eta * W0**2
    plus = quadratic_roots(damping + 1j * speed * gamma, W0**2 + 1j * viscous.circulatory * eta * W0**2)[0]
    minus = quadratic_roots(damping - 1j * speed * gamma, W0**2 - 1j * viscous.circulatory * eta * W0**2)[0]
    want = np.array([plus, minus])
    start = want * (1 + 1e-3 * np.exp(0.3j))
    s, _, converged = newton_many(
        model(c, gamma, eta, eta_f), speed, start, np.column_stack([Y_PLUS, Y_MINUS]), viscous=viscous
    )
    assert list(converged) == [True, True]
    np.testing.assert_allclose(s, want, rtol=1e-12, atol=0)
