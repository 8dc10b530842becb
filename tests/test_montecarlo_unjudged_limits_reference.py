"""A Monte-Carlo run says which question it could not ask: no exceedance probability without a
limit to judge.

References:

* :class:`~flexshaft.montecarlo.steady.MonteCarloResult`: ``gap_exceedance`` is "P(static offset +
  peak orbit > gap at some active bearing) and its standard error (None without a gap)",
  ``gap_events`` "None without a gap", ``force_events`` None "when no bearing has a limit"; the
  CLI's ``--json`` writes them as ``gap_exceedance`` (docs/transient.md) and ``p_gap_exceeded``
  (cli/transient.py). docs/transient.md: a sample exceeds "when some active bearing's static +
  peak value passes that bearing's own limit": a design with no active bearing has no limit to
  pass, so the question is not asked (None), which is not the answer "never exceeded" (p = 0 ± 0
  of N samples, an estimate the terminal and the figure would then print with its 95 % upper
  bound). The case: the [0] ply tube of tests/test_montecarlo_ply_check_reference.py, supported by
  a contact stop only (no active bearing), with a gap and a force limit asked for all the same:
  they apply to every active bearing, of which there is none.

Two samples on a 2-speed grid (as tests/test_montecarlo_draws_reported_reference.py, for
CPU). Exact None results: no tolerance.
"""

from __future__ import annotations

from test_montecarlo_ply_check_reference import unidirectional_tube  # noqa: F401 (pytest fixture)

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
