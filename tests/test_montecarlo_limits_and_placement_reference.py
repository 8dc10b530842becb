"""Monte-Carlo bookkeeping (:mod:`flexshaft.montecarlo.steady`): a sample exactly at its limit
does not exceed it, and the placement asked for is the one sampled.

References, counted by hand:

* :meth:`MonteCarloResult.exceedance` is documented as P(output > limit), strictly: of the
  finite samples [1, 2, 3, 3, nan] against the limit 3, none lies above it (p = 0), and against
  2, two of four (p = 0.5, standard error √(0.5 · 0.5/4) = 0.25).
* :attr:`MonteCarloResult.gap_events` and :attr:`~MonteCarloResult.force_events` judge each
  sample as the verdict's actuator checks judge the design, and those are "at most" checks
  (:mod:`flexshaft.verdict.checks`: the margin limit − value, which passes at 0): a bearing whose
  static offset + peak orbit equals its gap, or whose load equals its capacity, passes. Two
  bearings, three samples: sample 0 at both limits exactly (no event), sample 1 above the gap of
  "a" only, sample 2 above the capacity of "b" only: one gap event and one force event of 3.
* :func:`run_montecarlo`'s ``placement="mid_bay"`` puts each bay's unbalance at its middle
  (docs/transient.md: "at mid-bay or uniformly along the bay (`placement`)"; the module
  docstring: "at axial position x_b, mid-bay or uniform along the bay"): every reported
  ``position_bay{b}`` is the fraction 0.5 exactly, and the run says ``placement = "mid_bay"``.
  Run on the two-bay rotor of tests/test_montecarlo_bounds.py with two samples on a 2-speed
  grid and no strength evaluation (as tests/test_montecarlo_draws_reported_reference.py, for
  CPU).

Exact integer counts and fractions: no tolerance.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_montecarlo_bounds import SMALL  # the two-bay rotor with a magnet between its bearings

from flexshaft.design import loads_design
from flexshaft.montecarlo.steady import MonteCarloResult, run_montecarlo
from flexshaft.verdict.gather import ActuatorLimits

xr = pytest.importorskip("xarray")


def test_a_sample_at_the_limit_is_not_above_it():
    ds = xr.Dataset({"peak": ("sample", [1.0, 2.0, 3.0, 3.0, np.nan])})
    result = MonteCarloResult(ds, {})
    assert result.exceedance("peak", 3.0) == (0.0, 0.0)
    p, se = result.exceedance("peak", 2.0)
    assert p == 0.5 and se == pytest.approx(0.25, rel=1e-15)


def test_a_bearing_at_its_gap_or_capacity_passes():
    ds = xr.Dataset(
        {
            "actuator_excursion_a": ("sample", [4e-4, 5e-4, 4e-4]),
            "actuator_excursion_b": ("sample", [2e-4, 1e-4, 1e-4]),
            "actuator_load_a": ("sample", [300.0, 100.0, 100.0]),
            "actuator_load_b": ("sample", [900.0, 100.0, 901.0]),
        }
    )
    limits = {"a": ActuatorLimits(4e-4, 300.0), "b": ActuatorLimits(2e-4, 900.0)}
    result = MonteCarloResult(ds, limits)
    gap, force = result.gap_events, result.force_events
    assert (gap.events, gap.samples) == (1, 3)
    assert (force.events, force.samples) == (1, 3)


def test_a_mid_bay_run_places_every_unbalance_at_mid_bay():
    result = run_montecarlo(
        loads_design(SMALL), 2, seed=3, grade_mm_s=6.3, placement="mid_bay", n_speeds=2, strength=False
    )
    ds = result.dataset
    assert ds.attrs["placement"] == "mid_bay"
    for b in (1, 2):
        assert list(ds[f"position_bay{b}"].values) == [0.5, 0.5]
