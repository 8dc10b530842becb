"""Every root of the closed loop above the spin, with the hysteretic loss, against closed forms.

Reference (derived). The Jeffcott rotor of tests/rotors.py (20 kg midspan disk on a near-massless
pinned-pinned tube of stiffness k, loss factor η) with, at the disk, a bearing stiffness k_v in
v only (so the two planes' roots differ) and a magnetic bearing whose proportional law passes an
amplifier lag: force −k_i k_p d/(1 + s/ω_a) (k_s = 0, no derivative). The lag turns the
proportional stiffness partly into negative damping (−k_p/ω_a at low frequency), so without
the loss the disk's roots are unstable. The disk has no tilt at midspan: each plane is a single
degree of freedom. Above the spin the rotating-frame loss is i η k in both planes (the weights
(i, i, 0) of :func:`~flexshaft.analyses.loss.frequency_coefficients`), so each plane's root solves

    f(s) = m s² + k (1 + iη) + k_plane + k_p/(1 + s/ω_a) = 0,      k_plane = k_v or 0,

i.e. the cubic (m s² + k(1 + iη) + k_plane)(1 + s/ω_a) + k_p = 0 (numpy.roots). Without the
loss (η = 0) the same cubic gives the loss-free roots s₀, and the loss's first-order shift of a
simple root of the scalar f is Δs = −iηk/f'(s₀), f'(s) = 2ms − (k_p/ω_a)/(1 + s/ω_a)².

The tube's mass (7e-6 of the disk's) and the 4-element mesh leave the model's disk roots within
1e-6 of the single-degree-of-freedom ones (measured 8e-7): 1e-5 is asserted where the exact
root is meant, and the first-order value is told from the exact one by their distance, 2e-3 to
4e-3 |s| at η = 0.2 (derived from the two closed forms), 200 times that. Each check is one
dense eigen-solve of 42 states (20 lateral basis modes and the two amplifier states).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, L, jeffcott_text

from flexshaft.analyses.root_stability import closed_loop_poles, root_stability
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

K_V = 0.1 * K_SHAFT
F_A = 50.0  # amplifier bandwidth [Hz]
W_A = 2 * np.pi * F_A
SPEED = 0.5 * WN  # every disk root lies above the spin


def lagged_rotor(eta: float, kp: float):
    text = jeffcott_text(eta, 0.0, elements=4).replace("stiffness = {}", f"stiffness = {{ v = {K_V} }}")
    magnet = (
        f'[[bearings]]\nname = "amb"\nkind = "active"\nx = {L / 2}\nkp = {kp}\nkd = 0.0\nks = 0.0\nki = 1.0\n'
        f"amplifier_bandwidth = {F_A}\n\n[[disks]]"
    )
    return build_model(loads_design(text.replace("[[disks]]", magnet)))


def plane_root(eta: float, kp: float, k_plane: float) -> complex:
    """The oscillatory root (Im s > 0) of the plane's cubic (module docstring)."""
    cubic = np.polyadd(np.polymul([M_DISK, 0.0, K_SHAFT * (1 + 1j * eta) + k_plane], [1 / W_A, 1.0]), [kp])
    roots = np.roots(cubic)
    return complex(roots[np.argmax(roots.imag)])


def first_order(eta: float, kp: float, k_plane: float) -> complex:
    """s₀ + Δs, Δs = −iηk/f'(s₀) (module docstring)."""
    s0 = plane_root(0.0, kp, k_plane)
    slope = 2 * M_DISK * s0 - (kp / W_A) / (1 + s0 / W_A) ** 2
    return s0 - 1j * eta * K_SHAFT / slope


def nearest(roots: np.ndarray, s: complex) -> complex:
    return complex(roots[np.argmin(np.abs(roots - s))])


def test_roots_the_loss_leaves_unstable_are_solved_with_the_loss_above_the_spin():
    """η = 0.02, k_p = 0.2 k: the lag's negative damping (ζ ≈ −0.04) outweighs the loss's η/2,
    so both planes' disk roots stay unstable and are solved exactly with the upper side's loss
    (refined); each is its cubic's root, and reported at its damped frequency Im s."""
    eta, kp = 0.02, 0.2 * K_SHAFT
    result = root_stability(lagged_rotor(eta, kp), [SPEED])
    assert result.method == "full"
    want = sorted((plane_root(eta, kp, k) for k in (0.0, K_V)), key=lambda s: s.imag)
    assert all(s.real > 0 for s in want)
    assert len(result.unstable) == 2
    for root, s in zip(result.unstable, want):
        assert root.refined and root.kind == "oscillatory"
        assert root.root == pytest.approx(s, rel=1e-5)
        assert root.frequency == pytest.approx(s.imag, rel=1e-5)
    # every state's root counted once: 2 nb + 2 states (one amplifier state a plane), the two
    # planes' cubics each with one real root (its lag pole), every other root a complex pair
    assert result.n_roots[0] == result.basis_size + 2


def test_roots_the_loss_clearly_stabilises_keep_the_first_order_shift():
    """η = 0.2, k_p = 0.1 k: without the loss ζ ≈ −0.02, the loss adds about η/2 = 0.1, so half
    and one and a half times its first-order shift both leave the roots stable: the check
    settles them with that shift (not refined) and reports s₀ + Δs of each plane, 3e-3 to 4e-3
    |s| from the exact lossy root (also asserted: the two are told apart)."""
    eta, kp = 0.2, 0.1 * K_SHAFT
    result = root_stability(lagged_rotor(eta, kp), [SPEED])
    assert result.stable
    for k in (0.0, K_V):
        s0, settled, exact = plane_root(0.0, kp, k), first_order(eta, kp, k), plane_root(eta, kp, k)
        assert s0.real > 0 > settled.real
        assert abs(settled - exact) > 1e-3 * abs(exact)
        assert nearest(result.roots[0], settled) == pytest.approx(settled, rel=1e-5)
    assert result.n_refined[0] == 0


def test_roots_the_first_order_shift_stabilises_without_a_margin_are_solved_with_the_loss():
    """η = 0.2, k_p = 0.3 k: without the loss ζ ≈ −0.06, the loss's first-order shift leaves
    ζ ≈ +0.02 but half of it leaves ζ ≈ −0.02: not settled by the first-order estimate (its
    neglected terms could bring the root back), so each plane's root is solved with the loss
    and reported as its exact cubic root (2.6e-3 |s| from s₀ + Δs), stable."""
    eta, kp = 0.2, 0.3 * K_SHAFT
    result = root_stability(lagged_rotor(eta, kp), [SPEED])
    assert result.stable
    for k in (0.0, K_V):
        s0, settled, exact = plane_root(0.0, kp, k), first_order(eta, kp, k), plane_root(eta, kp, k)
        half = s0 + 0.5 * (settled - s0)
        assert half.real > 0 > settled.real and exact.real < 0
        assert abs(settled - exact) > 1e-3 * abs(exact)
        assert nearest(result.roots[0], exact) == pytest.approx(exact, rel=1e-5)
    assert result.n_refined[0] >= 2


def test_closed_loop_poles_are_the_loss_free_roots_with_positive_frequency():
    """The loss-free poles (step 2 alone): both planes' cubic roots with Im s > 0 are among them,
    and every pole returned has Im s > 0."""
    kp = 0.2 * K_SHAFT
    poles = closed_loop_poles(lagged_rotor(0.02, kp), SPEED)
    assert np.all(poles.imag > 0)
    for k in (0.0, K_V):
        s0 = plane_root(0.0, kp, k)
        assert nearest(poles, s0) == pytest.approx(s0, rel=1e-5)
