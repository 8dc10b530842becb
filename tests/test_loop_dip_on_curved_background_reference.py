r"""A dip of a resonance circle on a curved background, which the Möbius map of a lone mode
does not follow (``dip_crossovers`` of flexshaft.analyses.loop_dips), against the crossings of
Im L = 0 found by an independent route.

The loop, built by formula in x = ln(ω/ω_r), ω_r = 2π·100 rad/s:

    L(x) = a + B/(1 + i x/ζ) + q (x − x_a)(x − x_b)(x − x_c),

a lightly damped mode (ζ = 0.002; B/(1 + i x/ζ) runs over the circle of diameter [0, B]
exactly, a Möbius map of x) on a cubic background in ln ω that vanishes at the three points the
search is given (x_a = −2.5ζ, x_b = 3.5ζ, x_c = 4.8ζ), so L there lies on the circle of centre
c = −0.45 + 0.32i and radius 0.25 (B = 0.5 e^{1.84i}, a = c − B/2), which stays 0.07 above the
real axis, while between x_a and x_b the background q = (−0.002 − 0.006i)/ζ³ pulls Im L across
it. Im L is positive at both ends of the part (0.0996, 0.1505): the grid sees no crossing.

Reference (derived here, independent of the search): Im L sampled on 200001 logarithmic points
over [ω_a, ω_b] changes sign exactly twice, each change solved by scipy's brentq to 1e-12 rad/s
(ω = 625.918 and 626.910 rad/s, Re L = −0.652, −0.757 there: a phase crossover pair).

The first point the search evaluates is not the extreme of the map through the three given
points (at 619.1 rad/s, outside the part [ω_a, ω_b] = [625.18, 632.73] rad/s) but a golden-
section point of the part, 628.06 rad/s, where Im L = 0.259, above the axis; the map refitted
through it and its neighbours puts its extreme outside their bracket (592.8 rad/s). The search
must then weigh the lowest Im L found (0.0996, at ω_a), not the new point's (0.259), against
the previous map's error there (0.2554) before stopping; it goes on and finds the dip. A margin
taken from the newest point would stop it: that catch rests on 0.259 > 0.2554 (1.5 % apart, in
deterministic scalar arithmetic, no LAPACK/BLAS).

Tolerance: the search refines each crossing by regula falsi to a bracket of 1e-8 ω holding the
point returned, brentq's roots are exact to 1e-12 rad/s: 2e-8 relative. Im L at the points
returned: with t = x/ζ, (x − x_a)(x − x_b)(x − x_c) = ζ³ p(t), p'(t) = 3t² − 11.6t − 3.95, whose
largest magnitude on t in [−2.5, 3.5] is 43.8 (at t = −2.5), so |dL/dx| ≤ |B|/ζ + |q| ζ² max|p'|
= 250 + 139 ≈ 389 and a 1e-8 step in x moves Im L by at most 3.9e-6, hence 4e-6.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from flexshaft.analyses.local_projection import lockstep
from flexshaft.analyses.loop_dips import dip_crossovers

ZETA, WR = 0.002, 2 * np.pi * 100.0
CENTRE, RADIUS, ANGLE = -0.45 + 0.32j, 0.25, 1.84
B = 2 * RADIUS * np.exp(1j * ANGLE)
A0 = CENTRE - B / 2
XA, XB, XC = -2.5 * ZETA, 3.5 * ZETA, 4.8 * ZETA
Q = (-0.002 - 0.006j) / ZETA**3


def _loop(w):
    x = np.log(np.asarray(w, dtype=float) / WR)
    return A0 + B / (1 + 1j * x / ZETA) + Q * (x - XA) * (x - XB) * (x - XC)


def _dense_crossings(low, high):
    """Im L = 0 in (low, high) by a dense sign scan and brentq (module docstring)."""
    ws = np.geomspace(low, high, 200001)
    im = _loop(ws).imag
    changes = np.flatnonzero(im[:-1] * im[1:] < 0)
    return np.array([brentq(lambda x: float(_loop(x).imag), ws[k], ws[k + 1], xtol=1e-12) for k in changes])


def test_a_dip_the_background_bends_is_searched_past_a_misfitting_refit():
    a, b, c = WR * np.exp([XA, XB, XC])
    la, lb, lc = complex(_loop(a)), complex(_loop(b)), complex(_loop(c))
    # the three given values lie on the mode's circle, clear of the axis, Im L > 0 at both ends
    for value in (la, lb, lc):
        assert abs(abs(value - CENTRE) - RADIUS) < 1e-12
    assert CENTRE.imag - RADIUS == pytest.approx(0.07, abs=1e-12)
    assert la.imag > 0.09 and lb.imag > 0.15
    true = _dense_crossings(a, b)
    assert true.size == 2  # one dip across the axis in the part
    assert np.all(_loop(true).real < -0.6)  # on the negative real axis: phase crossovers
    found = lockstep([dip_crossovers(a, b, la, lb, c, lc)], lambda x, _: _loop(x))[0]
    assert len(found) == 2
    assert [x for x, _ in found] == pytest.approx(true, rel=2e-8)
    for x, value in found:
        assert value == pytest.approx(complex(_loop(x)), abs=1e-15)
        assert abs(value.imag) < 4e-6 and value.real < -0.6
