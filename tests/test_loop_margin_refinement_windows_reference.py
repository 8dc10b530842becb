"""The refinement windows of the loop margins on loops built by hand (hunt h54f).

Reference: the module docstring of :mod:`flexshaft.analyses.loop_margins` (hand-written): the
refinement starts from "the local maxima of |S| within PEAK_WINDOW of the largest grid value
[0.8] or more than twice a neighbour" and "the gain crossovers whose phase margin interpolated
on the grid is within MARGIN_WINDOW_DEG [3°] of the smallest". Each loop below is made so that
its answer is written by hand and only a window of the documented width finds it.

**A resonance sampled off its top.** The sensitivity is set directly, S = 1/(1 + L), so
L = 1/S − 1, with S piecewise a Lorentzian: S = 1 + A/(1 + i(ω − ω_A)/γ) below 200 rad/s and
1 + B/(1 + i(ω − ω_B)/γ) above, A = 4.5, B = 4, ω_A = 100, ω_B = 300, γ = 10 rad/s
(Re S > 0: L finite). With x = (ω − ω_c)/γ, |S|² = ((1 + A)² + x²)/(1 + x²), whose only
maximum is x = 0: the largest |S| is 1 + A = 5.5 at ω = 100 rad/s (derived here), the other
peak's 1 + B = 5 at 300 rad/s. The grid (17 rad/s steps) holds 300 exactly (|S| = 5, the grid's
largest) and samples the first peak at 107.7 rad/s (x = 0.77: |S| = 4.400, 88 % of 5) between
90.7 (4.085) and 124.7 (2.263): within the 80 % window, and not "more than twice a neighbour"
(4.400 < 2 × 2.263), so only the window sends it to refinement; refined, it is the peak.

**A gain crossover whose interpolated phase margin errs.** L = r e^{iφ} with ln r and φ [deg]
piecewise linear in ω: ln r = 0.1 up to 4, −0.1 from 5 to 14, 0.1 from 15 rad/s (|L| = 1 at
4.5 and 14.5 rad/s, midway in the grid intervals [4, 5] and [14, 15] of the grid 1, 2, ...,
20 rad/s); φ = −148.5° at 4 and 5 rad/s with a dip to −150° at 4.5, and −149° from 14 to 14.5
falling to −149.6° at 15 rad/s. The true phase margins 180° − |φ| are 30° at 4.5 rad/s (the
smallest) and 31° at 14.5 rad/s; the grid's interpolation (ln |L| linear: the crossover midway,
the phase the mean of the ends' phases) reads 31.5° and 30.7°. Within the 3° window both are
refined and the margin is 30° at 4.5 rad/s; a narrower window refines only the second.
|L| stays within e^{±0.1}, φ within −150° and −148.5°: no phase crossover.

**A phase crossover whose interpolated gain margin errs.** L = Re L + i Im L, both piecewise
linear in ω: Im L = −0.045, −0.005, 0.005, 0.005, −0.005, −0.15 at 0, 4, 5, 14, 15, 30 rad/s
(zeros at 4.5 and 14.5 rad/s, midway in [4, 5] and [14, 15]; no other change of sign);
Re L = −0.5 except a dip to −0.56 at 4.5 rad/s (−0.5 at 4 and 5) and −0.53 from 14 to
14.5 rad/s (−0.5 at 15). The true upper gain margins 20 log10(1/|L|) are 5.036 dB at 4.5 rad/s
(the smallest) and 5.514 dB at 14.5 rad/s; the grid's chords read |L| = 0.5 (6.021 dB) and
0.515 (5.764 dB). Within the 2 dB window both are refined and the margin is 20 log10(1/0.56)
at 4.5 rad/s; a narrower window refines only the second. |L| < 1 everywhere: no gain crossover.

Tolerances: the golden-section search stops at 1e-6 in ln ω: the frequency of a smooth maximum
to ~1e-6 relative (rel 1e-5 asserted), its value to second order (rel 1e-9 asserted); the gain
crossovers are roots of a linear ln |L| (the phase crossovers of a linear Im L) that regula
falsi finds to round-off, where φ (Re L) is exact to round-off: margins to 1e-9° (1e-9 dB),
frequencies to rel 1e-9. CPU: a few milliseconds.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.loop_margins import loop_margins

W_A, W_B, GAMMA, A, B, SPLIT = 100.0, 300.0, 10.0, 4.5, 4.0, 200.0


def _two_resonances(w):
    w = np.asarray(w, dtype=float)
    S = np.where(w < SPLIT, 1 + A / (1 + 1j * (w - W_A) / GAMMA), 1 + B / (1 + 1j * (w - W_B) / GAMMA))
    return 1.0 / S - 1.0


def test_a_resonance_the_grid_samples_off_its_top_is_refined_within_the_peak_window():
    step = 17.0
    grid = np.concatenate([W_A + 7.7 + step * np.arange(-4, 6), W_B + step * np.arange(-5, 6)])
    sampled = np.abs(1.0 / (1.0 + _two_resonances(grid)))
    k = int(np.argmax(np.where(grid < SPLIT, sampled, 0.0)))
    # the premises: the first peak's best sample lies between 80 % and 95 % of the grid's
    # largest value (the other peak's exact top) and is not twice a neighbour
    assert sampled.max() == pytest.approx(1 + B, rel=1e-12)
    assert 0.8 * sampled.max() < sampled[k] < 0.95 * sampled.max()
    assert sampled[k] < 2.0 * min(sampled[k - 1], sampled[k + 1])
    result = loop_margins(_two_resonances, grid)
    assert result.peak_sensitivity == pytest.approx(1 + A, rel=1e-9)
    assert result.peak_frequency == pytest.approx(W_A / (2 * math.pi), rel=1e-5)


def _two_gain_crossovers(w):
    w = np.asarray(w, dtype=float)
    log_r = np.interp(w, [0.0, 4.0, 5.0, 14.0, 15.0, 30.0], [0.1, 0.1, -0.1, -0.1, 0.1, 0.1])
    phi = np.interp(
        w,
        [0.0, 4.0, 4.5, 5.0, 14.0, 14.5, 15.0, 30.0],
        [-148.5, -148.5, -150.0, -148.5, -149.0, -149.0, -149.6, -149.6],
    )
    return np.exp(log_r + 1j * np.radians(phi))


def test_a_gain_crossover_within_the_phase_margin_window_of_the_smallest_estimate_is_refined():
    result = loop_margins(_two_gain_crossovers, np.arange(1.0, 21.0))
    assert result.phase_margin_deg == pytest.approx(30.0, abs=1e-9)
    assert result.phase_margin_frequency == pytest.approx(4.5 / (2 * math.pi), rel=1e-9)
    np.testing.assert_allclose(result.gain_crossovers, np.array([4.5, 14.5]) / (2 * math.pi), rtol=1e-9)
    assert result.phase_crossovers == ()


def _two_phase_crossovers(w):
    w = np.asarray(w, dtype=float)
    imag = np.interp(w, [0.0, 4.0, 5.0, 14.0, 15.0, 30.0], [-0.045, -0.005, 0.005, 0.005, -0.005, -0.15])
    real = np.interp(
        w, [0.0, 4.0, 4.5, 5.0, 14.0, 14.5, 15.0, 30.0], [-0.5, -0.5, -0.56, -0.5, -0.53, -0.53, -0.5, -0.5]
    )
    return real + 1j * imag


def test_a_phase_crossover_within_the_gain_margin_window_of_the_smallest_estimate_is_refined():
    result = loop_margins(_two_phase_crossovers, np.arange(1.0, 21.0))
    assert result.gain_margin_upper_db == pytest.approx(20.0 * math.log10(1.0 / 0.56), abs=1e-9)
    assert result.gain_margin_frequency == pytest.approx(4.5 / (2 * math.pi), rel=1e-9)
    np.testing.assert_allclose(result.phase_crossovers, np.array([4.5, 14.5]) / (2 * math.pi), rtol=1e-9)
    assert result.gain_margin_lower_db == -math.inf and result.gain_crossovers == ()
