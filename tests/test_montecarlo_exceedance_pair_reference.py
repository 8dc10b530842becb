"""Monte-Carlo exceedances as the documented pair (probability, standard error), counted by hand.

References (documented rules, docs/transient.md "Monte-Carlo imbalance"):

* ``result.gap_exceedance, result.force_exceedance  # (p, standard error)``;
* "A sample exceeds the gap (the force capacity) when some active bearing's static + peak value
  passes that bearing's own limit" (``actuator_excursion_<name>``, ``actuator_load_<name>``);
* "with k exceedances in N samples the estimate is k/N", its standard error √(p(1−p)/N).

Eight hand-made samples at two bearings. Gaps 0.25 mm (``a``) and 0.5 mm (``b``): ``a`` passes
its gap in samples 1 and 4, ``b`` in 0 and 5, so k = 4, p = 1/2, √(p(1−p)/N) = √(1/32) = 0.17678.
Force capacities 800 N (``a``) and 1000 N (``b``): only sample 2 (900 N at ``a``; ``b``'s
largest, 950 N, stays under its own 1000 N), k = 1, p = 1/8, √(7/512) = 0.11693.
Float arithmetic of k/N and a square root: 1e-12 relative. The two entries of each pair differ
(0.5 against 0.177, 0.125 against 0.117), so a pair in the other order fails.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.montecarlo.steady import MonteCarloResult
from flexshaft.verdict.gather import ActuatorLimits

xr = pytest.importorskip("xarray")

EXCURSION_MM = {
    "a": [0.10, 0.30, 0.20, 0.10, 0.40, 0.05, 0.10, 0.20],
    "b": [0.60, 0.10, 0.20, 0.10, 0.30, 0.70, 0.10, 0.20],
}
LOAD_N = {
    "a": [100.0, 50.0, 900.0, 300.0, 700.0, 20.0, 10.0, 799.0],
    "b": [950.0, 10.0, 100.0, 900.0, 0.0, 500.0, 10.0, 999.0],
}
LIMITS = {
    "a": ActuatorLimits(gap=0.25e-3, force_capacity=800.0),
    "b": ActuatorLimits(gap=0.5e-3, force_capacity=1000.0),
}


def _result() -> MonteCarloResult:
    data = {}
    for name in LIMITS:
        data[f"actuator_excursion_{name}"] = ("sample", np.asarray(EXCURSION_MM[name]) * 1e-3)
        data[f"actuator_load_{name}"] = ("sample", np.asarray(LOAD_N[name]))
    return MonteCarloResult(xr.Dataset(data, coords={"sample": np.arange(8)}), LIMITS)


def test_gap_exceedance_is_the_probability_then_its_standard_error():
    p, se = _result().gap_exceedance
    assert p == pytest.approx(4 / 8, rel=1e-12)
    assert se == pytest.approx(math.sqrt(0.5 * 0.5 / 8), rel=1e-12)


def test_force_exceedance_is_the_probability_then_its_standard_error():
    p, se = _result().force_exceedance
    assert p == pytest.approx(1 / 8, rel=1e-12)
    assert se == pytest.approx(math.sqrt((1 / 8) * (7 / 8) / 8), rel=1e-12)
