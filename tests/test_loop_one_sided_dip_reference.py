r"""Phase crossovers a resonance circle makes on one side of Re L = 0, the dip gate's circle and
the peak's half width (flexshaft.analyses.loop_margins ``hidden_crossovers``, flexshaft.analyses.loop_dips
``may_dip`` and ``_half_width``), against circles and a resonance solved by hand.

**A circle crossing the real axis once at Re L < 0 and once at Re L > 0.** L(ω) = a + iε + b H(ω),
H = 2iζω_rω/(ω_r² − ω² + 2iζω_rω) = q(1 + iu), u = (ω_r² − ω²)/(2ζω_rω), q = 1/(1 + u²)
(tests/test_loop_hidden_phase_crossover_reference.py), ζ = 1e-3, ω_r = 2π·100 rad/s, with
a = 0.1, ε = 0.1, b = −0.6 − 0.8i:

    Im L = ε + q(b_i + b_r u) = 0  ⇔  0.1(1 + u²) = 0.8 + 0.6u  ⇔  u² − 6u − 7 = 0,  u = 7, −1;
    Re L = a + q(b_r − b_i u) = 0.1 + (−0.6 + 0.8·7)/50 = 0.2 (no phase crossover) at u = 7,
                                 0.1 + (−0.6 − 0.8)/2 = −0.6 (a phase crossover) at u = −1.

So the only phase crossover is at u = −1, ω = ζω_r + √((ζω_r)² + ω_r²), upper gain margin
20 log₁₀(1/0.6) = 4.437 dB. L runs over the circle of centre c = a + iε + b/2 = −0.2 − 0.3i and
radius r = |b|/2 = 0.5: |L| ≤ |c| + r < 1 (no gain crossover), |S|max = 1/(|−1 − c| − r), at
Re L < 0, Im L < 0, between the two crossings. Both lie 0.8 % apart in ω inside one interval
of a 200-point logarithmic grid whose ends, |u| ≈ 23, have Im L > 0 and Re L > 0: the interval
shows no change of sign; split at the refined peak, its second part runs from the peak
(Re L < 0) to a grid point at Re L > 0, and holds the phase crossover.

**The dip gate's circle.** Three values of L on the circle of centre 0.1 + 0.2i, radius 0.3, at
angles 200° and −20° (both Im L = 0.097 > 0) and 90° (the third point): the arc from the first
to the second that avoids the third runs through the circle's lowest point 0.1 − 0.1i, across
the real axis at Re L = 0.1 ∓ √(0.3² − 0.2²) = −0.124 and 0.324: a dip across the negative real
axis is possible (its leftmost crossing at Re L < 0), though the rightmost lies at Re L > 0.

**Half width.** A loop with 1/(1 + L) = S_p/(1 + i(ω − p)/h) has |S| = S_p/√(1 + ((ω − p)/h)²):
the half width read from |S| at the peak and at any grid point beside it is h.

Tolerances: the crossovers are bracketed to 1e-8 ω and then solved by the Illinois method's
last secant step inside the bracket, which lands on the crossing of this smooth circle to
round-off (measured 1e-14; the bracket alone, through du/dω = 1/(ζ ω_r), would allow ~1e-5 on
the margin): 1e-7 on the frequency and the margin (as
tests/test_loop_hidden_phase_crossover_reference.py), the peak to 1e-6; the half
width is a square root of differences of numbers of order 1: 1e-9. Written for the
h46b-loop-* and h46b-dip-* mutations of scripts/mutations.toml; about 20 ms.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.loop_dips import _half_width, may_dip
from flexshaft.analyses.loop_margins import loop_margins

ZETA, WR = 1e-3, 2 * np.pi * 100.0
A, EPS, B = 0.1, 0.1, -0.6 - 0.8j
GRID = np.geomspace(2 * np.pi * 1.0, 2 * np.pi * 1e4, 200)


def _loop(w):
    h = 2j * ZETA * WR * w / (WR * WR - w * w + 2j * ZETA * WR * w)
    return A + 1j * EPS + B * h


def test_a_hidden_phase_crossover_between_the_peak_and_a_grid_point_at_positive_real_part():
    k = np.searchsorted(GRID, WR)
    ends = _loop(GRID[[k - 1, k]])
    assert np.all(_loop(GRID).imag > 0) and np.all(ends.real > 0)
    u = np.array([7.0, -1.0])
    q = 1 / (1 + u * u)
    assert EPS + q * (B.imag + B.real * u) == pytest.approx([0.0, 0.0], abs=1e-15)
    real = A + q * (B.real - B.imag * u)
    assert real == pytest.approx([0.2, -0.6], rel=1e-12)
    w = -ZETA * WR * u + np.sqrt((ZETA * WR * u) ** 2 + WR * WR)
    assert GRID[k - 1] < w.min() and w.max() < GRID[k]
    m = loop_margins(_loop, GRID)
    assert m.phase_crossovers == pytest.approx((w[1] / (2 * np.pi),), rel=1e-7)
    assert m.gain_margin_upper_db == pytest.approx(20 * np.log10(1 / 0.6), rel=1e-7)
    assert m.gain_margin_lower_db == -np.inf and m.phase_margin_deg == np.inf
    c, r = A + 1j * EPS + B / 2, abs(B) / 2
    assert abs(c) + r < 1
    assert m.peak_sensitivity == pytest.approx(1 / (abs(-1 - c) - r), rel=1e-6)


def test_the_dip_gate_reads_the_leftmost_crossing_of_the_circle():
    c, r = 0.1 + 0.2j, 0.3
    la, lb, third = (c + r * np.exp(1j * np.radians(t)) for t in (200.0, -20.0, 90.0))
    assert la.imag > 0 and lb.imag > 0
    half = np.sqrt(r * r - c.imag**2)
    assert (c.real - half, c.real + half) == pytest.approx((-0.1236, 0.3236), abs=1e-4)
    assert may_dip(complex(la), complex(lb), complex(third))
    # the same circle moved right by 0.3: both crossings at Re L > 0, no phase crossover
    assert not may_dip(complex(la + 0.3), complex(lb + 0.3), complex(third + 0.3))


def test_the_half_width_of_a_resonant_sensitivity():
    p, h, top = 2 * np.pi * 100.0, 2 * np.pi * 0.7, 8.0
    w = np.geomspace(p / 1.1, p * 1.1, 41)
    w = w[np.abs(w - p) > 1e-3 * p]  # the peak between two grid points
    L = (1 + 1j * (w - p) / h) / top - 1
    lp = 1 / top - 1
    assert np.abs(1 / (1 + L)) == pytest.approx(top / np.sqrt(1 + ((w - p) / h) ** 2), rel=1e-12)
    assert _half_width(w, L, p, lp) == pytest.approx(h, rel=1e-9)
