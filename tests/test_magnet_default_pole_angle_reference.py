"""The magnet functions' default pole angle is 0 (poles on the force axis), by closed form.

:mod:`flexshaft.elements.magnetic` documents ``pole_angle`` = 0 as the default of every
function. Reference, derived here for poles on the force axis (α = 0), infinitely permeable
iron, no fringing: a horseshoe with two gaps g in series and N turns carrying i stores the
co-energy W' = ½ L(g) i², L(g) = μ0 N² A_a/(2 g), so it pulls with f = ∂W'/∂g magnitude
½ i² μ0 N² A_a/(2 g²) = k i²/g² with k = ¼ μ0 N² A_a. The opposed pair at gaps g_0 ∓ x with
currents i_0 ± i, linearised at x = i = 0: k_i = ∂f/∂i = 4 k i_0/g_0² = μ0 N² A_a i_0/g_0²,
k_s = ∂f/∂x = 4 k i_0²/g_0³ = μ0 N² A_a i_0²/g_0³, with μ0 = 4π·10⁻⁷ H/m (Schweitzer & Maslen
2009, ch. 2-3, give the same forms with a factor cos α in k). For N = 200, A_a = 8 cm²,
i_0 = 5 A and g_0 = 1 mm: k = 1.0053e-5 N m²/A², k_i = 201.06 N/A and k_s = 1.0053e6 N/m
(hand evaluation of the closed forms below). With the 8-pole stator's α = 22.5° the coded k
(the textbook's convention) is lower by cos 22.5° = 0.924; the call with α given checks that
factor on k. Tolerance 1e-12 relative: a few products of doubles.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.elements import magnetic

MU0 = 4.0e-7 * math.pi
TURNS, AREA, I0, G0 = 200.0, 8.0e-4, 5.0, 1.0e-3


def test_magnet_constant_defaults_to_poles_on_the_force_axis():
    expected = 0.25 * MU0 * TURNS**2 * AREA
    assert magnetic.magnet_constant(TURNS, AREA) == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(1.0053e-5, rel=1e-4)
    tilted = magnetic.magnet_constant(TURNS, AREA, math.pi / 8)
    assert tilted == pytest.approx(expected * math.cos(math.pi / 8), rel=1e-12)


def test_current_gain_and_force_slope_default_to_poles_on_the_force_axis():
    ki = MU0 * TURNS**2 * AREA * I0 / G0**2
    ks = MU0 * TURNS**2 * AREA * I0**2 / G0**3
    assert magnetic.current_gain(TURNS, AREA, I0, G0) == pytest.approx(ki, rel=1e-12)
    assert magnetic.force_slope(TURNS, AREA, I0, G0) == pytest.approx(ks, rel=1e-12)
    assert (ki, ks) == pytest.approx((201.06, 1.0053e6), rel=1e-4)
