"""The Monte-Carlo ply check is the worst instant of a revolution, whatever the angle at which
the unbalance sits.

References:

* docs/transient.md, Monte-Carlo outputs per sample: the "ply Tsai-Wu safety factor at the
  operating speed (static loads + torque + the sample's imbalance response,
  `shaft_safety_factor`, 36 phases)": the factor is the smallest over 36 instants of one
  revolution, not the one at t = 0.
* Time shift (derived here): the steady response is linear in the unbalance, so turning a bay's
  unbalance by ψ multiplies its synchronous amplitude by e^{iψ}, i.e. shifts the motion by
  ψ/Ω in time. The worst instant of a revolution is therefore the same for every ψ. Two samples
  of one bay with the same eccentricity at the same (mid-bay) station differ only by their angles,
  so over a whole revolution their safety factors are equal.
* The case: the [0] ply tube of tests/test_montecarlo_ply_check_reference.py (one bay, clamped
  at x = 0, pinned at a stop at its end, 3000 rpm) with a static 500 N side force at mid-span
  and a fixed 2 mm eccentricity: the static bending curvature κ_s and the rotating imbalance
  curvature κ_d are of one order, so the bending strain r|κ_s + κ_d(t)| swings between
  ≈ r(|κ_s| − |κ_d|) and r(|κ_s| + |κ_d|) over a revolution, and a factor read at one instant
  would depend on ψ by tens of per cent (measured: 39 to 68 over six angles).

Tolerance 2e-3 (derived): 36 phases sample the revolution every δ = 10°, so the worst sampled
instant lies within δ/2 of the true worst. With a circular whirl (isotropic supports) the bending
strain there, √(a² + b² + 2ab cos(δ/2)) with a = |κ_s|, b = |κ_d|, is below the peak a + b by a
relative ab(δ/2)²/(2(a + b)²) ≤ (δ/2)²/8 = 9.5e-4; the factor varies at most like 1/strain, so
the samples agree to ~1e-3 (measured 1.6e-4). Six samples on a 2-speed grid: ~0.07 s after the
suite's first Monte-Carlo run has paid the lazy imports.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_montecarlo_ply_check_reference import unidirectional_tube_data
from test_shaft_strength_fields_reference import X0, X1

from flexshaft.design import design_from_dict
from flexshaft.montecarlo import run_montecarlo
from flexshaft.montecarlo.samples import EccentricityDistribution

SIDE_FORCE = 500.0  # N, static, at mid-span
ECCENTRICITY = 2e-3  # m, every sample


@pytest.fixture(scope="module")
def side_loaded_tube():
    """The [0] ply tube of tests/test_montecarlo_ply_check_reference.py (clamped at x = 0,
    pinned at a contact stop at its end: one bay), pushed sideways at mid-span."""
    data = unidirectional_tube_data()
    data["name"] = "side-loaded [0] tube"
    side = {"name": "side", "on": "shaft", "x": (X0 + X1) / 2, "force": [0.0, SIDE_FORCE, 0.0]}
    data["loads"]["point"] = [side]
    return design_from_dict(data)


def test_the_ply_factor_does_not_depend_on_the_unbalance_angle(side_loaded_tube):
    """Six samples, one eccentricity, angles spread over the circle: one safety factor."""
    fixed = EccentricityDistribution("fixed", ECCENTRICITY)
    ds = run_montecarlo(side_loaded_tube, 6, distribution=fixed, placement="mid_bay", n_speeds=2).dataset
    angles = ds["angle_bay1"].values
    assert np.ptp(np.cos(angles)) > 1.0, angles  # the angles do differ (else the test says nothing)
    np.testing.assert_array_equal(ds["eccentricity_bay1"].values, ECCENTRICITY)
    factors = ds["safety_factor"].values
    assert np.all(np.isfinite(factors)), factors
    np.testing.assert_allclose(factors, factors.min(), rtol=2e-3)
