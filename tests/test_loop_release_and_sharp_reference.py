"""The loop margins' refinement rules (:mod:`flexshaft.analyses.loop_margins`) on loops built by hand.

The module's docstring states three rules that decide which crossovers are refined or released;
each is checked here on a loop function whose answer is written by hand.

* **Sharp intervals.** "Any crossover whose bracket turns the phase by more than 30°" is
  refined. The loop L(ω) = r e^{iφ(ω)} with φ piecewise linear in ω (degrees: 160 at ω = 0,
  180 at 4.3, 230 at 12, 130 at 13 rad/s, then constant) and r = 0.45 below 8 rad/s, 0.5 above
  crosses the negative real axis twice: at ω = 4.3 (|L| = 0.45, an upper gain margin
  20 log10(1/0.45) = 6.936 dB) and at ω = 12.5, inside the grid interval [12, 13] where the
  phase turns by 100°, with |L| = 0.5 (20 log10 2 = 6.021 dB, the governing margin). On the
  grid 1, 2, ..., 20 rad/s the chord between L(12) = 0.5 e^{i230°} and L(13) = 0.5 e^{i130°}
  meets the real axis at 0.5 cos 130° = −0.321 (9.86 dB), outside the 2 dB window of 6.94 dB:
  only the 100° turn sends it to refinement. |L| < 1 everywhere: no gain crossover.
* **Crossovers left on the grid.** A phase crossover whose gain margin lies outside the window
  is "interpolated on the grid": the zero of Im L interpolated linearly. With Im L piecewise
  linear in ω (0.01 (ω − 3.3) below 6 rad/s, 0.027 − 0.01 (ω − 6) above: zeros at 3.3 and
  8.7 rad/s) and Re L = −0.5 below 6 rad/s, −0.05 above, the grid 1, ..., 12 rad/s refines the
  crossover at 3.3 rad/s (6.02 dB) and leaves the one at 8.7 rad/s (26.02 dB) with its
  interpolated frequency, exact here because Im L is linear over its interval [8, 9]. The gain
  margin's frequency is 3.3 rad/s.
* **The release rule** (:func:`~flexshaft.analyses.loop_margins.release_rule`, docstring): at a
  checked frequency ω₁ with the full L and the derivatives in x = ln ω, a gain crossover lies a
  Newton step δ = −ln|L|/Re g away (g = d ln L/dx) and its phase moves by at most
  10 (|g|δ + |g'|δ²) [rad]; it is released when its phase margin less that bound exceeds another
  crossover's of the same loop by 3°. For the integrator L = c/(iω) (g = −1, g' = 0, phase
  margin 90° at every ω) checked at |L| = e^{−δ}: δ = 0.1 gives 10 × 0.1 rad = 57.30°, a lower
  end 32.70° below 30° + 3° of an accepted crossover with a 30° margin: kept; δ = 0.05 gives
  28.65°, a lower end 61.35° > 33°: released. The lagged integrator L = c/(iω(1 + iω/p)) has,
  from ln L = ln c − ln(iω) − ln(1 + iω/p) and d/dx = ω d/dω, g = −1 − iω/(p + iω) and
  g' = −iωp/(p + iω)²; at ω = p/2: g = −1.2 − 0.4i (|g| = √1.6, Re g = −1.2), g' = −0.32 − 0.24i
  (|g'| = 0.4), phase margin 90° − atan(1/2) = 63.435°, and the trust test |g'|δ ≤ 0.1 |Re g|
  holds for δ ≤ 0.3. With c set so |L| = e^{−1.2δ} (step δ) and an accepted crossover with a 2°
  margin (window: released above 5°): δ = 0.08 gives 10 (√1.6 × 0.08 + 0.4 × 0.0064) rad =
  57.98° + 1.47° = 59.45°, a lower end 3.99° ≤ 5°: kept — without the δ² term it would be 5.46°,
  released, so the curvature term decides; δ = 0.075 gives 54.36° + 1.29°, a lower end
  7.79° > 5°: released.
  A phase crossing (Im L = 0) with L = x + 0.01i, L' = i, L'' = 0 lies δ = 0.01 away and L moves
  by at most 10 × 0.01 = 0.1, released only if Re L > 0.1 (it then stays positive): Re L = −2
  stays negative, a real phase crossover, kept; Re L = 0.09, just inside the bound, kept;
  Re L = 0.11 and +2, released. (0.09 and 0.11 pin RELEASE_SAFETY × |L'|δ to (0.09, 0.11):
  a safety other than about 10, or a test of Re L > 0 in place of Re L > bound, fails.)

Tolerances: frequencies refined by regula falsi to 1e-8 ω (rtol 1e-7); the refined |L| on the
circle of radius 0.5 is exact to round-off, its margin to 1e-9 dB; the interpolated crossover
of a linear Im L is exact to round-off (rtol 1e-12). CPU: a few milliseconds.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.local_projection import RefinementTask
from flexshaft.analyses.loop_margins import loop_margins, release_rule


def _sharp_loop(w):
    w = np.asarray(w, dtype=float)
    phi = np.radians(np.interp(w, [0.0, 4.3, 12.0, 13.0, 30.0], [160.0, 180.0, 230.0, 130.0, 130.0]))
    r = np.where(w < 8.0, 0.45, 0.5)
    return r * np.exp(1j * phi)


def test_a_phase_crossover_inside_a_sharp_turn_is_refined():
    grid = np.arange(1.0, 21.0)
    result = loop_margins(_sharp_loop, grid)
    assert result.gain_margin_upper_db == pytest.approx(20.0 * math.log10(2.0), abs=1e-9)
    assert result.gain_margin_frequency == pytest.approx(12.5 / (2 * np.pi), rel=1e-7)
    np.testing.assert_allclose(result.phase_crossovers, np.array([4.3, 12.5]) / (2 * np.pi), rtol=1e-7)
    assert result.gain_margin_lower_db == -math.inf and result.phase_margin_deg == math.inf


def _linear_loop(w):
    w = np.asarray(w, dtype=float)
    im = np.where(w < 6.0, 0.01 * (w - 3.3), 0.027 - 0.01 * (w - 6.0))
    re = np.where(w < 6.0, -0.5, -0.05)
    return re + 1j * im


def test_a_crossover_outside_the_window_keeps_its_interpolated_frequency():
    result = loop_margins(_linear_loop, np.arange(1.0, 13.0))
    np.testing.assert_allclose(result.phase_crossovers, np.array([3.3, 8.7]) / (2 * np.pi), rtol=1e-12)
    assert result.gain_margin_upper_db == pytest.approx(20.0 * math.log10(2.0), abs=1e-9)
    assert result.gain_margin_frequency == pytest.approx(3.3 / (2 * np.pi), rel=1e-7)


def _task(role):
    return RefinementTask("root", 0, 1, lambda: None, role)


def test_the_release_rule_bounds_a_gain_crossovers_phase_in_degrees():
    tasks = [_task("gain"), _task("gain"), _task("gain")]
    settle = release_rule(tasks, np.zeros(3, dtype=int))  # one loop
    accepted_value = np.exp(1j * np.radians(-150.0))  # phase margin 30°
    c = 7.0
    values, slopes, omegas = [accepted_value], [0j], [1.0]
    for delta in (0.1, 0.05):
        omega = c * np.exp(delta)  # |L| = e^{-δ}
        L = c / (1j * omega)
        values.append(L)
        slopes.append(-L)  # dL/d ln ω of the integrator
        omegas.append(omega)
    curvatures = np.array([0j, values[1], values[2]])  # d²L/d ln ω² = L: g' = 0
    release = settle(
        np.arange(3), np.array(omegas), np.array(values), np.array(slopes), curvatures, np.array([True, False, False])
    )
    assert list(release) == [False, False, True]


def test_the_release_rule_keeps_a_phase_crossing_on_the_negative_side():
    values = np.array([-2.0 + 0.01j, 2.0 + 0.01j, 0.09 + 0.01j, 0.11 + 0.01j])
    n = values.size
    settle = release_rule([_task("phase") for _ in range(n)], np.zeros(n, dtype=int))
    release = settle(np.arange(n), np.ones(n), values, np.full(n, 1j), np.zeros(n, complex), np.zeros(n, dtype=bool))
    assert list(release) == [False, True, False, True]


def test_the_release_rule_counts_the_curvature_of_a_lagged_integrator():
    tasks = [_task("gain"), _task("gain"), _task("gain")]
    settle = release_rule(tasks, np.zeros(3, dtype=int))  # one loop
    p = 10.0
    omega = p / 2
    g = -1.0 - 1j * omega / (p + 1j * omega)  # d ln L / d ln ω, by hand
    dg = -1j * omega * p / (p + 1j * omega) ** 2  # its derivative in ln ω, by hand
    values, slopes, curvatures = [np.exp(1j * np.radians(-178.0))], [0j], [0j]  # phase margin 2°
    for delta in (0.08, 0.075):
        shape = 1.0 / (1j * omega * (1.0 + 1j * omega / p))
        L = np.exp(-1.2 * delta) * shape / abs(shape)  # c chosen so |L| = e^{-1.2 δ}: step δ
        values.append(L)
        slopes.append(g * L)
        curvatures.append((dg + g * g) * L)
    release = settle(
        np.arange(3),
        np.full(3, omega),
        np.array(values),
        np.array(slopes),
        np.array(curvatures),
        np.array([True, False, False]),
    )
    assert list(release) == [False, False, True]
