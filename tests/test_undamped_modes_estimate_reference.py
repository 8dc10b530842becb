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
dashpot (800 N s/m) gives the damped roots ζ = 0.16 (modes 1, 2) and 0.11 (mode 4), measured
(ζ of the lowest asserted above 0.1): a residual that kept the damping s D Φ y would report
errors of that order for the undamped roots instead.

Mode numbers: README.md (Output): "Modes are numbered from 1 (the Python API counts from 0) in
increasing damped frequency"; undamped at rest the roots are the ``±iω`` of ``K φ = ω² M φ``
(``scipy.linalg.eigh`` here), so the row numbered k is the k-th lowest ω. Modes 1 and 2 are a
degenerate bending pair (151.26 rad/s), so the row numbered 3 is checked too: the distinct
torsion root 483.28 rad/s (neighbours 151.26 and 734.98). At rest the default basis holds these
undamped modes themselves, so the rows differ from eigh only by the two eigensolvers' round-off,
a priori about ½ ε λ_max/λ_k ≤ 1.1e-10 relative on ω (λ_max/λ₁ ≈ 1e6 on these 78 DOFs); measured
3e-12 to 8e-12 (row 1) and 1e-13 to 4e-13 (row 3); 1e-9 is asserted, far below the relative
gaps of row 3 to its neighbours (0.69 and 0.52 of ω₃) that an off-by-one would give.
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
    # truncation (8e-6 to 5e-4), not the reference's round-off: the three bending roots; the
    # third root is the tube's torsion, exact on the basis (4e-15)
    bending = true > 1e-10
    assert np.count_nonzero(bending) == 3
    assert np.all(m.error_estimate[bending] > true[bending] / 3)
    assert np.all(m.error_estimate[bending] < 3 * true[bending])
    assert modes(tube, speed, n_modes=4, basis_size=8).damping_ratios[0] > 0.1  # the dashpot's


def test_the_row_numbered_one_is_the_lowest_mode(tube):
    w2 = la.eigh(_free(tube, tube.K), _free(tube, tube.M), eigvals_only=True)
    m = modes(tube, 0.0, n_modes=4, damped=False)
    rows = m.table()
    for number in (1, 3):  # 1: the lowest; 3: the distinct torsion root, between 1-2 and 4
        row = next(r for r in rows if r["mode"] == number)
        omega = np.sqrt(w2[number - 1])
        assert abs(row["frequency_Hz"] * 2 * np.pi - omega) < 1e-9 * omega
    assert sorted(r["mode"] for r in rows) == [1, 2, 3, 4]
