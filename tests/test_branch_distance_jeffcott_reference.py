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
(the tube's small gyroscopic term aside, below)

    distance(forward) = 2 η ω_n² / (2|s|) = η ω_n (1 + η²)^{-1/4},    distance(backward) = 0.

Above the critical (Ω = 2 ω_n) the forward root on the lower branch is the growing one (its
loss is −iη: Re s = +η ω_n/2 to first order) and the backward root decays (Re s < 0), which
tells the two apart without relying on eigenvector order.

The tube's polar inertia adds a small gyroscopic term (derived here): with the static shape
φ = 3ξ − 4ξ³ of each half (ξ = x/L, φ = 1 at the disk), ∫φ'² dx = 4.8/L over the span and the
modal gyroscopic coefficient is g = ρ π (D_o⁴ − D_i⁴)/32 · (4.8/L)/m = 8.694e-9 (ρ = 0.1
kg/m³ of rotors.jeffcott_text; the reduced model's G[0, 1] is 8.69434e-9, the 1.7e-6 relative
difference being the tube's own mass in the modal mass). The forward root on the lower branch
is then the root with Im s > 0 of

    s² − iΩ g s + ω_n² (1 − iη) = 0,

whose modulus is ω_n (1 + η²)^{1/4} (1 + Ω g/(2 ω_n) + O(η² Ω g/ω_n)): the distance is lower
than η ω_n (1 + η²)^{-1/4} by Ω g/(2 ω_n) = 8.7e-9 relative at Ω = 2 ω_n. The expected
forward distance is η ω_n² / |s| with s that exact root (its ``ΔW`` is the same multiple of
the modal stiffness for every lateral shape, so nothing else enters).

The distance also agrees to first order with the actual separation of the forward roots of
the two branches, ω_n |√(1+iη) − √(1−iη)| = η ω_n (1 − η²/8 + O(η⁴)) against the distance's
η ω_n (1 − η²/4 + O(η⁴)): they differ by η²/8 = 1.25e-5 relative (measured 1.2508e-5; the
gyroscopic term lowers the distance alone, by 8.7e-9 relative, and the O(η⁴) terms are 1e-8).

ω_n is the reduced model's undamped disk frequency. Tolerances: 1e-10 relative on the forward
distance: measured 8e-14 (round-off of a 4×4 dense eigen-solve with well-separated roots, and
the tube's mass left out of g: 1.7e-6 × 8.7e-9 = 1.5e-14), so 1e-10 passes on any BLAS kernel
with a 1000x margin, yet stays 87x below the gyroscopic correction itself (leaving g out fails)
while a weight change left out or halved moves the distance by 50 %. 1e-9 η ω_n absolute on
the backward one (round-off of a difference of two equal weights times O(ω_n) numbers;
measured 8e-16 η ω_n). 3e-5 relative against the actual separation: its η²/8 = 1.25e-5 with a
2.4x margin. CPU: one two-mode reduction and two 4×4 eigen-solves, about 0.05 s.
"""

from __future__ import annotations

import numpy as np
from rotors import DI, DO, M_DISK, L, jeffcott

from flexshaft.analyses.continuation import branch_distance
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import branch_roots, branches

ETA = 0.01
RHO = 0.1  # the tube's density in rotors.jeffcott_text, kg/m³
G_TUBE = RHO * np.pi * (DO**4 - DI**4) / 32 * (4.8 / L) / M_DISK  # modal gyroscopic coefficient


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
    roots = np.roots([1.0, -1j * speed * G_TUBE, omega_n**2 * (1 - 1j * ETA)])
    s_exact = roots[np.argmax(roots.imag)]  # the forward whirl of the lower branch
    expected = ETA * omega_n**2 / abs(s_exact)
    assert abs(distance[forward] - expected) <= 1e-10 * expected, distance[forward] / expected - 1
    assert distance[backward] <= 1e-9 * ETA * omega_n, distance[backward]
    s_above, _ = branch_roots(red, speed, above.weights)
    separation = np.min(np.abs(s_above - s[forward]))  # both upper roots lie at Re s = −η ω_n/2
    assert abs(separation - distance[forward]) <= 3e-5 * distance[forward]
