"""The synchronous roots' quadratic fit of the weights holds on the whole of each window.

:mod:`flexshaft.analyses.synchronous_roots` fits each weight w(Ω) on a window [a, b] by the
quadratic through its three Chebyshev points x = ±√3/2, 0 (x = (Ω − mid)/half) and keeps the
window only when the fit agrees with the weight to ``FIT_TOLERANCE`` of its size; else it halves
the window. Reference (interpolation error, closed form): the quadratic through those points of
x⁴ is (3/4) x² (x⁴ = 9/16 at ±√3/2, 0 at 0), so its error x⁴ − (3/4) x² is 1/4 at the window's
ends x = ±1 but only 1/8 on the inner half |x| ≤ 1/2 (its extremum, x² = 3/8, lies outside).

A stand-in solver with one weight w(Ω) = 1 + ε x⁴ on [100, 300] rad/s, ε = 5e-8: the fit on the
whole range errs by ε/4 = 1.25e-8 at the ends, more than 1e-8 of the weight's size (1 + ε), so
the range must be halved (checked on the inner half only it would pass: ε/8 = 6.25e-9). On each
half, w = 1 + (ε/16)(x' ∓ 1)⁴ = 1 + (ε/16)(x'⁴ ∓ 4x'³ + ...), the quadratic part fitted exactly;
x'⁴ leaves x'⁴ − (3/4)x'² (at most 1/4) and the cubic ∓4x'³ leaves ∓4·T₃(x')/4 = ∓T₃(x') (x'³
less its fit is the nodes' polynomial x'(x'² − 3/4) = T₃(x')/4; at most 1), so the error is at
most (ε/16)(1/4 + 1) = (ε/16)(5/4) ≈ 3.9e-9 (reached at the range's ends Ω = 100, 300 rad/s)
and the halves are kept. Every kept window's fit is then checked here on 401 points against the
weight itself: within ``FIT_TOLERANCE`` of its size (the tolerance the module states, no slack
needed: both errors are exact polynomials evaluated to round-off, ~1e-16).
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.synchronous_roots import FIT_TOLERANCE, _windows

LOW, HIGH, EPS = 100.0, 300.0, 5e-8


class _QuarticWeight:
    """A stand-in solver whose one weight is 1 + ε ((Ω − 200)/100)⁴ along ω = Ω."""

    def term_weights(self, omegas, speeds):
        x = (np.asarray(omegas, dtype=float) - 0.5 * (LOW + HIGH)) / (0.5 * (HIGH - LOW))
        return (1.0 + EPS * x**4)[:, None].astype(complex)


def test_every_kept_window_fits_its_weight_on_the_whole_window():
    solver = _QuarticWeight()
    windows = list(_windows(solver, LOW, HIGH))
    # the whole range's fit errs by ε/4 > 1e-8 (1 + ε) at its ends: it is halved, the halves kept
    assert EPS / 4 > FIT_TOLERANCE * (1 + EPS) > EPS / 8
    assert [(a, b) for a, b, _ in windows] == [(LOW, 200.0), (200.0, HIGH)]
    for a, b, fit in windows:
        x = np.linspace(-1.0, 1.0, 401)
        exact = solver.term_weights(0.5 * (a + b) + 0.5 * (b - a) * x, None)
        error = np.abs(np.vander(x, 3, increasing=True) @ fit - exact).max()
        assert error <= FIT_TOLERANCE * np.abs(exact).max()
