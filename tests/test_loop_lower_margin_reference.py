"""Gain margins of a loop with several phase crossovers of known gain (mutation hunt 19c).

A loop with a transport delay τ (a digital controller's computation time) and a symmetric pair
of real poles ±ω0 (a magnet's negative stiffness on a mass, m s² − k_s):

    L(s) = −a e^{−sτ} / (1 − s²/ω0²),   so at s = iω   L = −a e^{−iωτ} / (1 + ω²/ω0²):

|L| = a/(1 + ω²/ω0²) and arg L = π − ωτ exactly. L is real and negative at ωτ = 2πj
(j = 0, 1, 2, ...), the phase crossovers, with |L| = a/(1 + (2πj/(ω0τ))²). With a = 10 and
ω0τ = π: |L| = 10, 2, 10/17, 10/37, ... at ω = 0, 2ω0, 4ω0, 6ω0, ... The gain may fall by
20 log10(1/10) = −20 dB (at ω = 0) or −6.02 dB (at 2ω0) before L reaches −1: the lower gain
margin is the one closest to 0 dB, 20 log10(1/2) dB at 2ω0; the upper one is the smallest
above 0 dB, 20 log10(1.7) = 4.61 dB at 4ω0, which is also the margin nearer 0 dB
(``gain_margin_db``).

Tolerance 2e-7 dB and 1e-7 relative in frequency: the crossovers are refined to 1e-8 ω
relative (loop_margins' root tolerance), and d ln|L|/d ln ω = −2 (ω/ω0)²/(1 + (ω/ω0)²), so an
error δ in ω moves |L| by less than 2δ relative: 20 log10(1 + 2e-8) = 1.7e-7 dB.
CPU: a few hundred loop evaluations, about 2 ms.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.loop_margins import loop_margins

A, OMEGA_0 = 10.0, 100.0  # static loop gain [-], pole pair [rad/s]
TAU = np.pi / OMEGA_0  # delay [s]


def _loop(w: np.ndarray) -> np.ndarray:
    s = 1j * w
    return -A * np.exp(-s * TAU) / (1 - (s / OMEGA_0) ** 2)


def test_the_lower_gain_margin_is_the_phase_crossover_closest_to_0_db():
    grid = np.geomspace(0.01 * OMEGA_0, 20 * OMEGA_0, 1500)
    margins = loop_margins(_loop, grid, static_gain=-A)
    lower = 20 * np.log10(1 / (A / (1 + 2**2)))  # at ω = 2 ω0: |L| = 2
    upper = 20 * np.log10(1 / (A / (1 + 4**2)))  # at ω = 4 ω0: |L| = 10/17
    assert lower == pytest.approx(-6.0206, abs=1e-4) and upper == pytest.approx(4.6090, abs=1e-4)
    assert margins.gain_margin_lower_db == pytest.approx(lower, abs=2e-7)
    assert margins.gain_margin_upper_db == pytest.approx(upper, abs=2e-7)
    assert margins.gain_margin_db == pytest.approx(upper, abs=2e-7)
    assert margins.gain_margin_frequency == pytest.approx(4 * OMEGA_0 / (2 * np.pi), rel=1e-7)
    hz = np.array(margins.phase_crossovers[:3])
    np.testing.assert_allclose(hz, [0.0, 2 * OMEGA_0 / (2 * np.pi), 4 * OMEGA_0 / (2 * np.pi)], rtol=1e-7)
