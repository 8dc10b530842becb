r"""A hidden phase-crossover pair in the first part of a run of grid points near a sharp |S|
peak (``dip_searches`` of flexshaft.analyses.loop_dips), where the circle through the part's
ends and the peak must be checked at the grid point before the run, against the crossings of
Im L = 0 found by an independent route.

The loop, built by formula in x = ln(ω/ω_r), ω_r = 100 rad/s, ζ = 0.01:

    L(x) = A + B/(1 + i x/ζ) − (10 i/ζ⁵) (x − x₃₈)(x − x₃₉)(x − 0)(x − x₄₀)(x − x₄₂).

The lone mode B/(1 + i x/ζ) runs exactly over the circle of diameter [0, B] (a Möbius map of
x); with A = c − B/2 the circle has centre c = −1 + √((r + ε)² − (r + δ)²) + (r + δ) i and
radius r = 0.25 (δ = 0.006, ε = 0.02: its lowest point 0.006 above the real axis, its point
nearest −1 at distance r + ε = 0.27), and B = 2r(−1 − c)/|−1 − c| points from c toward −1, so
the point nearest −1 (the |S| peak) is x = 0, ω = 100 rad/s exactly. The grid is
ω_k = ω_r e^{x_k}, x_k = (k − 39.5)·0.3ζ, k = 0..80; x₃₈ = −0.0045, x₃₉ = −0.0015 are the
ends of the run's first part, x₄₀ = 0.0015, x₄₂ = 0.0075. The quintic background vanishes
there and at the peak, so the grid and the peak see the bare circle, clear of the axis, while
inside (x₃₈, x₃₉) it pulls Im L below zero. At the grid point before the run, x₃₇ = −0.0075,
it is −(10 i/ζ⁵)·(−0.003)(−0.006)(−0.0075)(−0.009)(−0.015) = 1.8225 i, so the map through the
part's ends and the peak, checked there, misses Im L by 1.8 and does not clear the axis: the
search must run. Checked at the grid point beyond the run's other end (x₄₂, where the
background vanishes) the map would look exact and the part would be dropped.

Reference (derived here, independent of the search): Im L sampled on 200001 logarithmic points
over [ω₃₈, ω₃₉] changes sign exactly twice, each change solved by scipy's brentq to 1e-12 rad/s
(ω ≈ 99.597 and 99.810 rad/s, Re L ≈ −0.81, −0.90 there: a phase crossover pair).

Tolerance: the search refines each crossing by regula falsi to a bracket of 1e-8 ω holding the
point returned and brentq's roots are exact to 1e-12 rad/s: 2e-8 relative. Im L at the points
returned: on [x₃₈, x₃₉] (width h = 0.003) the distances to the five roots are at most h, h,
1.5h, 2h, 4h, so the derivative of the product is at most (12 + 12 + 8 + 6 + 3) h⁴ = 41 h⁴ =
3.3e-9 and |dL/dx| ≤ |B|/ζ + 10/ζ⁵·3.3e-9 = 50 + 332 = 382; a 1e-8 step in x moves Im L by
< 3.9e-6, hence 4e-6. The ends' and the peak's values lie on the circle up to rounding of the
formula (terms of size ≤ 1, 1e-12 allows for the ~1e-16 rounding many times over).
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

from flexshaft.analyses.local_projection import lockstep
from flexshaft.analyses.loop_dips import dip_searches

ZETA, WR = 0.01, 100.0
R, DELTA, EPS = 0.25, 0.006, 0.02
CENTRE = -1 + np.sqrt((R + EPS) ** 2 - (R + DELTA) ** 2) + 1j * (R + DELTA)
B = 2 * R * (-1 - CENTRE) / abs(-1 - CENTRE)
A0 = CENTRE - B / 2
X = (np.arange(81) - 39.5) * 0.3 * ZETA
ROOTS = (X[38], X[39], 0.0, X[40], X[42])


def _loop(w):
    x = np.log(np.asarray(w, dtype=float) / WR)
    return A0 + B / (1 + 1j * x / ZETA) - 10j / ZETA**5 * np.prod([x - q for q in ROOTS], axis=0)


def _dense_crossings(low, high):
    """Im L = 0 in (low, high) by a dense sign scan and brentq (module docstring)."""
    ws = np.geomspace(low, high, 200001)
    im = _loop(ws).imag
    changes = np.flatnonzero(im[:-1] * im[1:] < 0)
    return np.array([brentq(lambda x: float(_loop(x).imag), ws[k], ws[k + 1], xtol=1e-12) for k in changes])


def test_a_dip_in_a_runs_first_part_is_checked_before_the_run():
    w = WR * np.exp(X)
    L = _loop(w)
    peak = np.array([WR])
    at_peak = np.array([complex(_loop(WR))])
    # the peak and the part's neighbours lie on the circle, which stays 0.006 above the axis
    for value in (L[38], L[39], L[40], L[42], at_peak[0]):
        assert abs(abs(value - CENTRE) - R) < 1e-12
    assert abs(at_peak[0] + 1) < abs(L + 1).min()  # the |S| peak: nearest −1
    assert abs(abs(L[37] - CENTRE) - R) > 1.0  # the point before the run is far off the circle
    assert L[38].imag > 0 and L[39].imag > 0  # the grid sees no crossing in the part
    true = _dense_crossings(w[38], w[39])
    assert true.size == 2  # one dip across the axis in the part
    assert np.all(_loop(true).real < -0.7)  # on the negative real axis: phase crossovers
    tasks = dip_searches(w, L, peak, at_peak)
    found = [pair for result in lockstep([t.start() for t in tasks], lambda x, _: _loop(x)) for pair in result]
    assert len(found) == 2
    assert np.allclose(sorted(x for x, _ in found), true, rtol=2e-8, atol=0)
    for x, value in found:
        assert abs(value - complex(_loop(x))) < 1e-15
        assert abs(value.imag) < 4e-6 and value.real < -0.7
