"""The Campbell diagram draws the numbers an engineer reads off it where they belong.

A hand-built diagram (two modes of constant frequency, no model: the figure function takes plain
arrays) is drawn and its artists' data checked against the definitions, derived here:

* an excitation of order k of a shaft turning at n [rpm] has the frequency f = k·n/60 [Hz]
  (n/60 revolutions per second); the 1× ray is f = n/60, the 2× ray f = 2n/60;
* a critical speed n_c [rpm] lies on the 1× ray, at (n_c, n_c/60);
* a main-rotor excitation geared to the shaft is proportional to the shaft speed and equals its
  given frequency f_op at the operating speed n_op: f = f_op·n/n_op;
* an excitation given as an order r of the shaft speed is the ray f = r·n/60;
* the colour of a point is its log decrement δ (the colour bar's quantity), not ζ = δ/2π;
* forward whirl is drawn solid, backward dashed (the figure's documented key).

Every comparison is exact up to floating-point rounding (rel 1e-12): the figure draws these
straight lines from their two end points, no discretisation is involved. Agg, nothing written.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from flexshaft.plot.campbell import campbell_figure  # noqa: E402

SPEEDS = np.linspace(0.0, 6000.0, 13)  # [rpm]
F_FORWARD, F_BACKWARD = 70.0, 40.0  # the two modes [Hz]
OPERATING = 4800.0  # [rpm]
CRITICALS = [2400.0]  # [rpm]: where 1× (f = n/60) meets the backward mode at 40 Hz
VERDICT = [(4200.0, 7.5)]  # (speed [rpm], amplification factor)
DELTA_FORWARD, DELTA_BACKWARD = 0.3, -0.2  # log decrements, inside the colour range (-0.5, 1.0)
REL = 1e-12


@pytest.fixture(scope="module")
def ax():
    n = SPEEDS.size
    freqs = np.column_stack([np.full(n, F_FORWARD), np.full(n, F_BACKWARD)])
    whirl = np.array([["forward", "backward"]] * n)
    delta = np.column_stack([np.full(n, DELTA_FORWARD), np.full(n, DELTA_BACKWARD)])
    fig = campbell_figure(
        SPEEDS,
        freqs,
        whirl,
        critical_speeds_rpm=CRITICALS,
        operating_rpm=OPERATING,
        harmonics=(1, 2),
        log_decrement=delta,
        main_rotor_hz={"4/rev": 17.6},
        excitation_orders={"tail rotor 4/rev": 1.17},
        response_criticals=VERDICT,
    )
    return fig.axes[0]


def _line(ax, label: str):
    (line,) = [ln for ln in ax.get_lines() if ln.get_label() == label]
    return np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)


def test_shaft_excitation_rays_are_k_n_over_60(ax):
    for k in (1, 2):
        x, y = _line(ax, f"{k}× shaft speed")
        np.testing.assert_allclose(x, [SPEEDS[0], SPEEDS[-1]], rtol=REL)
        np.testing.assert_allclose(y, k * x / 60.0, rtol=REL)


def test_critical_speed_markers_lie_on_the_1x_ray(ax):
    x, y = _line(ax, "critical speed")
    np.testing.assert_allclose(x, CRITICALS, rtol=REL)
    np.testing.assert_allclose(y, np.asarray(CRITICALS) / 60.0, rtol=REL)


def test_the_verdicts_critical_speed_at_its_speed_with_its_speed_and_af(ax):
    x, y = _line(ax, "critical speed of the verdict (unbalance-response peak)")
    np.testing.assert_allclose(x, [VERDICT[0][0]], rtol=REL)
    np.testing.assert_allclose(y, [VERDICT[0][0] / 60.0], rtol=REL)
    assert "4200 rpm, AF 7.5" in [t.get_text() for t in ax.texts]


def test_geared_excitations_are_rays_of_their_slope(ax):
    x, y = _line(ax, "main rotor 4/rev")
    np.testing.assert_allclose(y, 17.6 * x / OPERATING, rtol=REL)  # through (n_op, f_op)
    x, y = _line(ax, "tail rotor 4/rev (1.17×)")
    np.testing.assert_allclose(y, 1.17 * x / 60.0, rtol=REL)


def test_operating_speed_line_at_the_operating_speed(ax):
    (line,) = [ln for ln in ax.get_lines() if str(ln.get_label()).startswith("operating speed")]
    np.testing.assert_allclose(line.get_xdata(), [OPERATING, OPERATING], rtol=REL)


def test_points_coloured_by_their_log_decrement_and_whirl_drawn_by_its_key(ax):
    colours = {}
    for coll in ax.collections:
        f = coll.get_offsets()[:, 1]
        for fi, ci in zip(f, np.asarray(coll.get_array())):
            colours.setdefault(float(fi), set()).add(float(ci))
    assert colours == {F_FORWARD: {DELTA_FORWARD}, F_BACKWARD: {DELTA_BACKWARD}}  # passed through unchanged
    styles = {}
    for ln in ax.get_lines():
        y = np.asarray(ln.get_ydata(), float)
        if y.size > 2 and np.all(y == y[0]):
            styles.setdefault(float(y[0]), set()).add(ln.get_linestyle())
    assert styles == {F_FORWARD: {"-"}, F_BACKWARD: {"--"}}
