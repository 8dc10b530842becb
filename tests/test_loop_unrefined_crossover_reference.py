r"""The smallest phase margin of a loop with two gain crossovers, one of them inside a grid
interval whose phase turns by 19°: each crossover's margin is estimated on the grid before the
refinement picks which ones to refine, and the estimate must interpolate the phase to the
crossing.

A loop function written by construction (no control code): with x = ln(ω/ω₀), u = x,

.. math:: |L| = e^{1 - u^2},\qquad \arg L = -180° + θ(u),\qquad
          θ(u) = 7.5° - 3.75° u + 30° u^2 + 1.25° u^3 .

|L| = 1 at u = ±1 exactly, where the phase margin 180° − |arg L| is θ(−1) = 40° and
θ(1) = 35° (the cubic is the one through those values with slopes −60°/unit and +60°/unit);
the smallest is 35° at ω = ω₀ e. Between the crossovers θ stays above 7° (|L| > 1), so no
phase crossover with Re L < 0 falls there, and outside them θ passes 180° only with Re L > 0
(no phase crossover either). On the grid u = −2.4, −2.1, …, 2.4 (17 points, 0.3 apart) the
crossing at u = 1 lies a third of the way into [0.9, 1.2], where θ turns from 29.3° to 48.4° (19°: not a
"sharp" interval, which is refined whatever its estimate). The grid estimate interpolated to
the crossing is 35.0° and it is refined; the phase at the interval's far end, 48.4°, would
leave it unrefined beside the other crossover's 34.3° end value, and the margin would read 40°.

Tolerance: the refinement solves |L| = 1 to 1e-8 ω relative (loop_margins), on which θ moves
by 60°/unit × 1e-8: 1e-4° is asserted.

Written for the mutation h37a-gain-crossover-phase-interpolation of scripts/mutations.toml.
CPU: a few hundred evaluations of a closed form, under 10 ms.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.loop_margins import loop_margins

W0 = 100.0  # rad/s


def _theta_deg(u):
    return 7.5 - 3.75 * u + 30.0 * u**2 + 1.25 * u**3


def _loop(omegas):
    u = np.log(np.asarray(omegas, dtype=float) / W0)
    return np.exp(1.0 - u**2) * np.exp(1j * np.radians(-180.0 + _theta_deg(u)))


def test_the_smallest_phase_margin_is_found_at_a_crossover_inside_a_turning_interval():
    assert _theta_deg(-1.0) == pytest.approx(40.0) and _theta_deg(1.0) == pytest.approx(35.0)
    grid = W0 * np.exp(np.linspace(-2.4, 2.4, 17))
    m = loop_margins(_loop, grid)
    assert m.phase_margin_deg == pytest.approx(35.0, abs=1e-4)
    assert m.phase_margin_frequency == pytest.approx(W0 * np.e / (2 * np.pi), rel=1e-6)
    assert sorted(m.gain_crossovers)[0] == pytest.approx(W0 / np.e / (2 * np.pi), rel=0.05)
    assert len(m.gain_crossovers) == 2
