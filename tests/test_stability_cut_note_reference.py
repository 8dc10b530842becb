"""The stability panel says when it cuts curves, and only then.

A log-decrement panel's view is chosen to show the unstable side and the requirement; a well
damped mode may then run off its top, and the panel writes a note "curves above δ = … cut". The
reference is what the reader sees, read from the axes independently of how the view was chosen:
a curve is cut when some tracked δ is above the upper limit of the panel's y axis. Hand-built
curves (no model):

* a mode at δ = 2.0 with another going slightly unstable (δ down to −0.05): the view is sized to
  the small values (the unstable side must be legible), the δ = 2.0 curve is above the axis: the
  note is there, and the δ it names is inside the view (below the axis' upper limit) and below
  the cut curve;
* the same with the damped mode at δ = 0.2: every curve is inside the view: no note;
* review r126: the damped mode at δ = 0.31 and 0.32, above the view's chosen top 0.3 but inside
  its 8 % margin (the axis ends at 0.328): visible, so no note (the panel wrote one before); and a
  requirement δ ≥ 0.5 that makes the view taller than every curve (δ = 0.2): no note.

Exact comparisons (the inputs and the limits are plain floats; the note's δ, the axis' top
since review r126, is printed to three significant figures and compared with the axis' top to half a unit
in the third figure, 5e-3 of a mantissa 1.00). Agg, nothing written.
"""

from __future__ import annotations

import re

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from flexshaft.plot.stability import log_decrement_figure  # noqa: E402

SPEEDS = np.linspace(0.0, 6000.0, 7)  # [rpm]


def _panel(damped: float, required: float | None = None):
    unstable = 0.1 - SPEEDS / 40000.0  # 0.1 at rest down to −0.05 at 6000 rpm
    delta = np.column_stack([unstable, np.full(SPEEDS.size, damped)])
    fig = log_decrement_figure(SPEEDS, {"shaft": delta}, {"shaft": 4000.0}, required=required)
    ax = fig.axes[0]
    notes = [t.get_text() for t in ax.texts if "cut" in t.get_text()]
    plt.close(fig)
    return delta, ax.get_ylim(), notes


def test_a_curve_above_the_view_is_declared_cut():
    delta, (_, high), notes = _panel(2.0)
    assert delta.max() > high  # the reference: the δ = 2 curve leaves the view
    assert len(notes) == 1, notes
    named = float(re.search(r"δ = ([-0-9.e+]+) cut", notes[0]).group(1))
    assert named == pytest.approx(high, rel=5e-3) and named < delta.max()  # the axis' top, three figures


def test_no_note_when_every_curve_is_in_view():
    delta, (low, high), notes = _panel(0.2)
    assert low <= delta.min() and delta.max() <= high  # the reference: nothing leaves the view
    assert notes == []


@pytest.mark.parametrize("damped, required", [(0.31, None), (0.32, None), (0.2, 0.5), (2.0, 0.5)])
def test_the_note_is_written_exactly_when_a_curve_leaves_the_view(damped, required):
    delta, (_, high), notes = _panel(damped, required)
    assert (len(notes) == 1) == bool(delta.max() > high), (damped, required, high, notes)
    if notes:
        named = float(re.search(r"δ = ([-0-9.e+]+) cut", notes[0]).group(1))
        assert named == pytest.approx(high, rel=5e-3) and named < delta.max()  # the axis' top, three figures
