"""A pair of phase crossovers hidden inside one grid interval, found from the refined
sensitivity peak between them (flexshaft.analyses.loop_margins, ``hidden_crossovers`` and the
margins made of them), against the crossings of a resonance circle solved by hand.

The loop, built by formula: L(ω) = a + iε + b H(ω) with a = −0.3, ε = 0.1, b = −0.3 − 0.4i and
H = 2iζω_rω/(ω_r² − ω² + 2iζω_rω) a resonance of ζ = 1e-3 at ω_r = 2π·100 rad/s. With
u = (ω_r² − ω²)/(2ζω_rω) and q = 1/(1 + u²), H = q(1 + iu), so

    Im L = ε + q(b_i + b_r u),   Re L = a + q(b_r − b_i u).

Im L = 0: 0.1(1 + u²) − 0.4 − 0.3u = 0, u² − 3u − 3 = 0, u = (3 ± √21)/2; ω from u:
ω = −ζω_r u + √((ζω_r u)² + ω_r²). There Re L = −0.2209 and −0.6791 (both on the negative real
axis: two phase crossovers), and the smallest upper gain margin is 20 log₁₀(1/0.6791) =
3.361 dB. L traces a circle of centre a + iε + b/2 = −0.45 − 0.1i and radius |b|/2 = 0.25;
its nearest point to −1 lies at distance d − r, d = |0.55 − 0.1i|, so |S|max = 1/(d − r) =
3.2361 (below the real axis, between the two crossings). The crossings lie 0.46 % apart
inside one interval of a 200-point logarithmic grid (4.7 % steps); at the interval's ends
(|u| ≈ 23) Im L = 0.1 ∓ 0.013 > 0: the grid shows no change of sign of Im L, only the refined
peak, where Im L < 0, does. |L| ≤ |c| + r = 0.711 < 1 everywhere: no gain crossover, phase
margin ∞. The grid has no point near the peak's top (which :func:`loop_margins` asks of its
grid); the peak is found by the refinement of its neighbours.

Tolerances: the crossovers are refined to 1e-8 ω (Illinois), so the frequencies and the gain
margin to 1e-7; the peak is located to 1e-6 in ln ω (golden section), where |S| is flat to
second order: 1e-6.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.loop_margins import loop_margins

ZETA, WR = 1e-3, 2 * np.pi * 100.0
A, EPS, B = -0.3, 0.1, -0.3 - 0.4j


def _loop(w):
    h = 2j * ZETA * WR * w / (WR * WR - w * w + 2j * ZETA * WR * w)
    return A + 1j * EPS + B * h


def test_two_phase_crossovers_inside_one_grid_interval_set_the_gain_margin():
    grid = np.geomspace(2 * np.pi * 1.0, 2 * np.pi * 1e4, 200)
    k = np.searchsorted(grid, WR)
    assert np.all(_loop(grid).imag > 0)  # the grid alone sees no phase crossover
    u = np.array([(3 + np.sqrt(21)) / 2, (3 - np.sqrt(21)) / 2])
    q = 1 / (1 + u * u)
    real = A + q * (B.real - B.imag * u)
    assert np.all(real < 0) and real == pytest.approx([-0.220871, -0.679129], abs=1e-6)
    w = -ZETA * WR * u + np.sqrt((ZETA * WR * u) ** 2 + WR * WR)
    assert grid[k - 1] < w.min() and w.max() < grid[k]  # both inside one grid interval
    m = loop_margins(_loop, grid)
    assert m.phase_crossovers == pytest.approx(sorted(w / (2 * np.pi)), rel=1e-7)
    assert m.gain_margin_upper_db == pytest.approx(20 * np.log10(1 / abs(real[1])), rel=1e-7)
    assert m.gain_margin_upper_db == pytest.approx(3.3610, abs=1e-4)
    assert m.gain_margin_lower_db == -np.inf and m.phase_margin_deg == np.inf
    d, r = abs(-1 - (A + 1j * EPS + B / 2)), abs(B) / 2
    assert m.peak_sensitivity == pytest.approx(1 / (d - r), rel=1e-6)
