"""A pair of gain crossovers hidden inside one grid interval, beside a sharp sensitivity peak.

The loop (a delayed integrator plus a lightly damped mode, real coefficients)::

    L(s) = e^{−sτ} [g/s + a·2ζω_n²/(s² + 2ζω_n s + ω_n²)],
    ω_n = 2π·100 rad/s, ζ = 0.0025, ω_n τ = 80°, g = 0.78 ω_n, a = 0.24.

At ω_n both terms lie at −90° before the delay (g/(iω_n) = −0.78i, the mode −a i = −0.24i), so
|L(iω_n)| = 1.02 > 1, while the integrator alone is below 1 above g/(2π) = 78 Hz: |L| rises above
1 only over the mode's half width, a band of 0.16 Hz about 100 Hz (derived here). The closed
loop's lightly damped pole (1 + L(s) = 0, solved below by Newton) lies at 100.14 Hz, ζ = 7.8e-4,
and the |S| peak beside it, where |L| = 0.96 < 1: a grid of loop_grid's recipe (200 logarithmic
points over 0.1 Hz-2 kHz and ω_d + (−½, 0, ½)ζ|s| at the pole) has |L| < 1 at every point near
the mode (asserted: the pair is hidden, no grid interval shows a change of sign), and splitting
its intervals at the refined |S| peak shows none either. The two crossings set the phase margin
(≈ 6°, against 27.8° at the integrator's crossover at 78 Hz).

Reference (independent of the code's refinement): |L(iω)| − 1 of the closed form above on a
uniform 200 001-point scan of 99.5-100.5 Hz (5e-6 Hz steps; the band is 0.16 Hz wide, so
both changes of sign are seen), each bracket then bisected on the closed form to 1e-13 Hz, and
the phase margin 180° − |arg L| there. Tolerances: the code refines a crossover to 1e-8 ω
(1e-6 Hz at 100 Hz); the phase of L turns by less than 100°/Hz over the scan (asserted; the
margin changes by 8° over the pair's 0.16 Hz, 50°/Hz), so the refined phase margin is within
1e-4° of the reference's, asserted to 1e-3°, and the frequencies to 2e-8 relative (two
refinement tolerances).
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.loop_margins import loop_margins

OMEGA_N = 2.0 * np.pi * 100.0
ZETA = 0.0025
TAU = np.radians(80.0) / OMEGA_N
G = 0.78 * OMEGA_N
A = 0.24


def _loop_s(s):
    """The closed form L(s) of the module docstring."""
    return np.exp(-s * TAU) * (G / s + A * 2.0 * ZETA * OMEGA_N**2 / (s**2 + 2.0 * ZETA * OMEGA_N * s + OMEGA_N**2))


def _loop(omegas):
    return _loop_s(1j * np.asarray(omegas, dtype=float))


def _grid() -> np.ndarray:
    """loop_grid's recipe: 200 log points over 0.1 Hz-2 kHz plus ω_d + (−½, 0, ½)ζ|s| at the
    closed-loop pole near ω_n (Newton on 1 + L(s) = 0 from the open-loop mode)."""
    s = 1j * OMEGA_N * 1.0016
    for _ in range(50):
        h = 1e-6 * OMEGA_N
        s -= (1.0 + _loop_s(s)) / ((_loop_s(s + h) - _loop_s(s - h)) / (2.0 * h))
    assert abs(1.0 + _loop_s(s)) < 1e-10
    damping = -s.real / abs(s)
    assert 5e-4 < damping < 1e-3 and abs(s.imag / (2.0 * np.pi) - 100.14) < 0.01
    base = 2.0 * np.pi * np.geomspace(0.1, 2000.0, 200)
    return np.unique(np.concatenate([base, s.imag + np.array([-0.5, 0.0, 0.5]) * damping * abs(s)]))


def _reference_crossings() -> list[tuple[float, float]]:
    """(frequency [Hz], phase margin [deg]) of each |L| = 1 in 99.5-100.5 Hz (module docstring)."""
    f = np.linspace(99.5, 100.5, 200_001)
    excess = np.abs(_loop(2.0 * np.pi * f)) - 1.0
    phase = np.unwrap(np.angle(_loop(2.0 * np.pi * f)))
    assert np.max(np.abs(np.diff(np.degrees(phase)))) / (f[1] - f[0]) < 100.0  # turn rate [deg/Hz]
    crossings = []
    for k in np.flatnonzero(np.sign(excess[:-1]) != np.sign(excess[1:])):
        lo, hi = f[k], f[k + 1]
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if np.sign(abs(_loop(2.0 * np.pi * mid)) - 1.0) == np.sign(excess[k]):
                lo = mid
            else:
                hi = mid
        x = 0.5 * (lo + hi)
        crossings.append((x, 180.0 - abs(float(np.degrees(np.angle(_loop(2.0 * np.pi * x)))))))
    return crossings


def test_the_hidden_pair_of_gain_crossovers_sets_the_phase_margin():
    """The phase margin is the pair's, at its upper crossing (≈ 6.0° at 100.08 Hz)."""
    grid = _grid()
    near = np.abs(grid / OMEGA_N - 1.0) < 0.05
    assert np.all(np.abs(_loop(grid[near])) < 1.0)  # the premise: the grid shows no change of sign there
    pair = _reference_crossings()
    assert len(pair) == 2
    (low, pm_low), (high, pm_high) = pair
    assert 0.1 < high - low < 0.2 and pm_high < pm_low  # derived bands of the docstring
    margins = loop_margins(_loop, grid)
    assert abs(margins.phase_margin_deg - pm_high) < 1e-3
    assert abs(pm_high - 6.0) < 0.05  # the reviewer's 6.0° (sanity of the reference itself)
    assert abs(margins.phase_margin_frequency - high) < 2e-8 * high
    assert len(margins.gain_crossovers) == 3  # the integrator's at 78 Hz and the pair
    found = np.array(margins.gain_crossovers)
    for x in (low, high):
        assert np.min(np.abs(found - x)) < 2e-8 * x
