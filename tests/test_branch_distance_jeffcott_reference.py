"""The first-order distance between a whirl's two branch roots, on a Jeffcott rotor.

:func:`flexshaft.analyses.continuation.branch_distance` estimates how far a root of one side of
the synchronous line moves on the other side's loss weights, ``|yᴴ ΔW y| / (2|s|)``; the
continuation skips the other branch when a root lies farther than ten such distances from the
line. Reference derived here for the rotor of tests/rotors.py (a midspan disk on a near-
massless tube, rotating hysteretic loss factor η of the shaft; the loss condenses exactly onto
the disk): in complex coordinates r = v + i w and unit modal mass the whirl obeys

    s² + ω_n² (1 + i η sgn(ω − Ω)) = 0       for forward whirl (r ∝ e^{st}, ω = Im s),
    s² + ω_n² (1 + i η) = 0                  for backward whirl (ω + Ω > 0 always),

(the rotating-frame loss acts on the whirl frequency seen by the material, ω ∓ Ω; Zorzi &
Nelson 1977 for its viscous form). Across the line the forward whirl's loss stiffness changes
by ``ΔW = 2iη ω_n²`` and the backward whirl's not at all, so with ``|s| = ω_n (1 + η²)^{1/4}``

    distance(forward) = 2 η ω_n² / (2|s|) = η ω_n (1 + η²)^{-1/4},    distance(backward) = 0.

Above the critical (Ω = 2 ω_n) the forward root on the lower branch is the growing one (its
loss is −iη: Re s = +η ω_n/2 to first order) and the backward root decays (Re s < 0), which
tells the two apart without relying on eigenvector order. The distance also agrees to first
order with the actual separation of the forward roots of the two branches, ω_n |√(1+iη) −
√(1−iη)| = η ω_n (1 + O(η²)).

ω_n is the reduced model's undamped disk frequency. Tolerance 1e-7 relative on the forward
distance: the formula is exact for this rotor once the eigenvector is (its ``ΔW`` is the same
multiple of the modal stiffness for every lateral shape); measured 7e-9 (not traced further),
so 1e-7 keeps a 14x margin while a weight change left out or halved moves the distance by
50 %. 1e-9 η ω_n absolute on the backward one (round-off of a difference of two equal weights
times O(ω_n) numbers; measured 8e-16 η ω_n). 1e-3 relative against the actual separation: its
O(η²) = 1e-4 terms. CPU: one two-mode reduction and two 4×4 eigen-solves, about 0.05 s.
"""

from __future__ import annotations

import numpy as np
from rotors import jeffcott

from flexshaft.analyses.continuation import branch_distance
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import branch_roots, branches

ETA = 0.01


def test_branch_distance_is_eta_omega_for_forward_whirl_and_zero_for_backward():
    red = reduce(jeffcott(ETA, 0.0), 2)
    omega_n = float(np.sqrt(red.w2.max()))
    speed = 2.0 * omega_n  # supercritical: both whirl roots lie on the lower branch's side
    below, above = branches(red, speed)
    s, Y = branch_roots(red, speed, below.weights)
    assert s.size == 2
    forward, backward = (1, 0) if s[1].real > s[0].real else (0, 1)
    assert s[forward].real > 0 > s[backward].real  # internal damping destabilises the forward whirl
    distance = branch_distance(red, below.weights, above.weights, s, Y)
    expected = ETA * omega_n / (1 + ETA**2) ** 0.25
    assert abs(distance[forward] - expected) <= 1e-7 * expected, distance[forward] / expected
    assert distance[backward] <= 1e-9 * ETA * omega_n, distance[backward]
    s_above, _ = branch_roots(red, speed, above.weights)
    separation = np.min(np.abs(s_above - s[forward]))  # both upper roots lie at Re s = −η ω_n/2
    assert abs(separation - distance[forward]) <= 1e-3 * distance[forward]
