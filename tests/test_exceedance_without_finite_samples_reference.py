"""An exceedance counted over no sample: NaN statistics and "no samples", not an error.

References (the documented rules of the code's docstrings, montecarlo/confidence.py and
montecarlo/steady.py):

* ``Exceedance.probability``: "The estimate k/N [-] (NaN without samples)";
* ``Exceedance.upper_bound``: "Exact one-sided upper confidence bound [-] ... NaN without
  samples";
* ``Exceedance.describe``: ``"no samples"`` when there is none;
* ``MonteCarloResult._count_exceeding`` counts "of the samples with a finite value at every
  judged bearing", so a study whose every sample is non-finite at a judged bearing (a NaN from
  a failed solve) counts 0 of 0 — the JSON of ``flexshaft montecarlo --json`` then writes
  that count's ``to_dict()``.

Four hand-made samples at one bearing, every excursion NaN. No arithmetic: NaN is checked as
NaN, the counts as integers.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.montecarlo import Exceedance
from flexshaft.montecarlo.steady import MonteCarloResult
from flexshaft.verdict.gather import ActuatorLimits

xr = pytest.importorskip("xarray")


def test_no_sample_gives_nan_statistics_not_an_error():
    events = Exceedance(0, 0)
    assert math.isnan(events.probability)
    assert math.isnan(events.standard_error)
    assert math.isnan(events.upper_bound())
    assert math.isnan(events.upper_bound(0.99))
    assert events.describe() == "no samples"


def test_study_without_a_finite_sample_writes_nan_bound():
    nan = np.full(4, np.nan)
    data = {"actuator_excursion_a": ("sample", nan), "actuator_load_a": ("sample", nan)}
    result = MonteCarloResult(
        xr.Dataset(data, coords={"sample": np.arange(4)}), {"a": ActuatorLimits(gap=0.5e-3, force_capacity=1000.0)}
    )
    for events in (result.gap_events, result.force_events):
        assert (events.events, events.samples) == (0, 0)
        written = events.to_dict()
        assert (written["events"], written["samples"]) == (0, 0)
        for key in ("probability", "standard_error", "upper_bound"):
            assert math.isnan(written[key]), key
        assert events.describe() == "no samples"
