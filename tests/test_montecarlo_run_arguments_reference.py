"""What :func:`flexshaft.montecarlo.steady.run_montecarlo` refuses before it samples, and the
bays its study declares.

References, from the documentation and counted by hand:

* **Limits.** A gap or force limit is a positive length or force ("gap, force_limit: Actuator
  radial gap [m] and force capacity [N]"; the CLI's ``--gap-mm`` and ``--force-limit``): 0 would
  make every sample an exceedance, so 0 is refused as a negative value is.
* **Speeds.** A spin-up of one speed has no peak to find (docs/transient.md "Speeds": uniform
  speeds to the operating speed, refined around every local peak): ``n_speeds`` < 2 refused.
* **Seed.** numpy's generators take any non-negative integer and the run records the seed as
  text because netCDF3 holds at most 32-bit integers (``MAX_SEED = 2**63 − 1``, the comment
  beside it and in ``run_montecarlo``): a seed of 2³¹ is a valid seed, so a run with it and a
  zero gap is refused for the gap, not the seed; 2⁶³ is beyond the largest seed and refused.
* **Bays.** docs/transient.md "Unbalance per bay": each bay is the span between consecutive
  bearings; the two-bay rotor of tests/test_montecarlo_bounds.py (bearings at 0, 1 and 2 m)
  has two, so the study declares ``eccentricity_bay1``, ``eccentricity_bay2`` and no third.

Exact refusals and names: no tolerance. Every refusal is raised before any response is solved.
"""

from __future__ import annotations

import pytest
from test_montecarlo_bounds import SMALL

from flexshaft.analyses.guards import RefusedInputError
from flexshaft.design import loads_design
from flexshaft.montecarlo.samples import EccentricityDistribution
from flexshaft.montecarlo.steady import MonteCarloSampler, montecarlo_study, run_montecarlo


@pytest.fixture(scope="module")
def design():
    return loads_design(SMALL)


@pytest.mark.parametrize("key", ["gap", "force_limit"])
def test_a_zero_limit_is_refused(design, key):
    with pytest.raises(ValueError, match=f"{key} must be > 0"):
        run_montecarlo(design, 2, grade_mm_s=6.3, n_speeds=2, strength=False, **{key: 0.0})


def test_a_single_speed_is_refused(design):
    with pytest.raises(ValueError, match="n_speeds"):
        run_montecarlo(design, 2, grade_mm_s=6.3, n_speeds=1, strength=False)


def test_a_64_bit_seed_is_a_seed(design):
    with pytest.raises(ValueError, match="gap must be > 0"):
        run_montecarlo(design, 2, seed=2**31, grade_mm_s=6.3, n_speeds=2, strength=False, gap=0.0)
    with pytest.raises(ValueError, match="gap must be > 0"):
        run_montecarlo(design, 2, seed=2**63 - 1, grade_mm_s=6.3, n_speeds=2, strength=False, gap=0.0)
    with pytest.raises(RefusedInputError, match="seed"):
        run_montecarlo(design, 2, seed=2**63, grade_mm_s=6.3, n_speeds=2, strength=False)


def test_the_study_declares_one_output_set_per_bay(design):
    sampler = MonteCarloSampler(0, EccentricityDistribution("fixed", 1e-5), n_speeds=2, strength=False)
    names = {output.name for output in montecarlo_study(design, 2, sampler).outputs}
    for what in ("eccentricity", "angle", "position"):
        assert {n for n in names if n.startswith(f"{what}_bay")} == {f"{what}_bay1", f"{what}_bay2"}
