"""The loops' grid stays inside the range asked for and samples the poles of the speed asked for.

* Range (:func:`~flexshaft.analyses.loop_grid.frequency_grid`): a lightly damped pole just below
  the range's top, ω_n = 62.5 rad/s, ζ = 0.02, on the 1-10 Hz range (top 20π = 62.83 rad/s), has
  its points ω_d and ω_d ± ζω_n/2 = ω_d ± 0.625 rad/s at ω_d = 62.5√(1 − 4e-4) = 62.4875 rad/s;
  ω_d + 0.625 = 63.11 rad/s is above the range and left out (the margins are read on the range
  only; a second pole above the range, 100 rad/s, keeps the natural frequencies out). By hand;
  rel 1e-12 covers the rounding of a product and a square root.
* Speed (:func:`~flexshaft.analyses.bearing_loops.bearing_loops`): a rigid rotor (1 m steel tube
  1e4 times stiffer than steel, disk m = 20 kg, I_d = 0.5 kg m², I_p = 1 kg m² at mid-span) on
  two PD magnetic bearings (k = 1e5 N/m, c = 20 N s/m) at x = 0.1 and 0.9 m (a = ±0.4 m about
  the centre) whose operating speed is 6000 rpm, assessed at rest (speed = 0). At rest the
  planes and the translation and tilt decouple (bearings symmetric about the centre):

      m s² + 2c s + 2k = 0,        I_t s² + 2c a² s + 2k a² = 0,

  m and I_t the tube's and disk's mass and diametral inertia about the centre (the tube's
  I_t = ρ A L³/12 + ρ I L, its rotary inertia). Both roots are lightly damped (ζ ≈ 0.007 and
  0.012), so the grid has a point at each ω_d = Im s. At 6000 rpm the gyroscopic coupling
  (Ω I_p/I_t ≈ 270 rad/s) splits the tilt roots far from the rest value: a grid sampled at the
  operating speed's poles would miss it. The FE rotor's rigid-body roots differ from the
  closed form by at most 1e-6 (tests/test_loop_robustness.py; 3e-8 measured here): rel 1e-5.

CPU: the model and its loops on a 40-point grid, about 0.2 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_amb import HALF_SPAN, I_T, MASS, rotor_text

from flexshaft.analyses.bearing_loops import bearing_loops
from flexshaft.analyses.loop_grid import frequency_grid
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

K_BEARING, C_BEARING = 1.0e5, 20.0
M_ROTOR, A_HALF = MASS, HALF_SPAN  # the tube's and disk's mass; the bearings at 0.5 ∓ 0.4 m


def _text() -> str:
    """test_amb's rigid rotor (the same tube, disk and bearing stations) on PD bearings, whose
    operating speed is 6000 rpm."""
    return rotor_text(f"kp = {K_BEARING}\nkd = {C_BEARING}", speed_rpm=6000.0)


def test_a_pole_point_above_the_range_is_left_out():
    natural, zeta = 62.5, 0.02
    damped = natural * np.sqrt(1 - zeta * zeta)
    log = 2 * np.pi * np.array([1.0, np.sqrt(10.0), 10.0])
    near_top = natural * complex(-zeta, np.sqrt(1 - zeta * zeta))
    above = 100.0 * complex(-0.01, np.sqrt(1 - 1e-4))  # above the range: no natural frequency stands in
    grid = frequency_grid(None, (1.0, 10.0), 3, np.array([near_top, above]))
    np.testing.assert_allclose(grid, np.sort(np.concatenate([log, [damped - 0.625, damped]])), rtol=1e-12)
    assert grid.max() <= 20 * np.pi


def test_at_rest_the_grid_samples_the_rest_roots_not_the_operating_speeds():
    model = build_model(loads_design(_text()))
    assert model.speed == pytest.approx(6000 * np.pi / 30, rel=1e-12)
    loops = bearing_loops(model, speed=0.0, n_points=40, frequency_range=(1.0, 100.0))
    grid = 2 * np.pi * loops[0].frequencies
    for inertia, lever2 in ((M_ROTOR, 1.0), (I_T, A_HALF**2)):
        roots = np.roots([inertia, 2 * C_BEARING * lever2, 2 * K_BEARING * lever2])
        damped = float(np.max(roots.imag))
        assert np.min(np.abs(grid / damped - 1)) < 1e-5, damped
