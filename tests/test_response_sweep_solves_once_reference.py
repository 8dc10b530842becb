"""The projected imbalance sweep solves each speed in full at most once, and its response is the
full one, on the rigid rotor on three springs of tests/test_critical_search_load_cases_reference.py.

References:

* :mod:`flexshaft.analyses.sweep_projection`'s contract: ``SweepResult.full_solves`` is "banded
  solves made (one per speed solved in full, for all load cases at once)", and each round solves
  the full model where the reduced model's residual indicator is largest among the speeds not yet
  solved: a speed solved again adds no direction to the basis. So the banded solves the sweep
  makes (counted by wrapping :meth:`BandedHarmonicSolver.sweep`) number exactly ``full_solves``.
* The module's accuracy promise, against the all-full imbalance response
  (:func:`flexshaft.analyses.response.imbalance_response`, one banded solve per speed): every
  orbit within 1e-7 of the scan's peak (tests/test_spinup_projection.py's tolerance, about 5×
  the 1.5-1.9e-8 measured; the sweep's own tolerance is 1e-8).

300 speeds from 0.02 to 1.3 Ω_op (the greedy accepts after one round; how many full solves it
makes, 26-41, depends on the BLAS's round-off and is not asserted); the 4-element rigid rotor
keeps it cheap (about 0.1 s).

Written for the mutation h39b-sweep-indicator-resolves-solved of scripts/mutations.toml, which
only the count catches (re-solving a speed leaves the response as accurate): the count is
:attr:`SweepResult.full_solves`'s documented contract, "banded solves made".
"""

from __future__ import annotations

import numpy as np
from test_critical_search_load_cases_reference import TEXT

from flexshaft.analyses.banded import BandedHarmonicSolver
from flexshaft.analyses.response import imbalance_response
from flexshaft.analyses.sweep_projection import imbalance_sweep
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import loads_design


def test_each_speed_is_solved_in_full_once(monkeypatch):
    model = build_model(loads_design(TEXT))
    speeds = np.linspace(0.02, 1.3, 300) * model.speed
    loads = imbalance_loads(model)
    solved = []
    sweep = BandedHarmonicSolver.sweep

    def counted(self, points, rhs):
        points = list(points)
        solved.extend(points)
        return sweep(self, points, rhs)

    monkeypatch.setattr(BandedHarmonicSolver, "sweep", counted)
    result = imbalance_sweep(model, speeds, loads)
    monkeypatch.undo()
    assert result.basis_size > 0  # the projection, not the all-full fallback
    assert len(solved) == result.full_solves
    assert len(set(solved)) == len(solved)
    full = np.asarray(imbalance_response(model, speeds, loads))
    assert np.abs(np.asarray(result.response) - full).max() <= 1e-7 * np.abs(full).max()
