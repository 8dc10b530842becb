"""Where :func:`~flexshaft.analyses.loop_margins.loop_margins` reports its phase crossovers: the
frequency of the governing gain margin when a grid-bracketed crossover lies above a hidden
pair, and a crossover outside the gain-margin window left at its interpolated frequency, on
loops whose crossovers are solved by hand.

* **The governing margin's frequency.** The resonance loop of
  tests/test_loop_hidden_phase_crossover_reference.py, L₀(ω) = a + iε + b H(ω) with a = −0.3,
  ε = 0.1, b = −0.3 − 0.4i, H = 2iζω_rω/(ω_r² − ω² + 2iζω_rω), ζ = 1e-3, ω_r = 2π·100 rad/s,
  has two phase crossovers inside one grid interval (u = (ω_r² − ω²)/(2ζω_rω) = (3 ± √21)/2,
  ω = −ζω_r u + √((ζω_r u)² + ω_r²), Re L = −0.2209 and −0.6791): the governing upper gain
  margin is 20 log₁₀(1/0.6791) = 3.361 dB at the crossover above ω_r (u < 0). Here a ramp
  −iκ(ω − ω_s) for ω > ω_s = 2π·1000 rad/s, κ = 0.1/ω_s, is added (L unchanged below ω_s), so
  Im L ≈ 0.1 − κ(ω − ω_s) crosses zero near 2000 Hz with Re L ≈ −0.3: a third phase crossover,
  bracketed by the grid, of gain margin 20 log₁₀(1/0.3) ≈ 10.5 dB (not the governing one).
  |L| ≤ 0.711 below ω_s and ≤ |−0.3 − 0.8i| = 0.854 up to the grid's 10 kHz: no gain
  crossover. The gain margin's frequency is that of the crossover where it is set (LoopMargins
  docstring), the hidden one above ω_r, not the 2000 Hz one (the refinement finds the hidden
  pair after the grid's crossover; the margins must travel with their frequencies).
* **A crossover outside the window.** API contract (code docstrings, not docs/*.md):
  LoopMargins.phase_crossovers "…interpolated on the grid elsewhere" and the module
  docstring's refinement rule (within MARGIN_WINDOW_DB of the smallest, or a bracket turning
  > 30°). So a phase crossover whose gain margin lies outside the 2 dB window of the smallest
  and whose grid interval turns the phase by under 30° is reported at the zero of Im L
  linearly interpolated between the two grid points. The delay loop L(ω) = A(ω) e^{−iωτ},
  τ = 1 s, A = 0.5 (π/ω)² real and positive, has Im L = −A sin ω = 0 at ω = nπ and Re L < 0 at
  odd n: ω = π (|L| = 0.5, 20 log₁₀ 2 = 6.021 dB, refined) and 3π (|L| = 1/18,
  20 log₁₀ 18 = 25.1 dB, outside the window); 5π lies above the grid 0.5, 0.75, ..., 11.75 rad/s.
  Every grid interval turns the phase by 0.25 rad = 14.3° < 30° (not sharp), and crossing the
  negative real axis is a turn of 14.3°, not the 360° jump of the wrapped angle. A = 1 at
  ω = π/√2, where the phase margin is 180° − (π/√2)(180°/π) = 52.72°. Im L is curved over
  [9.25, 9.5], so the interpolated zero lies 2.7e-4 (relative) off 3π: the test tells the
  interpolated frequency from the refined one.

Tolerances: refined crossovers to 1e-8 ω (Illinois), so frequencies and margins to 1e-7; the
interpolated zero is a ratio of two O(0.01) values of Im L (−1.00e-2 and 4.11e-3), exact to a few ulp (1e-12); the
ramp's crossover only to 1 % (its small resonance term is not solved here). CPU: milliseconds.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.loop_margins import loop_margins

ZETA, WR = 1e-3, 2 * np.pi * 100.0
A, EPS, B = -0.3, 0.1, -0.3 - 0.4j
WS = 2 * np.pi * 1000.0  # rad/s, start of the ramp
KAPPA = 0.1 / WS


def _resonance_and_ramp(w):
    w = np.asarray(w, dtype=float)
    h = 2j * ZETA * WR * w / (WR * WR - w * w + 2j * ZETA * WR * w)
    return A + 1j * EPS + B * h - 1j * KAPPA * np.maximum(w - WS, 0.0)


def test_the_gain_margin_frequency_is_the_hidden_crossover_that_sets_it():
    grid = np.geomspace(2 * np.pi * 1.0, 2 * np.pi * 1e4, 200)
    u = np.array([(3 + np.sqrt(21)) / 2, (3 - np.sqrt(21)) / 2])
    q = 1 / (1 + u * u)
    real = A + q * (B.real - B.imag * u)
    hidden = -ZETA * WR * u + np.sqrt((ZETA * WR * u) ** 2 + WR * WR)  # rad/s
    assert hidden[1] > WR and real[1] == pytest.approx(-0.679129, abs=1e-6)
    assert np.all(np.abs(_resonance_and_ramp(grid)) < 0.86)  # no gain crossover
    m = loop_margins(_resonance_and_ramp, grid)
    assert len(m.phase_crossovers) == 3
    assert m.phase_crossovers[:2] == pytest.approx(sorted(hidden / (2 * np.pi)), rel=1e-7)
    assert m.phase_crossovers[2] == pytest.approx(2000.0, rel=1e-2)  # the ramp's, bracketed
    assert m.gain_margin_upper_db == pytest.approx(20 * np.log10(1 / abs(real[1])), rel=1e-7)
    assert m.gain_margin_frequency == pytest.approx(hidden[1] / (2 * np.pi), rel=1e-7)
    assert m.phase_margin_deg == math.inf


def _delay(w):
    w = np.asarray(w, dtype=float)
    return 0.5 * (np.pi / w) ** 2 * np.exp(-1j * w)


def test_a_phase_crossover_outside_the_window_keeps_its_interpolated_frequency():
    grid = np.arange(0.5, 12.0, 0.25)
    m = loop_margins(_delay, grid)
    lo, hi = 9.25, 9.5  # the grid interval around 3π = 9.4248
    assert lo < 3 * np.pi < hi
    im_lo, im_hi = _delay(np.array([lo, hi])).imag
    interpolated = lo + im_lo / (im_lo - im_hi) * (hi - lo)
    assert abs(interpolated / (3 * np.pi) - 1) > 1e-4  # tells interpolated from refined
    assert len(m.phase_crossovers) == 2
    assert m.phase_crossovers[0] == pytest.approx(0.5, rel=1e-7)  # π rad/s, refined
    assert m.phase_crossovers[1] == pytest.approx(interpolated / (2 * np.pi), rel=1e-12)
    assert m.gain_margin_upper_db == pytest.approx(20 * math.log10(2.0), rel=1e-7)
    assert m.gain_margin_frequency == pytest.approx(0.5, rel=1e-7)
    assert m.gain_crossovers == pytest.approx([1 / (2 * math.sqrt(2))], rel=1e-7)
    assert m.phase_margin_deg == pytest.approx(180.0 - 180.0 / math.sqrt(2), rel=1e-7)
