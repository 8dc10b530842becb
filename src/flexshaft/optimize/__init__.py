"""Multi-objective design optimization of the driveline, with the requirements as constraints.

* :mod:`~flexshaft.optimize.variables`: design variables and objectives;
* :mod:`~flexshaft.optimize.problem`: the problem (variables, objectives, constraints, base design);
* :mod:`~flexshaft.optimize.evaluate`: one evaluation, the assessment of a candidate at the
  optimizer's fidelity (:func:`flexshaft.verdict.assess.assess`), as floats;
* :mod:`~flexshaft.optimize.store`: every evaluation on disk, and batches on the sweep engine;
* :mod:`~flexshaft.optimize.nsga`: the search (NSGA-II from pymoo, ask and tell);
* :mod:`~flexshaft.optimize.result`: the Pareto front, its figure and design files;
* :mod:`~flexshaft.optimize.files`: design files and their re-verification;
* :mod:`~flexshaft.optimize.reference`: ZDT1, a verification problem with a known front.

pymoo (the extra ``flexshaft[optimize]``) is imported by the search only.
"""

from flexshaft.optimize.nsga import optimize
from flexshaft.optimize.problem import DesignProblem, objectives_and_constraints
from flexshaft.optimize.result import OptimizationResult, hypervolume, pareto_mask
from flexshaft.optimize.variables import DesignVariable, Objective, OptimizeError, default_variables

__all__ = [
    "DesignProblem",
    "DesignVariable",
    "Objective",
    "OptimizationResult",
    "OptimizeError",
    "default_variables",
    "hypervolume",
    "objectives_and_constraints",
    "optimize",
    "pareto_mask",
]
