"""Loss weights at the edges of docs/model.md's hysteretic loss law.

Reference (hand-written, docs/model.md, "Every member's loss is hysteretic"): with the
``"rotating"`` internal-damping model the loss is

    L(ω, Ω) = i sgn(ω) F + i (σ_B + σ)/2 K_lat + (σ_B − σ)/2 K_lat S,
    σ = sgn(ω − Ω),  σ_B = sgn(ω + Ω),

and with the ``"thesis"`` model ``L(ω) = i sgn(ω)(F + K_lat)``. The weights of (F, K_lat,
K_lat S) are therefore read off by hand at chosen points, with sgn(0) = 0 as docs/model.md's
"Synchronous forward whirl (imbalance) is not damped by the shaft at all" requires of the
forward part. The reverse-spin point Ω = −ω lies outside the product's speeds (≥ 0,
docs/limits.md §6): public API only; the product path of these weights is the static point
ω = Ω = 0. The fixed-frame weight is checked
as energy too: a single hysteretic spring k(1 + iη) driven at x = X cos ωt dissipates
π η k X² per cycle (derived here: the loss force −η k X sin ωt times dx = −X ω sin ωt dt
integrated over a period gives η k X² ω · π/ω), so a loss force ``w η k x`` dissipates
π η k X² Im(w) per cycle: Im(w) = 1 exactly for the fixed-frame weight i.

The weights are exact small integers / halves (no LAPACK), so they are compared to 1e-15;
the per-cycle energy is a 64-point periodic trapezoid sum, exact for the trigonometric
polynomial integrand up to round-off of 64 terms of order one (1e-12 relative).
"""

import numpy as np
import pytest

from flexshaft.analyses.loss import eigen_coefficients, frequency_coefficient_arrays

EXACT = 1e-15


def _documented(omega: float, speed: float) -> tuple[complex, complex, float]:
    """docs/model.md's rotating-frame weights, with sgn(0) = 0."""
    sigma = float(np.sign(omega - speed))
    sigma_b = float(np.sign(omega + speed))
    return 1j * float(np.sign(omega)), 0.5j * (sigma_b + sigma), 0.5 * (sigma_b - sigma)


def test_banded_weights_at_rest_and_zero_frequency_are_lossless() -> None:
    """A static point (ω = 0) of a shaft at rest (Ω = 0): sgn(ω) = σ = σ_B = sgn(0) = 0, so every
    weight of L is zero — no strain rate, no hysteretic force, in the banded (vectorised)
    weights that frequency sweeps use."""
    fixed, lateral, circulatory = frequency_coefficient_arrays("rotating", np.array([0.0]), np.array([0.0]))
    assert abs(fixed[0]) <= EXACT
    assert abs(lateral[0]) <= EXACT
    assert abs(circulatory[0]) <= EXACT


def test_banded_weights_on_the_backward_rotating_frame_line() -> None:
    """Reverse spin Ω = −ω (ω = 30 rad/s): the backward wave is seen at ω + Ω = 0, so σ_B = 0 and
    σ = sgn(2ω) = 1: lateral weight i/2 and circulatory weight −1/2 (docs/model.md), not the
    full lateral loss i with no circulatory term."""
    omega = 30.0
    fixed, lateral, circulatory = frequency_coefficient_arrays("rotating", np.array([omega]), np.array([-omega]))
    want = _documented(omega, -omega)
    assert want == (1j, 0.5j, -0.5)
    assert abs(fixed[0] - want[0]) <= EXACT
    assert abs(lateral[0] - want[1]) <= EXACT
    assert abs(circulatory[0] - want[2]) <= EXACT


@pytest.mark.parametrize(("omega", "speed"), [(10.0, 40.0), (50.0, 40.0), (5.0, 0.0)])
def test_banded_weights_follow_the_chosen_law(omega: float, speed: float) -> None:
    """Each model keeps its own documented law in the banded weights: below the spin the
    rotating model has no lateral loss and a unit circulatory weight (σ = −1, σ_B = 1), above
    it the full lateral loss i; the thesis model is i on F and K_lat and no circulatory
    term at every point."""
    o, s = np.array([omega]), np.array([speed])
    rot = frequency_coefficient_arrays("rotating", o, s)
    for got, want in zip(rot, _documented(omega, speed), strict=True):
        assert abs(got[0] - want) <= EXACT
    thesis = frequency_coefficient_arrays("thesis", o, s)
    for got, want in zip(thesis, (1j, 1j, 0.0), strict=True):
        assert abs(got[0] - want) <= EXACT


@pytest.mark.parametrize("sigma", [-1.0, 0.0, 1.0])
def test_fixed_frame_loss_dissipates_pi_eta_k_x2_on_either_whirl_side(sigma: float) -> None:
    """The fixed-frame (boom, bearing) loss does not depend on the whirl side: with σ given
    explicitly the weight of F is still i, and a spring k(1 + iη) loaded by it dissipates
    π η k X² per cycle (docstring derivation)."""
    w = eigen_coefficients("rotating", 25.0, 40.0, sigma=sigma)
    k, eta, amplitude, omega = 2.0e5, 0.05, 1.0e-3, 25.0
    t = np.arange(64) * (2 * np.pi / omega) / 64
    x_dot = -amplitude * omega * np.sin(omega * t)
    force = np.real(w.fixed * eta * k * amplitude * np.exp(1j * omega * t))
    dissipated = float(np.sum(force * x_dot) * (2 * np.pi / omega) / 64)
    assert dissipated == pytest.approx(np.pi * eta * k * amplitude**2, rel=1e-12)
    assert abs(w.fixed - 1j) <= EXACT  # and no storage part: the weight is i itself
