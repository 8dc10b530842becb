"""Monte-Carlo imbalance: random residual unbalance per bay and the distribution of what it does.

* :mod:`~flexshaft.montecarlo.samples`: the eccentricity distribution (ISO 21940-11's balance
  grade), each bay's unbalance ``U_b = e_b m_b`` (m_b its rotating mass), the draws and the unit
  responses that make each sample a weighted sum (linearity);
* :mod:`~flexshaft.montecarlo.steady`: the steady spin-up of every sample on the sweep engine,
  with the probabilities of exceeding the actuators' limits;
* :mod:`~flexshaft.montecarlo.runup`: the same samples over a run-up transient;
* :mod:`~flexshaft.montecarlo.confidence`: exceedance counts and their exact (Clopper–Pearson)
  upper confidence bounds.
"""

from flexshaft.montecarlo.confidence import Exceedance, clopper_pearson_upper
from flexshaft.montecarlo.runup import RunupSamples, runup_montecarlo
from flexshaft.montecarlo.samples import (
    EccentricityDistribution,
    ImbalanceDraws,
    UnitResponses,
    bay_unbalances,
    draw_imbalance,
    sample_outputs,
    unit_responses,
)
from flexshaft.montecarlo.steady import MonteCarloResult, MonteCarloSampler, montecarlo_study, run_montecarlo

__all__ = [
    "EccentricityDistribution",
    "Exceedance",
    "ImbalanceDraws",
    "MonteCarloResult",
    "MonteCarloSampler",
    "RunupSamples",
    "UnitResponses",
    "bay_unbalances",
    "clopper_pearson_upper",
    "draw_imbalance",
    "montecarlo_study",
    "run_montecarlo",
    "runup_montecarlo",
    "sample_outputs",
    "unit_responses",
]
