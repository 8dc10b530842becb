"""What a Monte-Carlo run reports of each sample's draws, on the two-bay rotor of
tests/test_montecarlo_bounds.py.

* docs/transient.md ("Results"): ``flexshaft montecarlo --grade G`` (which passes no placement)
  draws each bay's eccentricity over the grade's tolerance disk, a random angle *and position*:
  the default placement is uniform along the bay, so positions are fractions in [0, 1), not all
  the mid-bay 0.5.
* The module docstring of :mod:`flexshaft.montecarlo.steady`: sample k draws from
  ``default_rng([seed, k])`` alone; the reported ``eccentricity_bay{b}``, ``angle_bay{b}`` and
  ``position_bay{b}`` are bay b's draws of that sample
  (:func:`flexshaft.montecarlo.samples.draw_imbalance`, the sampler's documented order), and with
  a disk distribution of radius e_per (ISO 21940-11 §5.3, e_per = G/Ω_max) each lies in
  [0, e_per]. Two bays' continuous draws differ (equal with probability 0).

Tolerance: the dataset stores the draws as float64 (exact equality up to 1e-15 relative).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_montecarlo_bounds import SMALL

from flexshaft.design import loads_design
from flexshaft.montecarlo.samples import EccentricityDistribution, draw_imbalance
from flexshaft.montecarlo.steady import run_montecarlo

SEED = 7


@pytest.fixture(scope="module")
def run():
    design = loads_design(SMALL)
    return design, run_montecarlo(design, 1, seed=SEED, grade_mm_s=6.3, n_speeds=2, strength=False)


def test_the_default_placement_is_uniform_along_the_bay(run):
    _, result = run
    ds = result.dataset
    assert ds.attrs["placement"] == "uniform"
    positions = np.array([ds[f"position_bay{b}"].values for b in (1, 2)])
    assert np.all((positions >= 0.0) & (positions < 1.0))
    assert not np.allclose(positions, 0.5)


def test_each_bay_reports_its_own_draws(run):
    design, result = run
    ds = result.dataset
    dist = EccentricityDistribution.from_grade(6.3, design.operating.speed_limits[1])
    for k in range(1):
        draws = draw_imbalance([k], 2, dist, "uniform", SEED)
        for b in range(2):
            assert ds[f"eccentricity_bay{b + 1}"].values[k] == pytest.approx(draws.eccentricity[0, b], rel=1e-15)
            assert ds[f"angle_bay{b + 1}"].values[k] == pytest.approx(draws.angle[0, b], rel=1e-15)
            assert ds[f"position_bay{b + 1}"].values[k] == pytest.approx(draws.position[0, b], rel=1e-15)
            assert 0.0 <= ds[f"eccentricity_bay{b + 1}"].values[k] <= dist.scale
        assert ds["eccentricity_bay1"].values[k] != ds["eccentricity_bay2"].values[k]


def test_the_scale_is_recorded_in_metres(run):
    """The dataset's ``eccentricity_scale_m`` is e_per = G/Ω_max in metres (ISO 21940-11 §5.3):
    G 6.3 mm/s at 6000 rev/min (no speed range: Ω_max = 6000 · 2π/60 = 628.32 rad/s) is
    6.3e-3 / 628.32 = 10.03 µm. Written for h41b-mc-scale-attribute-in-mm."""
    _, result = run
    assert result.dataset.attrs["eccentricity_scale_m"] == pytest.approx(6.3e-3 / (6000.0 * np.pi / 30.0), rel=1e-12)
