"""The Campbell diagram's names and colours sit on the curves and speeds they name.

Hand-made diagrams (constant-frequency modes, no model: the figure function takes plain arrays)
are drawn and the anchors of their texts and the colours of their points read back from the
artists. The references, derived here:

* a mode's number names its curve: it is anchored at the curve's last drawn point, (the last
  speed where the mode's frequency is finite, that frequency), as the mode numbers are placed
  "just right of the last point of each curve";
* a critical speed n_c given in rpm is labelled in rpm, with its value: "2400 rpm", not its
  frequency n_c/60 = 40 (Hz) written as rpm;
* an excitation given as an order r of the shaft speed is the ray f = r·n/60 [Hz]; its name is
  anchored on that ray (y/x = r/60), not on the 1× ray f = n/60;
* a main-rotor excitation f_op at the operating speed n_op is the ray f = f_op·n/n_op; its name
  is anchored on it (y/x = f_op/n_op);
* every tracked mode has its log decrement shown: when the markers are thinned (more than 40
  speeds: "at most ~40 markers per curve"), every curve keeps markers at the same speeds, and
  each marker's colour value is the log decrement of the mode it sits on.

The anchors are exact data coordinates except the mode numbers', which go through the axes'
pixel transform and back (an affine map and its inverse: rounding of order 1e-13 of the axis
range), so positions are compared at rel 1e-9: far below any misplacement (the wrong curve is
tens of percent away). Agg, nothing written.
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


def test_each_mode_number_is_anchored_at_the_last_point_of_its_own_curve(ax):
    """Mode 1 ends at (6000 rpm, 20 Hz); mode 2, found up to 4500 rpm, at (4500 rpm, 70 Hz)."""
    texts = _texts(ax)
    for number, (x, f) in {"1": (SPEEDS[-1], F_LOW), "2": (SPEEDS[LAST_HIGH], F_HIGH)}.items():
        xy = texts[number].xy
        assert xy[0] == pytest.approx(x, rel=REL), number
        assert xy[1] == pytest.approx(f, rel=REL), number


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
    """81 speeds (more than 40: thinned) and three modes with log decrements 0.3, -0.2 and
    0.6: each mode's frequency carries markers (at least one, at most 40) at the same speeds of
    the grid, and every marker's colour value is its own mode's δ."""
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
    marked = []
    for f, d in zip(f_modes, delta_modes, strict=True):
        on = np.isclose(xy[:, 1], f, rtol=1e-12)
        assert 0 < on.sum() <= 40, f
        # colour values are the log decrements clipped to the colour range: these lie inside it
        np.testing.assert_allclose(value[on], d, rtol=1e-12)
        marked.append(np.sort(xy[on, 0]))
    for speeds_marked in marked[1:]:  # the same speeds on every curve, each one of the grid's
        np.testing.assert_array_equal(speeds_marked, marked[0])
    assert np.isin(marked[0], speeds).all()
