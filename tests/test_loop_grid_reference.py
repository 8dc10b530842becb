"""The bearing loops' frequency grid (:mod:`flexshaft.analyses.loop_grid`) on hand-built cases.

* Given poles: the grid over 1-10 Hz is the logarithmic grid of 2π-20π rad/s plus, for the
  lightly damped pole s = ω_n(−ζ + i√(1 − ζ²)) with ω_n = 40 rad/s, ζ = 0.01 (given twice, as
  the two lateral planes give it), the points ω_d and ω_d ± ζω_n/2 = ω_d ± 0.2 rad/s (its top
  and half-power half width); nothing for a well-damped pole (ζ = 0.5) nor for a pole above
  the range (which also keeps the undamped natural frequencies out: none lies above it).
* Above the highest pole, the undamped natural frequencies of (K + K_a, M) stand in, with
  ζ = 1e-3: on a two-DOF model K = diag(100, 900), K_a = diag(300, 0), M = I they are
  √400 = 20 and √900 = 30 rad/s (by hand), giving the points ω_n and ω_n(1 ± 0.5e-3); without
  K_a the first would be 10 rad/s, below the 1 Hz range. Both ways of computing them: read off
  the model's whole shift-inverted spectrum (the modal bases', up to 400 free DOFs) and
  LAPACK's subset solve of (K + K_a, M) (above).

The expected grids are written from these closed forms; they agree to the rounding of the
products and square roots (rel 1e-12 is a wide margin over 1e-15). CPU: a few milliseconds.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
import scipy.sparse as sp

from flexshaft.analyses import loop_grid
from flexshaft.analyses.loop_grid import AROUND, frequency_grid, natural_frequencies

LOG = 2 * np.pi * np.array([1.0, np.sqrt(10.0), 10.0])  # geomspace(2π, 20π, 3) [rad/s]


def _pole(natural: float, zeta: float) -> complex:
    return natural * complex(-zeta, np.sqrt(1.0 - zeta * zeta))


class _Model(SimpleNamespace):
    """A stand-in model, hashable by identity like a Model (the whole-spectrum cache's key)."""

    __hash__ = object.__hash__


def _two_dof_model():
    return _Model(
        dofs=SimpleNamespace(free=np.arange(2)),
        K=sp.csr_matrix(np.diag([100.0, 900.0])),
        Kp=sp.csr_matrix(np.diag([300.0, 0.0])),
        M=sp.csr_matrix(np.eye(2)),
    )


def test_a_lightly_damped_pole_gets_its_top_and_half_width():
    light = _pole(40.0, 0.01)
    poles = [light, light, _pole(30.0, 0.5), _pole(100.0, 0.01), np.conj(light)]
    damped = 40.0 * np.sqrt(1.0 - 1e-4)
    expected = np.sort(np.concatenate([LOG, [damped - 0.2, damped, damped + 0.2]]))
    grid = frequency_grid(None, (1.0, 10.0), 3, np.array(poles))
    np.testing.assert_allclose(grid, expected, rtol=1e-12)
    top_only = frequency_grid(None, (1.0, 10.0), 3, np.array(poles), around=AROUND[1])
    np.testing.assert_allclose(top_only, np.sort(np.concatenate([LOG, [damped]])), rtol=1e-12)


@pytest.mark.parametrize("whole_up_to", [400, 0], ids=["whole spectrum", "subset solve"])
def test_natural_frequencies_include_the_bearing_stiffness(monkeypatch, whole_up_to):
    monkeypatch.setattr(loop_grid, "WHOLE_DENSE_BASIS_UP_TO", whole_up_to)
    model = _two_dof_model()
    np.testing.assert_allclose(natural_frequencies(model, 15.0, 35.0), [20.0, 30.0], rtol=1e-12)
    np.testing.assert_allclose(natural_frequencies(model, 25.0, 35.0), [30.0], rtol=1e-12)


def test_above_the_poles_the_natural_frequencies_stand_in_with_a_nominal_width():
    grid = frequency_grid(_two_dof_model(), (1.0, 10.0), 3, np.zeros(0))
    peaks = [n * (1.0 + k * 1e-3) for n in (20.0, 30.0) for k in (-0.5, 0.0, 0.5)]
    np.testing.assert_allclose(grid, np.sort(np.concatenate([LOG, peaks])), rtol=1e-12)


@pytest.mark.parametrize("n_points", [2, 50])
def test_the_coarse_grid_spans_the_range_in_rad_s(n_points):
    grid = frequency_grid(None, (1.0, 10.0), n_points, np.array([_pole(100.0, 0.01)]))
    np.testing.assert_allclose(grid, np.geomspace(2 * np.pi, 20 * np.pi, n_points), rtol=1e-12)


def test_only_the_natural_frequencies_above_the_highest_pole_stand_in():
    """A pole given at 25 rad/s (ζ = 0.01: points ω_d and ω_d ± ζω_n/2 = ω_d ± 0.125 rad/s) is
    the top of a truncated basis's poles: of the two natural frequencies 20 and 30 rad/s (by
    hand, above) only 30 rad/s, above it, stands in; the mode at 20 rad/s is one of the poles
    given (module docstring: "above the highest pole given"). A real pole (a derivative
    filter's at −1000 rad/s, or its conjugate pair's lower half) is no peak and no top: it makes
    no grid point and keeps no natural frequency out."""
    damped = 25.0 * np.sqrt(1.0 - 1e-4)
    poles = np.array([_pole(25.0, 0.01), np.conj(_pole(25.0, 0.01)), -1000.0 + 0j])
    grid = frequency_grid(_two_dof_model(), (1.0, 10.0), 3, poles)
    above = [30.0 * (1.0 + k * 1e-3) for k in (-0.5, 0.0, 0.5)]
    expected = np.sort(np.concatenate([LOG, [damped - 0.125, damped, damped + 0.125], above]))
    np.testing.assert_allclose(grid, expected, rtol=1e-12)
