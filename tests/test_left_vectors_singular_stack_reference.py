"""The left vectors of the eigenvalue error estimate when one matrix of the stack is singular.

``eigen_error._left_vectors`` takes each mode's left vector z_k by one step of inverse iteration,
``T_kᵀ z_k = y_k`` normalised, all modes in one stacked solve; the tracking's estimate stacks the
modes of several speeds (``tracked_errors``). numpy refuses the whole stack when one T_k is
exactly singular; that T_k's vector is then the smallest singular vector, and every other one
must still be its own inverse-iteration step, not a singular vector as well (found in review:
another speed's vector moved by 4e-7). Reference: the definition, solved on its own with
scipy's LU. The regular matrix here has condition number about 10, so the two solves agree to
about 10·ε; 1e-12 leaves a wide margin, while a singular vector in its place differs by O(1).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as la

from flexshaft.analyses.eigen_error import _left_vectors


def test_a_singular_matrix_leaves_the_others_their_inverse_iteration() -> None:
    rng = np.random.default_rng(7)
    n = 6
    regular = np.eye(n) * 3.0 + 0.5 * (rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n)))
    singular = regular.copy()
    singular[:, 2] = 0.0  # exactly singular: numpy's LU meets a zero pivot
    Y = rng.standard_normal((n, 2)) + 1j * rng.standard_normal((n, 2))
    Z = _left_vectors(np.stack([singular, regular]), Y)

    want = la.solve(regular.T, Y[:, 1])
    want /= np.linalg.norm(want)
    assert np.linalg.cond(regular) < 20
    np.testing.assert_allclose(Z[:, 1], want, rtol=0, atol=1e-12)
    # the singular one: a unit null vector of its transpose
    assert abs(np.linalg.norm(Z[:, 0]) - 1.0) < 1e-12
    assert np.linalg.norm(singular.T @ Z[:, 0]) < 1e-12 * np.linalg.norm(singular)
