"""Monte-Carlo exceedance bookkeeping (:mod:`flexshaft.montecarlo.steady`) counted by hand.

* ``exceedance(name, limit)`` is the fraction of finite samples *above* the limit and its
  binomial standard error √(p(1 − p)/N): of [1, 2, 3, 4, 5, nan] above 3.5, 2 of 5, p = 0.4,
  se = √(0.4 · 0.6/5).
* The governing gap and force capacity of several active bearings are the smallest (the
  tightest limit is the first exceeded).
* A gap passed to :func:`run_montecarlo` replaces each bearing's design gap in the limits the
  exceedances use (its docstring); the design's force capacity stays.

The last one runs the two-bay rotor of tests/test_montecarlo_bounds.py with one sample on a
2-speed grid and no strength evaluation (the limits do not depend on the samples; CPU budget).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_montecarlo_bounds import SMALL  # the two-bay rotor with a magnet between its bearings

from flexshaft.design import loads_design
from flexshaft.montecarlo.steady import MonteCarloResult, run_montecarlo
from flexshaft.verdict.gather import ActuatorLimits

xr = pytest.importorskip("xarray")


def test_exceedance_is_the_fraction_above_the_limit():
    ds = xr.Dataset({"peak": ("sample", [1.0, 2.0, 3.0, 4.0, 5.0, np.nan])})
    p, se = MonteCarloResult(ds, {}).exceedance("peak", 3.5)
    assert p == pytest.approx(0.4, rel=1e-15)
    assert se == pytest.approx(math.sqrt(0.4 * 0.6 / 5), rel=1e-12)


def test_the_tightest_limit_governs():
    ds = xr.Dataset({"peak": ("sample", [1.0])})
    limits = {"a": ActuatorLimits(5e-4, 300.0), "b": ActuatorLimits(2e-4, 900.0), "c": ActuatorLimits(None, None)}
    result = MonteCarloResult(ds, limits)
    assert result.gap == 2e-4
    assert result.force_limit == 300.0


def test_a_gap_given_to_the_run_replaces_the_design_gap():
    result = run_montecarlo(loads_design(SMALL), 1, grade_mm_s=2.5, gap=5e-4, n_speeds=2, strength=False)
    assert result.limits["amb"].gap == 5e-4
    assert result.limits["amb"].force_capacity == 1.0e4
