"""What the every-root check covers: its highest frequency, and a basis it cannot estimate (hunt h39a).

References.

1. The full check's reach. A driveline with a PID magnet (controller states: not passive) is
   checked on every mode of its free DOFs (``exact``), and :attr:`RootStability.highest_frequency`
   is the highest undamped natural frequency of the modes it holds [rad/s]: one of the model's
   natural frequencies, ``(K + K_p) φ = ω² M φ`` solved here directly by scipy.linalg.eigh on the
   free-DOF matrices: the highest of those that are not torsion (the torsional modes, decoupled,
   may be left out; a mode is torsional when its twist DOFs hold more than half its kinetic
   energy). The Jeffcott rotor of tests/jeffcott_bearing.py, 4 elements, 24 free DOFs;
   its highest mode is the near-massless tube's axial one, 1.7e7 rad/s, which eigh and the
   basis agree on to 3e-8: tolerance 1e-6 relative.

2. An estimate that cannot be computed accepts no basis. A passive driveline (contact dashpot,
   rotating loss η = 0.01; a steel tube of 16 elements, 96 free DOFs) is checked on the first
   enriched basis whose roots below the spin are estimated within the tolerance of the full
   model's (47 vectors here, estimate 5e-18). With the estimate replaced by NaN (as for a
   reduced model without full operators) no basis can be accepted on it: the check must end on
   its last basis, every lateral mode (the free DOFs without the 16 free twists, decoupled), whose
   roots are the full model's (estimate 0 by construction), and the least-damped root is the same
   as on the estimated basis (to 1e-9 relative: both within 1e-17 of the full model).
CPU: about 0.1 s.
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest
import scipy.linalg as la
from jeffcott_bearing import PID, model_with
from rotors import WN, jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import loads_design

checks = importlib.import_module("flexshaft.analyses.root_stability")


def test_the_full_checks_highest_frequency_is_a_natural_frequency_in_rad_s():
    model = model_with(PID)
    result = checks.root_stability(model, [0.0])
    assert result.method == "full" and result.exact
    free = model.dofs.free
    K = restrict((model.K + model.Kp).tocsr(), free).toarray()
    M = restrict(model.M.tocsr(), free).toarray()
    w, V = la.eigh(K, M)  # V is M-normalised: each mode's kinetic-energy shares sum to 1
    omega = np.sqrt(np.clip(w, 0.0, None))
    twist = np.isin(free, model.dofs.shaft(np.arange(model.dofs.n_shaft_nodes), "theta"))
    torsional = np.einsum("ij,ij->j", V[twist], (M @ V)[twist]) > 0.5
    # the highest of the modes that are not torsion (here the tube's axial mode, above the
    # highest torsional one, 1.2e7 rad/s)
    assert result.highest_frequency == pytest.approx(omega[~torsional].max(), rel=1e-6)


def test_a_basis_whose_error_cannot_be_estimated_is_not_accepted(monkeypatch):
    text = jeffcott_text(0.01, 50.0, elements=16).replace("density = 0.1", "density = 7800.0")
    model = build_model(loads_design(text))
    speed = 2 * WN
    estimated = checks.root_stability(model, [speed])
    assert estimated.method == "passive" and estimated.error_estimate <= 1e-6
    estimate = checks.eigenvalue_errors
    monkeypatch.setattr(checks, "eigenvalue_errors", lambda *a, **k: np.full(np.shape(estimate(*a, **k)), np.nan))
    blind = checks.root_stability(model, [speed])
    dm = model.dofs
    twists = np.intersect1d(dm.shaft(np.arange(dm.n_shaft_nodes), "theta"), dm.free).size
    assert estimated.basis_size < dm.free.size - twists
    assert blind.basis_size == dm.free.size - twists
    assert blind.error_estimate == 0.0
    assert blind.least_damped[0] == pytest.approx(estimated.least_damped[0], rel=1e-9)
