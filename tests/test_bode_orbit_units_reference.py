"""Bode and orbit figures: amplitudes in the unit on the axis, phase unwrapped, whirl sense kept.

Hand-built complex amplitudes (no model); references derived here:

* amplitudes given in metres are drawn in millimetres (1 m = 1000 mm), orbits under 0.1 mm in
  micrometres (1 mm = 1000 μm);
* a response z = e^{−iθ} whose lag θ grows 0°, 100°, 200°, 300° has the continuous phase −θ:
  the phase panel reads 0, −100, −200, −300° (a lag past 180° is not a lead);
* the orbit of (v, w) = (a, −i b) is v = Re(a e^{iφ}) = a cos φ, w = Re(−i b e^{iφ}) = b sin φ
  for φ from 0 to 2π (the figure's 121 points): drawn with w horizontal and v vertical, it
  starts at (0, a) and moves to w > 0, clockwise, which is forward whirl seen along +x;
* the auxiliary-bearing circle has the radial gap as its radius.

Compared to rel 1e-12 / abs 1e-12 in the drawn unit (arithmetic only). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.response import bode_figure, orbit_figure  # noqa: E402

REL = 1e-12
PHI = np.linspace(0.0, 2.0 * np.pi, 121)


def test_bode_amplitude_in_mm_and_phase_unwrapped():
    speeds = np.array([1000.0, 2000.0, 3000.0, 4000.0])  # [rpm]
    lag = np.radians([0.0, 100.0, 200.0, 300.0])
    z = 0.1e-3 * np.exp(-1j * lag)  # 0.1 mm
    amp, phase = bode_figure(speeds, {"disk": z}).axes[:2]
    np.testing.assert_allclose(amp.get_lines()[0].get_ydata(), 0.1, rtol=REL)
    np.testing.assert_allclose(phase.get_lines()[0].get_ydata(), [0.0, -100.0, -200.0, -300.0], atol=1e-9)


def test_orbit_drawn_w_across_v_up_forward_and_the_gap_circle_radial():
    a, b = 0.2e-3, 0.05e-3  # [m]
    ax = orbit_figure({"amb": (a, -1j * b)}, 0.25e-3).axes[0]
    orbit = ax.get_lines()[0]
    np.testing.assert_allclose(orbit.get_xdata(), 0.05 * np.sin(PHI), rtol=REL, atol=1e-15)  # w [mm]
    np.testing.assert_allclose(orbit.get_ydata(), 0.2 * np.cos(PHI), rtol=REL, atol=1e-15)  # v [mm]
    (circle,) = [ln for ln in ax.get_lines() if ln.get_linestyle() == "--"]
    np.testing.assert_allclose(np.hypot(circle.get_xdata(), circle.get_ydata()), 0.25, rtol=REL)


def test_small_orbit_in_micrometres():
    ax = orbit_figure({"disk": (20e-6, -5e-6j)}).axes[0]  # 0.02 mm by 0.005 mm
    orbit = ax.get_lines()[0]
    np.testing.assert_allclose(orbit.get_ydata(), 20.0 * np.cos(PHI), rtol=REL, atol=1e-12)
    assert ax.get_xlabel() == "w (lateral) [μm]" and ax.get_ylabel() == "v (vertical) [μm]"
