"""The Campbell diagram draws each mode's whole curve: unbroken across a whirl change, and
inside the frequency axis.

Hand-built diagrams (no model: the figure function takes plain arrays); references derived here:

* a tracked mode is one continuous function f(Ω) sampled at the analysed speeds Ω_1 < … < Ω_n;
  drawn as a polyline it consists of the n − 1 straight pieces [Ω_i, Ω_i+1]. Splitting the
  polyline where the whirl label changes (solid forward, dashed backward) must not drop a piece:
  the pieces of all the mode's segments together are exactly the n − 1 intervals, and the
  segments meet at a shared speed (the piece across the change belongs to one of them);
* a forward-whirl mode stiffened by the gyroscopic moment rises with speed (here from 50 Hz at
  rest to 150 Hz at the top speed); every drawn point of every mode must lie inside the
  frequency axis, 0 ≤ f ≤ top of the axis, whatever the speed at which the mode peaks.

Speeds and frequencies are copied into the artists, never computed: the comparisons are exact
(the axis-limit check is an inequality with no tolerance needed). Agg, nothing written.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from flexshaft.plot.campbell import campbell_figure  # noqa: E402

SPEEDS = np.linspace(0.0, 6000.0, 7)  # [rpm], 1000 rpm apart


def _mode_lines(ax, freqs: np.ndarray) -> list:
    """The lines drawn for one mode: those whose y data are a slice of that mode's frequencies."""
    out = []
    for line in ax.get_lines():
        x = np.asarray(line.get_xdata(), dtype=float)
        y = np.asarray(line.get_ydata(), dtype=float)
        if x.size < 2 or x.size != y.size:
            continue
        idx = np.searchsorted(SPEEDS, x)
        if np.all(idx < SPEEDS.size) and np.array_equal(SPEEDS[idx], x) and np.array_equal(freqs[idx], y):
            out.append(line)
    return out


@pytest.mark.parametrize("damped", [False, True])
def test_whirl_change_keeps_every_piece_of_the_curve(damped):
    """A mode forward at the first four speeds and backward at the last three: its solid and dashed
    segments together cover all six intervals of the speed grid, and the dashed one starts where
    the solid one ends, at one of the two speeds bracketing the change (3000 or 4000 rpm)."""
    n = SPEEDS.size
    f = np.linspace(60.0, 30.0, n)  # a falling (backward-going) mode [Hz], not on any excitation line
    whirl = np.array([["forward"]] * 4 + [["backward"]] * 3)
    delta = np.full((n, 1), 0.2) if damped else None
    ax = campbell_figure(SPEEDS, f[:, None], whirl, log_decrement=delta).axes[0]
    lines = _mode_lines(ax, f)
    pieces = set()
    for line in lines:
        x = list(line.get_xdata())
        pieces |= set(zip(x[:-1], x[1:]))
    assert pieces == set(zip(SPEEDS[:-1], SPEEDS[1:]))
    styles = {line.get_linestyle(): list(line.get_xdata()) for line in lines}
    assert styles["-"][-1] == styles["--"][0]
    assert styles["--"][0] in (3000.0, 4000.0)


def test_rising_forward_mode_stays_inside_the_frequency_axis():
    """A forward mode rising 50 → 150 Hz and a backward one falling 50 → 20 Hz, no critical given:
    the top of the frequency axis is at least the highest drawn frequency, 150 Hz (at 6000 rpm),
    so no part of either curve is cut off."""
    n = SPEEDS.size
    freqs = np.column_stack([np.linspace(50.0, 150.0, n), np.linspace(50.0, 20.0, n)])
    whirl = np.array([["forward", "backward"]] * n)
    ax = campbell_figure(SPEEDS, freqs, whirl).axes[0]
    low, top = ax.get_ylim()
    for mode in range(2):
        (line,) = _mode_lines(ax, freqs[:, mode])
        y = np.asarray(line.get_ydata(), dtype=float)
        assert low <= y.min() and y.max() <= top
    assert top >= 150.0
