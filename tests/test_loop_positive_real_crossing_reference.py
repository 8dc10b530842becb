"""A loop whose Nyquist curve crosses the real axis only on its positive side has no gain margin
(mutation hunt h33c).

The loop, written here: L(s) = g H(s)², H(s) = 2ζω_n s/(s² + 2ζω_n s + ω_n²), the band-pass
resonance. On s = iω, H = 1/(1 + iQ) with Q(ω) = (ω² − ω_n²)/(2ζω_nω) running from −∞ to +∞,
so with 1 + iQ = e^{iθ}/cos θ (θ = atan Q),

    L(iω) = g cos²θ e^{−2iθ},   Im L = −g cos²θ sin 2θ,

zero only at θ = 0 (ω = ω_n), where L = g > 0: the curve crosses the real axis once, on its
positive side (phase 0°), and |arg L| = 2|θ| < 180° elsewhere, so it never reaches the negative
real axis: there is no phase crossover and no gain margin either way (+inf dB upper, −inf dB
lower). |L| = g cos²θ ≤ g = 0.5 < 1: no gain crossover, phase margin +inf.

The grid is chosen so that the crossing at ω_n = 100 rad/s (ζ = 0.01) falls inside one interval
whose ends lie at phases of about +171° and −168° (Re L < 0 at both ends, Im L changing sign):
the chord between them meets the real axis on its negative side, a candidate phase crossover,
the only one, so it is refined (its gain margin is the smallest); the refined crossing (L = g > 0)
must not be read as a phase crossover at −180° with |L| = g (a 6 dB "gain margin"). About 5 ms.
"""

from __future__ import annotations

import math

import numpy as np

from flexshaft.analyses.loop_margins import loop_margins

G, ZETA, WN = 0.5, 0.01, 100.0


def loop(w: np.ndarray) -> np.ndarray:
    s = 1j * np.asarray(w, dtype=float)
    H = 2 * ZETA * WN * s / (s * s + 2 * ZETA * WN * s + WN * WN)
    return G * H * H


def test_a_crossing_of_the_positive_real_axis_sets_no_gain_margin():
    w = np.geomspace(1.1, 1.1e4, 41)  # ratio 10^0.1: 87.4 and 110 rad/s around ω_n
    below, above = w[w < WN].max(), w[w > WN].min()
    ends = loop(np.array([below, above]))
    assert np.all(ends.real < 0) and ends[0].imag > 0 > ends[1].imag  # the interval straddles the crossing
    m = loop_margins(loop, w)
    assert m.phase_crossovers == ()
    assert m.gain_margin_upper_db == math.inf
    assert m.gain_margin_lower_db == -math.inf
    assert m.gain_crossovers == () and m.phase_margin_deg == math.inf
