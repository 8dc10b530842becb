"""The Campbell diagram's bookkeeping on hand-built curves: the critical speeds where the
curves cross the excitation lines ω = kΩ, the optimal matching of the tracking, and the numbers
its tables print (mutation hunt h35a).

Curves typed by hand, their crossings worked out by hand:

* speeds Ω = 0, 20, 40, 60 rad/s; mode 0 at a constant damped frequency Im s = 50 rad/s, mode 1
  at 30 rad/s. Mode 0 meets the 1× line Ω = 50 between 40 and 60 (g = Im s − kΩ = 10, −10:
  t = 10/20, Ω = 50) and the 2× line 2Ω = 50 at Ω = 25 (g = 10, −30 between 20 and 40:
  t = 1/4); mode 1 meets them at 30 and 15. In order of speed: 15 (mode 1, 2×), 25 (mode 0,
  2×), 30 (mode 1, 1×), 50 (mode 0, 1×): mode 0's crossings are not the lowest, so an order by
  mode differs from the order by speed, and each crossing carries its own excitation order.
* a curve at Im s = 40 rad/s lies on the 2× line at the sample Ω = 20 (g = 0 exactly, no sign
  change on either side): a critical speed at 20 rad/s of order 2, if the curve is lateral; a
  torsional curve on the same line is not a lateral critical speed (the module's definition:
  the lateral curves' intersections).
* the optimal assignment of the tracking (least total cost, distinct columns) against all 3! =
  6 permutations enumerated, once where the rows' cheapest columns are distinct (they are the
  answer) and once where two rows want one column and the optimum is a 3-cycle that uses the
  matrix's least entry.

The tables: a critical speed Ω [rad/s] is Ω·60/(2π) rpm; the tracked modes are numbered from 1
(``to_dataframe``'s docstring); the mode summary's "f last" and "whirl last" are those at the last
speed; the real parts are Re s = −ζω_n of s = −ζω_n + iω_n√(1 − ζ²), negative for a damped
mode. All arithmetic exact or to round-off: tolerance 1e-12 relative. CPU: a few milliseconds.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from flexshaft.analyses.campbell import Campbell, CriticalSpeed, assignment, critical_speeds

SPEEDS = np.array([0.0, 20.0, 40.0, 60.0])


def _curves(*frequencies: float) -> np.ndarray:
    """Eigenvalues (speeds, modes) with the given constant damped frequencies [rad/s]."""
    return np.array([[-0.5 + 1j * f for f in frequencies]] * SPEEDS.size)


def test_crossings_of_the_1x_and_2x_lines_in_order_of_speed_with_their_orders():
    whirl = np.array([["forward", "backward"]] * SPEEDS.size)
    kind = np.full(whirl.shape, "lateral")
    found = critical_speeds(SPEEDS, _curves(50.0, 30.0), whirl, kind, harmonics=(1.0, 2.0))
    got = [(c.speed, c.mode, c.harmonic, c.whirl) for c in found]
    expected = [
        (15.0, 1, 2.0, "backward"),
        (25.0, 0, 2.0, "forward"),
        (30.0, 1, 1.0, "backward"),
        (50.0, 0, 1.0, "forward"),
    ]
    assert [g[1:] for g in got] == [e[1:] for e in expected]
    assert [g[0] for g in got] == pytest.approx([e[0] for e in expected], rel=1e-12)


def test_a_lateral_curve_on_the_2x_line_at_a_sample_is_a_critical_speed_a_torsional_one_is_not():
    whirl = np.array([["forward", "none"]] * SPEEDS.size)
    kind = np.array([["lateral", "torsional"]] * SPEEDS.size)
    found = critical_speeds(SPEEDS, _curves(40.0, 40.0), whirl, kind, harmonics=(2.0,))
    assert [(c.speed, c.mode, c.harmonic, c.whirl) for c in found] == [(20.0, 0, 2.0, "forward")]


def _brute_force(cost: np.ndarray) -> tuple[int, ...]:
    """The permutation of least total cost, all of them enumerated."""
    every = itertools.permutations(range(cost.shape[1]), cost.shape[0])
    return min(every, key=lambda p: sum(cost[i, j] for i, j in enumerate(p)))


def test_assignment_keeps_distinct_row_minima():
    cost = np.array([[0.0, 1.0, 2.0], [2.0, 0.0, 1.0], [1.0, 2.0, 0.0]])
    assert tuple(assignment(cost)) == _brute_force(cost) == (0, 1, 2)


def test_assignment_solves_a_conflict_with_the_least_total_cost():
    # rows 0 and 2 both want column 1; the optimum (1, 2, 0), total 0.7, is a 3-cycle (its
    # inverse (2, 0, 1) costs 18.1) through the matrix's least entry, cost[0, 1] = 0
    cost = np.array([[1.0, 0.0, 9.0], [9.0, 2.0, 0.5], [0.2, 0.1, 9.0]])
    assert len(set(np.argmin(cost, axis=1))) < 3
    assert _brute_force(cost) == (1, 2, 0)
    assert tuple(int(j) for j in assignment(cost)) == (1, 2, 0)


def _campbell() -> Campbell:
    """Two modes over three speeds: mode 0 rises from 10 to 12 Hz and whirls forward once
    spinning (planar at rest), mode 1 (ζ = 0.05, ω_n = 2π·20 rad/s) stays put, backward."""
    speeds = np.array([0.0, 100.0, 200.0])
    wn, zeta = 2 * np.pi * 20.0, 0.05
    s1 = -zeta * wn + 1j * wn * np.sqrt(1 - zeta**2)
    f0 = np.array([10.0, 11.0, 12.0])
    eig = np.stack([-1.0 + 2j * np.pi * f0, np.full(3, s1)], axis=1)
    whirl = np.array([["planar", "planar"], ["forward", "backward"], ["forward", "backward"]])
    crit = (CriticalSpeed(70.0, 0, 1.0, "forward"), CriticalSpeed(125.0, 1, 1.0, "backward"))
    kind = np.full(whirl.shape, "lateral")
    return Campbell(speeds, eig, whirl, np.zeros(whirl.shape), crit, kind)


def test_critical_speed_in_rpm():
    assert CriticalSpeed(100.0, 0, 1.0, "forward").speed_rpm == pytest.approx(100.0 * 60 / (2 * np.pi), rel=1e-12)


def test_critical_speeds_table_numbers_modes_from_one_and_gives_rpm():
    df = _campbell().to_dataframe()
    assert list(df["mode"]) == [1, 2]
    assert list(df["speed_rpm"]) == pytest.approx([70.0 * 60 / (2 * np.pi), 125.0 * 60 / (2 * np.pi)], rel=1e-12)


def test_mode_summary_reads_the_last_speed_for_f_last_and_whirl():
    rows = _campbell().mode_summary()
    assert rows[0][1] == pytest.approx(10.0, rel=1e-12)  # f first [Hz]
    assert rows[0][2] == pytest.approx(12.0, rel=1e-12)  # f last [Hz]
    assert [rows[0][4], rows[1][4]] == ["forward", "backward"]  # whirl at the last speed, not at rest


def test_real_parts_are_minus_zeta_omega_n():
    c = _campbell()
    wn, zeta = 2 * np.pi * 20.0, 0.05
    assert c.real_parts[:, 1] == pytest.approx(np.full(3, -zeta * wn), rel=1e-12)
    assert c.damping_ratios[:, 1] == pytest.approx(np.full(3, zeta), rel=1e-12)
