r"""The frequency of the smallest phase margin when it is set by a gain crossover hidden inside
a grid interval (found in the second round, after the grid's own crossovers).

A loop function written by construction (no control code): with x = ln(ω/ω₀),

.. math:: \ln|L| = -c + \frac{c + δ}{1 + ((x - x_r)/ε)^2} + c\,(1 + \tanh((x - x_h)/w)),\qquad
          \arg L = -180° + T (x - x_r - s),

c = 0.5, δ = 0.05, ε = 0.03, x_r = 0, x_h = 0.5, w = 0.02, T = 100°/unit, s = d/3 with
d = ε√(δ/c). The narrow bump lifts |L| above 1 only for |x − x_r| < d: |L| = 1 at x_r ± d
exactly (the tanh term is 2e-22 there, far below round-off), where the phase margin
180° − |arg L| is T(d + s) = 1.265° and T(d − s) = 0.632°. A third gain crossover lies near
x_h (phase margin about 50°). On the grid x = −1.05, −0.95, …, 1.45 (0.1 apart) the pair lies
inside [−0.05, 0.05], whose ends both read ln|L| = −0.354: no change of sign, only the refined
peak of |S| reveals the pair. That peak lies at x ≈ 0.00929, 2.0e-4 inside the upper crossover
d = 0.00949 (near x = d, |1 + L|² ≈ g′²(x − d)² + φ′²(x − s)² with g′ = d ln|L|/dx = −9.58 and
φ′ = 1.745 rad per unit, so x_p ≈ d − φ′²(d − s)/(g′² + φ′²); a 400 001-point scan agrees):
inside the pair by far more than the peak's refinement tolerance (1e-6), which is what the
test rests on. So the grid's
crossover near x_h is listed before the hidden pair, and the smallest phase margin, 0.632°, is
read at ω₀ e^d, the pair's upper crossover (the docstring of :class:`LoopMargins`:
``phase_margin_frequency`` is "the gain crossover of the smallest phase margin").

Tolerances: the crossovers are refined to 1e-8 ω relative (loop_margins): 1e-7 is asserted on
the frequencies, and on the margin T × 1e-8 → 1e-5° is asserted.

Written for the mutation h58e-loop-phase-margins-not-reordered of scripts/mutations.toml.
CPU: a few hundred evaluations of a closed form, under 20 ms.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.loop_margins import loop_margins

W0 = 2 * np.pi * 50.0  # rad/s
C, DELTA, EPS = 0.5, 0.05, 0.03
X_H, WIDTH, T = 0.5, 0.02, 100.0
D = EPS * np.sqrt(DELTA / C)
S = D / 3


def _loop(omegas):
    x = np.log(np.asarray(omegas, dtype=float) / W0)
    log_mag = -C + (C + DELTA) / (1 + (x / EPS) ** 2) + C * (1 + np.tanh((x - X_H) / WIDTH))
    return np.exp(log_mag) * np.exp(1j * np.radians(T * (x - S) - 180.0))


def test_the_smallest_phase_margin_is_read_at_its_own_hidden_crossover():
    """Crossovers ω₀e^{∓d} (closed form, module docstring), the smallest margin T(d − s) read at ω₀e^{d}."""
    grid = W0 * np.exp(-1.05 + 0.1 * np.arange(26))
    k = np.searchsorted(grid, W0)
    assert np.all(np.abs(_loop(grid[k - 1 : k + 1])) < 1)  # the pair's interval shows no sign change
    m = loop_margins(_loop, grid)
    assert len(m.gain_crossovers) == 3
    assert m.gain_crossovers[:2] == pytest.approx(
        [W0 * np.exp(-D) / (2 * np.pi), W0 * np.exp(D) / (2 * np.pi)], rel=1e-7
    )
    assert m.phase_margin_deg == pytest.approx(T * (D - S), abs=1e-5)
    assert m.phase_margin_frequency == pytest.approx(W0 * np.exp(D) / (2 * np.pi), rel=1e-7)
