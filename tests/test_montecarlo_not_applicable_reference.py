"""A Monte-Carlo run says which questions it could not ask: no exceedance probability without a
limit to judge, and a ply factor that is not applicable says so.

References:

* :class:`~flexshaft.montecarlo.steady.MonteCarloResult`: ``gap_exceedance`` is "P(static
  offset + peak orbit > gap at some active bearing) and its standard error (None without a
  gap)", ``gap_events`` "None without a gap", ``force_events`` None "when no bearing has a
  limit"; the CLI's ``--json`` writes them as ``p_gap_exceeded`` / ``gap_exceedance``
  (docs/transient.md). docs/transient.md: a sample exceeds "when some active bearing's static +
  peak value passes that bearing's own limit": a design with no active bearing has no limit to
  pass, so the question is not asked (None), which is not the answer "never exceeded"
  (p = 0 ± 0 of N samples, an estimate the terminal and the figure would then print with its
  95 % upper bound). The case: the [0] ply tube of tests/test_montecarlo_ply_check_reference.py,
  supported by a contact stop only (no active bearing), with a gap and a force limit asked for
  all the same: they apply to every active bearing, of which there is none.
* The ply check is Tsai-Wu on the laminate's plies: ``safety_factor`` is "NaN when ``strength``
  is False or the shaft is not laminated" (:func:`flexshaft.montecarlo.samples.sample_outputs`),
  and ``run_montecarlo`` says why in the column's CF ``comment`` ("not applicable, NaN in every
  sample: the shaft is not laminated (Tsai-Wu), or strength was not asked for",
  ``_mark_not_applicable``). On the isotropic steel two-bay rotor of
  tests/test_montecarlo_bounds.py with the ply check asked for (the default), the factor is NaN
  in every sample and the comment is there: a bare NaN column would read as a failed
  computation.

Two samples on a 2-speed grid each (as tests/test_montecarlo_draws_reported_reference.py, for
CPU). Exact None / NaN results and text: no tolerance.
"""

from __future__ import annotations

import numpy as np
from test_montecarlo_bounds import SMALL  # the isotropic steel two-bay rotor with a magnet
from test_montecarlo_ply_check_reference import unidirectional_tube  # noqa: F401 (pytest fixture)

from flexshaft.design import loads_design
from flexshaft.montecarlo import run_montecarlo
from flexshaft.montecarlo.samples import EccentricityDistribution


def test_no_active_bearing_gives_no_exceedance_probability(unidirectional_tube):  # noqa: F811
    balanced = EccentricityDistribution("fixed", 0.0)
    result = run_montecarlo(
        unidirectional_tube, 2, distribution=balanced, n_speeds=2, strength=False, gap=2.5e-4, force_limit=2e3
    )
    assert result.limits == {}
    assert result.gap_events is None and result.force_events is None
    assert result.gap_exceedance is None and result.force_exceedance is None


def test_an_isotropic_shafts_ply_factor_is_marked_not_applicable():
    result = run_montecarlo(loads_design(SMALL), 2, grade_mm_s=6.3, n_speeds=2)
    factor = result.dataset["safety_factor"]
    assert np.isnan(factor.values).all(), factor.values
    assert "not applicable" in factor.attrs.get("comment", ""), factor.attrs
    assert "not laminated" in factor.attrs["comment"], factor.attrs
