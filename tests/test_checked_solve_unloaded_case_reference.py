""":func:`~flexshaft.analyses.refinement.checked_solve` of a regular system with an unloaded case.

Reference (closed form, derived here): a regular matrix maps only the zero vector to zero, so
the solution of ``A x = 0`` is ``x = 0`` exactly, and LU forward/back substitution of a zero
right-hand side gives exact zeros (every operation is a product with or a sum of zeros), as does
every refinement correction (the residual ``0 − A·0`` is zero). The relative correction
``|dx|/|x|`` of that column is then 0/0. API contract (docstring of
:func:`~flexshaft.analyses.refinement.checked_solve`): "Solution of ``A x = b`` (columns), or
None when ``A`` is singular to working precision." The chain is regular, so the column must
come back as zeros, not as a refusal.

The matrix is the spring chain of tests/test_checked_solve_singular_reference.py held at its
first mass (springs k = 1/3, 1/7, 1/11, κ ≈ 28): a unit pull −1 at the free end carries the force
1 through every spring, each stretched by ``1/k`` (statics), so the displacements are
``0, −3, −10, −21``. Tolerance 1e-12 of the largest (round-off of a κ ≈ 28 solve, ~1e-15,
with margin for a different BLAS); the zero case is exact.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.refinement import checked_solve

SPRINGS = (1 / 3, 1 / 7, 1 / 11)


def _held_chain() -> np.ndarray:
    n = len(SPRINGS) + 1
    K = np.zeros((n, n))
    for i, k in enumerate(SPRINGS):
        K[i : i + 2, i : i + 2] += k * np.array([[1.0, -1.0], [-1.0, 1.0]])
    K[0, :], K[:, 0], K[0, 0] = 0.0, 0.0, 1.0  # the first mass held (a unit row: x0 = load0)
    return K


def test_an_unloaded_case_beside_a_loaded_one_is_solved_as_zero():
    """Two load cases at once, the pull and nothing: statics for the first, exact zeros for
    the second."""
    loads = np.array([[0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [-1.0, 0.0]])
    x = checked_solve(_held_chain(), loads)
    assert x is not None, "a regular chain with an unloaded case was refused as singular"
    np.testing.assert_allclose(x[:, 0], [0.0, -3.0, -10.0, -21.0], rtol=0, atol=1e-12 * 21)
    assert np.all(x[:, 1] == 0.0)


def test_a_system_without_load_is_solved_as_zero():
    """The only case unloaded: x = 0, not a refusal."""
    x = checked_solve(_held_chain(), np.zeros((4, 1)))
    assert x is not None, "a regular chain without load was refused as singular"
    assert np.all(x == 0.0)
