"""How far the every-root check reaches on a truncated basis, in the report's sentence (hunt h54f).

Reference: the module docstring of :mod:`flexshaft.analyses.root_stability` (step 1): above
:data:`~flexshaft.analyses.root_stability.FULL_BASIS_LIMIT` free DOFs the check projects on
"the lowest FULL_BASIS_LIMIT modes, and :attr:`RootStability.highest_frequency` says where the
check stops"; the torsional modes, decoupled, are left out. :meth:`RootStability.coverage` is the
sentence the report prints (``report/run_sections.py``): "the roots of the lowest N modes (to
f Hz)", f the highest natural frequency of the basis in hertz, ω/(2π).

The Jeffcott rotor of tests/jeffcott_bearing.py with a PID magnet (controller states: not
passive, so the "full" method), 4 elements, 24 free DOFs. Its natural frequencies
``(K + K_p) φ = ω² M φ`` are solved here directly by scipy.linalg.eigh on the free-DOF matrices
(as in tests/test_root_stability_coverage_reference.py); a mode is torsional when its twist DOFs
hold more than half its kinetic energy. To reach the truncated branch without a 900-DOF model
the limit is set to 10: the lowest ten modes hold one torsional mode (the sixth) and end on a
degenerate lateral pair (ω₉ = ω₁₀ = 3.98e6 rad/s, not split by the cut), so the basis holds
nine modes and its highest frequency is the tenth eigh frequency, 6.342e5 Hz (3.98e6 rad/s).

Tolerances: the sentence prints four significant digits (``.4g``): relative rounding at most
5e-4, so the parsed number is compared to 1e-3 relative; a slip to rad/s is a factor 2π. The
basis and eigh agree on these frequencies to ~1e-8 (the coverage test's 3e-8). CPU: ~20 ms.
"""

from __future__ import annotations

import importlib
import math
import re

import numpy as np
import pytest
import scipy.linalg as la
from jeffcott_bearing import PID, model_with

from flexshaft.assembly.sparse import restrict

checks = importlib.import_module("flexshaft.analyses.root_stability")


def test_a_truncated_check_states_its_reach_in_hertz(monkeypatch):
    model = model_with(PID)
    free = model.dofs.free
    K = restrict((model.K + model.Kp).tocsr(), free).toarray()
    M = restrict(model.M.tocsr(), free).toarray()
    w2, V = la.eigh(K, M)
    omega = np.sqrt(np.clip(w2, 0.0, None))
    twist = np.isin(free, model.dofs.shaft(np.arange(model.dofs.n_shaft_nodes), "theta"))
    torsional = np.einsum("ij,ij->j", V[twist], (M @ V)[twist]) > 0.5
    limit = 10
    lowest = slice(0, limit)
    assert omega[limit] > omega[limit - 1] * (1 + 1e-6)  # the cut does not split a degenerate pair
    kept = omega[lowest][~torsional[lowest]]

    monkeypatch.setattr(checks, "FULL_BASIS_LIMIT", limit)
    result = checks.root_stability(model, [0.0])
    assert result.method == "full" and not result.exact
    assert result.basis_size == kept.size
    assert result.highest_frequency == pytest.approx(kept.max(), rel=1e-6)
    sentence = result.coverage()
    found = re.search(r"lowest (\d+) modes \(to ([0-9.e+]+) Hz\)", sentence)
    assert found is not None, sentence
    assert int(found.group(1)) == kept.size
    assert float(found.group(2)) == pytest.approx(kept.max() / (2 * math.pi), rel=1e-3)
