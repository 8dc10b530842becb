"""The Campbell diagram's names and colours sit on the curves and speeds they name.

Hand-made diagrams (constant-frequency modes, no model: the figure function takes plain arrays)
are drawn and the anchors of their texts and the colours of their points read back from the
artists. The references:

* README.md:176, "Modes are numbered from 1", alike in the Campbell diagram's tracked modes: the
  number "k" names the k-th column's curve. Where it sits is the code's stated rule
  (campbell.py:444, "just right of the last point of each curve"), not a reference; checked is
  only what naming needs: the number is at the height of its own curve's last finite point and
  within that curve's finite speed span;
* the `campbell_figure` docstring: the critical speeds [rpm] are "marked on the 1× excitation
  line (f = Ω/60) and labelled": a critical speed n_c is labelled with its speed in rpm,
  "2400 rpm", not its frequency n_c/60 = 40 (Hz) written as rpm, at (n_c, n_c/60);
* the same docstring: the excitation orders are "drawn as labelled rays f = order·Ω/60": an
  order r's name is anchored on that ray (y/x = r/60), not on the 1× ray f = Ω/60; a main-rotor
  excitation f_op at the operating speed n_op is a ray "through (operating speed, frequency)",
  f = f_op·Ω/n_op, and its name is anchored on it (y/x = f_op/n_op);
* README.md:234, `c.plot()  # Campbell diagram, log decrement as colour`, on a 60-speed grid:
  every tracked mode shows its log decrement as colour also when the markers are thinned (the
  code's stated rule, campbell.py:240, "at most ~40 markers per curve", makes 60 speeds
  thinned); each marker's colour value is the log decrement of the mode it sits on.

The anchors are exact data coordinates except the mode numbers' and the critical speeds'
(through place_point_labels, labels.py:118), which go through the axes' pixel transform and back
(an affine map and its inverse: rounding of order 1e-13 of the axis range), so positions are
compared at rel 1e-9: far below any misplacement (the wrong curve is tens of percent away).
Agg, nothing written.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from flexshaft.plot.campbell import campbell_figure  # noqa: E402

SPEEDS = np.linspace(0.0, 6000.0, 13)  # [rpm], 500 rpm apart
F_LOW, F_HIGH = 20.0, 70.0  # the two modes [Hz], far apart: the numbers need no spreading
LAST_HIGH = 9  # the upper mode is found up to SPEEDS[9] = 4500 rpm only (NaN beyond)
REL = 1e-9


def _texts(ax):
    return {t.get_text(): t for t in ax.texts}


@pytest.fixture(scope="module")
def ax():
    n = SPEEDS.size
    high = np.full(n, F_HIGH)
    high[LAST_HIGH + 1 :] = np.nan
    freqs = np.column_stack([np.full(n, F_LOW), high])
    whirl = np.array([["forward", "backward"]] * n)
    fig = campbell_figure(
        SPEEDS,
        freqs,
        whirl,
        critical_speeds_rpm=[1200.0, 4800.0],
        operating_rpm=4800.0,
        main_rotor_hz={"4/rev": 17.6},
        excitation_orders={"tail rotor 4/rev": 1.17},
    )
    return fig.axes[0]


def test_each_mode_number_is_anchored_at_the_end_of_its_own_curve(ax):
    """Mode 1's curve ends at 20 Hz, mode 2's (found up to 4500 rpm) at 70 Hz: "1" and "2" are
    anchored at those heights, each within its own curve's finite speed span (0 to 6000 rpm,
    0 to 4500 rpm)."""
    texts = _texts(ax)
    for number, (x_last, f) in {"1": (SPEEDS[-1], F_LOW), "2": (SPEEDS[LAST_HIGH], F_HIGH)}.items():
        x, y = texts[number].xy
        assert y == pytest.approx(f, rel=REL), number
        assert SPEEDS[0] <= x <= x_last * (1.0 + REL), number


def test_critical_speeds_are_labelled_with_their_speed_in_rpm(ax):
    """Criticals given at 1200 and 4800 rpm (far apart: one label each) read "1200 rpm" and
    "4800 rpm", anchored on the 1× ray at (n_c, n_c/60)."""
    labels = {t.get_text(): t.xy for t in ax.texts if t.get_text().endswith(" rpm")}
    assert set(labels) == {"1200 rpm", "4800 rpm"}
    for text, (x, y) in labels.items():
        n_c = float(text.split()[0])
        assert x == pytest.approx(n_c, rel=REL)
        assert y == pytest.approx(n_c / 60.0, rel=REL)


def test_excitation_names_are_anchored_on_their_own_rays(ax):
    """The tail rotor's 1.17× ray: y/x = 1.17/60 at its name's anchor (the 1× ray would give
    1/60, 15 % lower); the main rotor's 17.6 Hz at 4800 rpm: y/x = 17.6/4800."""
    texts = _texts(ax)
    for name, slope in {"tail rotor 4/rev": 1.17 / 60.0, "MR 4/rev": 17.6 / 4800.0}.items():
        x, y = texts[name].xy
        assert x > 0.0, name
        assert y / x == pytest.approx(slope, rel=REL), name
        assert x <= SPEEDS[-1] * (1.0 + REL), name  # the anchor is inside the diagram


def test_every_mode_keeps_its_damping_markers_when_thinned():
    """81 speeds (thinned, as README.md:234's 60 are) and three modes with log decrements 0.3,
    -0.2 and 0.6: each mode's frequency carries at least one marker, on a speed of the grid (the
    docstring: "the points are coloured by it"), and every marker's colour value is its own
    mode's δ."""
    speeds = np.linspace(0.0, 8000.0, 81)
    f_modes = (15.0, 45.0, 90.0)
    delta_modes = (0.3, -0.2, 0.6)
    n = speeds.size
    freqs = np.column_stack([np.full(n, f) for f in f_modes])
    delta = np.column_stack([np.full(n, d) for d in delta_modes])
    whirl = np.array([["forward"] * 3] * n)
    fig = campbell_figure(speeds, freqs, whirl, log_decrement=delta)
    ax = fig.axes[0]
    xy = np.vstack([np.asarray(c.get_offsets()) for c in ax.collections if c.get_array() is not None])
    value = np.concatenate([np.asarray(c.get_array()) for c in ax.collections if c.get_array() is not None])
    for f, d in zip(f_modes, delta_modes, strict=True):
        on = np.isclose(xy[:, 1], f, rtol=1e-12)
        assert on.sum() > 0, f
        assert np.isin(xy[on, 0], speeds).all(), f
        # colour values are the log decrements clipped to the colour range: these lie inside it
        np.testing.assert_allclose(value[on], d, rtol=1e-12)
