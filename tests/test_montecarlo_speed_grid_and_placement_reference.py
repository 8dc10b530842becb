"""Monte-Carlo imbalance: where along its bay each unbalance sits, and the spin-up speed grid a
run is given.

References, from the documentation and derived here:

* **Placement.** docs/transient.md "Unbalance per bay": each bay's unbalance sits "at mid-bay or
  uniformly along the bay (``placement``)", its position recorded as the fraction of the bay.
  With ``"mid_bay"`` every position is exactly 1/2. With ``"uniform"`` the positions are
  U(0, 1) draws: mean 1/2, variance 1/12. For N = 800 draws (400 samples × 2 bays) the standard
  deviation of the sample mean is √(1/(12 N)) = 0.0102 and that of the sample variance
  √((μ₄ − σ⁴)/N) with μ₄ = 1/80, σ⁴ = 1/144: 0.00264; the tolerances are about five of them
  (0.05 is 4.9σ, 0.013 is 4.93σ). Kolmogorov's 0.1 % critical distance for N = 800 is
  1.95/√N = 0.069. The draws are ``default_rng([seed, k])`` (PCG64, the same on every
  machine) and the seed is fixed (7), so the test is deterministic; at seed 7 the distance is
  0.0234, |mean − ½| = 0.001 (0.1σ) and |var − 1/12| = 0.0014 (0.5σ). A sampler that put the
  "uniform" unbalances at mid-bay has variance 0 and Kolmogorov distance 1/2, 7 times the
  critical distance.
* **Speed grid.** A run's ``n_speeds`` (``run_montecarlo``, held by its ``MonteCarloSampler``)
  spin-up speeds: docs/transient.md "Speeds" says "150 uniform speeds to the operating speed,
  refined around every local peak". Two details are from the code, not the docs
  (montecarlo/samples.py ``unit_responses``): the grid starts at a slow start of 2 % of the
  operating speed (``SLOW_START`` = 0.02, resolution.py), and only *interior* local peaks are
  refined (an end point has no bracket). With ``n_speeds = 2`` the grid is {0.02 Ω, Ω} and
  has no interior point to refine, so every sample's ``shaft_peak_speed`` is one of those two
  speeds. The two-bay rotor of tests/test_montecarlo_bounds.py has a lightly damped critical
  near 598 rad/s, below its 628 rad/s operating speed: a finer grid would find the peak there,
  so a run that ignored ``n_speeds`` would report it. Exact membership to 1e-12 relative (the
  grid is Ω times 0.02 or 1).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_montecarlo_bounds import SMALL

from flexshaft.design import loads_design
from flexshaft.montecarlo.samples import EccentricityDistribution, draw_imbalance
from flexshaft.montecarlo.steady import run_montecarlo

N_SAMPLES, N_BAYS = 400, 2


def test_uniform_placement_spreads_the_unbalances_evenly_along_each_bay():
    """Positions of "uniform" placement: U(0, 1) mean, variance and Kolmogorov distance."""
    draws = draw_imbalance(range(N_SAMPLES), N_BAYS, EccentricityDistribution("fixed", 1e-5), "uniform", seed=7)
    p = draws.position.ravel()
    assert p.size == N_SAMPLES * N_BAYS
    assert np.all((p >= 0.0) & (p < 1.0))
    assert p.mean() == pytest.approx(0.5, abs=0.05)
    assert p.var() == pytest.approx(1.0 / 12.0, abs=0.013)
    ordered = np.sort(p)
    n = ordered.size
    distance = max(np.max(np.arange(1, n + 1) / n - ordered), np.max(ordered - np.arange(n) / n))
    assert distance < 1.95 / np.sqrt(n)


def test_mid_bay_placement_puts_every_unbalance_at_half_the_bay():
    """Positions of "mid_bay" placement: every one exactly 1/2 (module docstring)."""
    draws = draw_imbalance(range(20), N_BAYS, EccentricityDistribution("fixed", 1e-5), "mid_bay", seed=7)
    assert np.all(draws.position == 0.5)


def test_a_two_speed_spin_up_peaks_at_one_of_its_two_speeds():
    """``n_speeds = 2``: the grid {0.02 Ω, Ω}, nothing to refine (module docstring). Run
    through ``run_montecarlo``, so the path from its argument to the sampler's grid is covered
    too (about 0.5 s CPU for 3 samples)."""
    design = loads_design(SMALL)
    omega = design.operating.speed_rad_s
    result = run_montecarlo(design, 3, distribution=EccentricityDistribution("disk", 1e-5), n_speeds=2, strength=False)
    speeds = result.dataset["shaft_peak_speed"].values
    assert speeds.shape == (3,)
    for speed in speeds:
        assert min(abs(speed - 0.02 * omega), abs(speed - omega)) <= 1e-12 * omega
    assert np.all(result.dataset["shaft_peak"].values > 0.0)
