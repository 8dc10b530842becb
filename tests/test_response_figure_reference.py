"""Response figures draw limits and amplitudes in the units their axes state.

Hand-built inputs (no model), the figures' artists checked against references derived here:

* lengths are given in metres and drawn in millimetres (1 m = 1000 mm); an auxiliary-bearing
  gap is the radial clearance, drawn at its own value (not the diametral 2×gap);
* the orbit of (v, w) = (a, −i b), a > b > 0 real, is the ellipse v = a cos φ, w = b sin φ:
  major semi-axis a, which is the orbit size the note states;
* an actuator's excursion is its static offset plus its orbit amplitude (the orbit is centred
  on the static position), its load the static force plus the dynamic amplitude;
* the strength figure's critical point is the station of the smallest safety factor.

Values compared to rel 1e-12 (unit conversions and sums, no discretisation). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from flexshaft.plot.driveline import actuator_figure, imbalance_response_figure, safety_factor_figure  # noqa: E402
from flexshaft.plot.response import bode_figure, orbit_figure  # noqa: E402

REL = 1e-12
GAP = 0.25e-3  # radial gap [m] = 0.25 mm


def _labelled(ax, start: str):
    return [ln for ln in ax.get_lines() if str(ln.get_label()).startswith(start)]


def test_bode_and_imbalance_response_draw_the_radial_gap_in_mm():
    speeds = np.linspace(100.0, 6000.0, 5)
    z = np.full(5, 0.1e-3 + 0.0j)  # 0.1 mm
    amp = bode_figure(speeds, {"disk": z}, gap=GAP).axes[0]
    (gap,) = _labelled(amp, "auxiliary-bearing gap")
    np.testing.assert_allclose(gap.get_ydata(), [0.25, 0.25], rtol=REL)
    ax = imbalance_response_figure(speeds, {"disk": z}, gap=GAP).axes[0]
    (gap,) = _labelled(ax, "auxiliary-bearing gap")
    np.testing.assert_allclose(gap.get_ydata(), [0.25, 0.25], rtol=REL)
    np.testing.assert_allclose(_labelled(ax, "disk")[0].get_ydata(), 0.1, rtol=REL)


def test_orbit_note_states_the_major_semi_axis():
    a, b = 0.2e-3, 0.05e-3  # [m]: semi-axes 0.2 mm (v) and 0.05 mm (w)
    ax = orbit_figure({"amb": (a, -1j * b)}, {"amb": GAP}).axes[0]
    (note,) = [t.get_text() for t in ax.texts if t.get_text().startswith("max")]
    assert note.splitlines()[0] == "max 0.2 mm"
    assert note.splitlines()[1] == "80 % of gap 0.25 mm"  # 0.2 / 0.25


def test_actuator_figure_draws_static_plus_dynamic_against_the_limits():
    speeds = np.linspace(0.0, 4800.0, 4)
    orbit = np.array([0.0, 0.01e-3, 0.03e-3, 0.02e-3])  # [m]
    force = np.array([0.0, 5.0, 20.0, 12.0])  # [N]
    offset, static = 0.04e-3, 30.0  # [m], [N]
    fig = actuator_figure(
        speeds,
        {"amb_1": orbit},
        {"amb_1": force},
        gap=GAP,
        force_capacity=150.0,
        static_offset={"amb_1": offset},
        static_force={"amb_1": static},
    )
    top, bottom = fig.axes[:2]
    (excursion,) = _labelled(top, "amb_1: static + spin-up")
    np.testing.assert_allclose(excursion.get_ydata(), (orbit + offset) * 1e3, rtol=REL)
    (load,) = _labelled(bottom, "amb_1: static + spin-up")
    np.testing.assert_allclose(load.get_ydata(), force + static, rtol=REL)
    (gap,) = _labelled(top, "gap")
    np.testing.assert_allclose(gap.get_ydata(), [0.25, 0.25], rtol=REL)
    (capacity,) = _labelled(bottom, "force capacity")
    np.testing.assert_allclose(capacity.get_ydata(), [150.0, 150.0], rtol=REL)


def test_strength_figure_marks_the_smallest_safety_factor():
    x = np.linspace(0.0, 6.0, 7)
    r = np.array([9.0, 6.0, 3.0, 2.0, 4.0, 8.0, 12.0])  # smallest, 2.0, at x = 3 m
    ax = safety_factor_figure(x, r).axes[0]
    (point,) = _labelled(ax, "critical point")
    assert (point.get_xdata()[0], point.get_ydata()[0]) == pytest.approx((3.0, 2.0), rel=REL)
    (failure,) = _labelled(ax, "failure")
    np.testing.assert_allclose(failure.get_ydata(), [1.0, 1.0], rtol=REL)  # Tsai-Wu R = 1 fails


def test_strength_figure_draws_the_required_factor_in_view():
    """The verdict's limit beside failure: R ≥ 2.25 drawn at 2.25 and kept in view when every
    drawn factor lies below it (the axis reaches past the larger of the two)."""
    x = np.linspace(0.0, 6.0, 7)
    r = np.array([1.9, 1.8, 1.7, 1.6, 1.7, 1.8, 1.9])
    ax = safety_factor_figure(x, r, required=2.25).axes[0]
    (required,) = _labelled(ax, "required (R ≥ 2.25)")
    np.testing.assert_allclose(required.get_ydata(), [2.25, 2.25], rtol=REL)
    assert ax.get_ylim()[1] > 2.25
