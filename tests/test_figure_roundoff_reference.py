"""Figures of an undamped response or spectrum draw its round-off as what it is: nothing.

* **Bode phase.** An undamped receptance 1/(k − m Ω²) is real: its phase is exactly 0° below the
  resonance (and 180° above it), so a response below it carries only round-off in its imaginary
  part (here 1e-16 of the amplitude, 6e-15°). matplotlib autoscales such a line to a band of
  ±1e-14° whose 90° locator draws no tick at all, and the figure then reads as a phase somewhere
  between two unlabelled edges. The axis must show the phase at its true scale: a span of at
  least 180° with the 90° ticks around the line (−90, 0, 90).
* **Campbell colour.** An undamped mode's log decrement 2πσ/ω is 0; an eigen-solution gives it
  as ±1e-18 (the sign of round-off). Coloured by it, the diagram painted half the points red
  ("unstable") on a colour bar from −1e-18 to 1e-18. Every point must get the colour of δ = 0,
  on a bar that does not reach below zero.
"""

from __future__ import annotations

import numpy as np

from flexshaft.plot.campbell import campbell_figure
from flexshaft.plot.response import bode_figure


def _close(fig) -> None:
    import matplotlib.pyplot as plt

    plt.close(fig)


def test_a_phase_that_does_not_turn_is_drawn_on_a_90_degree_scale():
    speeds = np.linspace(0.0, 400.0, 81)  # below the 500 rad/s resonance
    real = 1e-3 / (1.0 - (speeds / 500.0) ** 2)
    response = real * (1.0 + 1e-16j * np.sin(speeds))  # round-off in the imaginary part
    fig = bode_figure(speeds, {"undamped": response})
    phase_ax = fig.axes[1]
    lo, hi = phase_ax.get_ylim()
    assert hi - lo >= 180.0 and lo < -90.0 < 0.0 < 90.0 < hi
    ticks = [t for t in phase_ax.get_yticks() if lo <= t <= hi]
    assert ticks == [-90.0, 0.0, 90.0]
    _close(fig)


def test_an_undamped_modes_round_off_gets_the_colour_of_zero_damping():
    speeds = np.linspace(0.0, 3000.0, 7)
    freqs = np.column_stack([np.full(7, 20.0), np.full(7, 20.0)])  # a pair at 20 Hz
    whirl = np.array([["forward", "backward"]] * 7)
    delta = 1e-18 * np.where(np.arange(14).reshape(7, 2) % 2 == 0, 1.0, -1.0)  # ± round-off
    fig = campbell_figure(speeds, freqs, whirl, log_decrement=delta)
    ax = fig.axes[0]
    collections = [c for c in ax.collections if c.get_array() is not None]
    for c in collections:
        c.update_scalarmappable()  # the colours as drawn
    colours = np.vstack([c.get_facecolors() for c in collections])
    norm = collections[0].norm
    zero = collections[0].cmap(norm(0.0))
    assert norm.vmin >= 0.0  # no unstable (red) half on the colour bar
    np.testing.assert_array_equal(colours, np.tile(zero, (colours.shape[0], 1)))
    _close(fig)


def test_a_failed_check_with_no_margin_to_show_reads_fails_not_minus_zero():
    """A thermal runaway fails with the margin of its last temperature, drawn at −1e-300 (below
    zero, :func:`~flexshaft.verdict.result.normalised_margin`), which "{:+.0%}" prints as "-0%":
    a failure that reads as exactly at the limit. A failure with no finite margin (−inf) is no
    "not evaluated" either. Both bars must say they fail; a real −25 % keeps its number."""
    from flexshaft.plot.verdict import margins_figure

    fig = margins_figure(["runaway", "no margin", "orbit"], [-1e-300, -np.inf, -0.25], ["fail", "fail", "fail"])
    texts = [t.get_text() for t in fig.axes[0].texts]
    assert texts == ["fails", "fails: no finite margin", "-25%"]
    _close(fig)
