"""The undamped (gyroscopic-only) modes of :func:`~flexshaft.analyses.modal.modes` on a plain
basis: their error estimate against the full model solved here, and the table's mode numbers.

Reference (derived here): ``damped=False`` drops the dashpot (the :func:`modes` docstring), so
the exact roots at spin Ω are those of ``(s² M + s Ω G + K) φ = 0`` on the free DOFs of the
unreduced model. Solved in first-order form through its inverse as in
tests/test_modes_full_model_reference.py: ``A⁻¹ = [[−K⁻¹ΩG, −K⁻¹M], [I, 0]]`` with the DOFs
Jacobi-scaled (κ(K) ≈ 1e4), accurate to ~1e-12 relative. A plain 8-mode basis of the 12-element
tube (78 free DOFs) errs by 8e-6 to 5e-4 on its three lowest bending roots (measured), well
above the reference's round-off, and the a-posteriori estimate (first order in the residual,
:mod:`flexshaft.analyses.eigen_error`) must match that true error within a factor 3. The
dashpot (800 N s/m) gives the damped roots ζ ≈ 1e-2 (asserted below): a residual that kept the
damping s D Φ y would report errors of that order for the undamped roots instead.

Mode numbers: docs/validation.md's benchmarks call the lowest frequency "mode 1", and the
table's caption says modes are numbered from 1 by f; so the row numbered 1 is the one of the
lowest undamped root ω₁ of ``K φ = ω² M φ`` (``scipy.linalg.eigh``), to 1e-10 (the reduced
root of a plain basis errs by its truncation, ~1e-7 here, on ω; 1e-5 relative is asserted).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from test_modes_full_model_reference import TUBE

from flexshaft.analyses import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


@pytest.fixture(scope="module")
def tube():
    return build_model(loads_design(TUBE))


def _free(model, A):
    free = model.dofs.free
    return A.toarray()[np.ix_(free, free)]


def _full_gyroscopic_roots(model, speed: float, n: int) -> np.ndarray:
    """The ``n`` lowest roots (Im s > 0, by Im s) of the unreduced undamped problem."""
    M, K, G = (_free(model, A) for A in (model.M, model.K, model.G))
    d = 1.0 / np.sqrt(np.diag(K))
    M, K, G = (d[:, None] * X * d[None, :] for X in (M, K, G))
    size = M.shape[0]
    A_inv = np.block([[-la.solve(K, speed * G), -la.solve(K, M)], [np.eye(size), np.zeros((size, size))]])
    s = 1.0 / la.eigvals(A_inv)
    s = s[s.imag > 0]
    return s[np.argsort(s.imag)][:n]


def test_undamped_estimate_is_the_true_error_of_a_plain_basis(tube):
    speed = float(tube.speed)
    exact = _full_gyroscopic_roots(tube, speed, 4)
    m = modes(tube, speed, n_modes=4, basis_size=8, damped=False)
    true = np.abs(m.eigenvalues - exact) / np.abs(exact)
    bending = np.array([k for k in range(4) if m.kind[k] == "lateral"])
    assert bending.size == 3  # the third root is the tube's torsion, exact on the basis
    assert np.all(true[bending] > 1e-10)  # truncation, not the reference's round-off
    assert np.all(m.error_estimate[bending] > true[bending] / 3)
    assert np.all(m.error_estimate[bending] < 3 * true[bending])
    assert modes(tube, speed, n_modes=4, basis_size=8).damping_ratios[0] > 1e-3  # the dashpot's


def test_the_row_numbered_one_is_the_lowest_mode(tube):
    w2 = la.eigh(_free(tube, tube.K), _free(tube, tube.M), eigvals_only=True)
    m = modes(tube, 0.0, n_modes=4, damped=False)
    rows = m.table()
    assert sorted(r["mode"] for r in rows) == [1, 2, 3, 4]
    first = next(r for r in rows if r["mode"] == 1)
    assert abs(first["frequency_Hz"] * 2 * np.pi - np.sqrt(w2[0])) < 1e-5 * np.sqrt(w2[0])
