""":func:`~flexshaft.analyses.refinement.checked_solve` refuses a matrix singular to working
precision even when the loads lie in its range.

Reference (closed form): the stiffness of a free-free chain of four masses joined by springs
k = 1/3, 1/7, 1/11 has the rigid translation (1, 1, 1, 1) in its null space exactly (each row
sums to zero), so it is singular, rank 3; in floating point the springs are not representable
and the LU leaves a pivot of round-off size (2.8e-17) instead of an exact zero, which a
factorisation alone does not refuse. A self-equilibrated load (+1 at the first mass, −1 at the
last: orthogonal to the null vector, so in the range of the symmetric matrix) has infinitely
many solutions; its own iterative refinement can converge on one of them, so only the random
probe, which no singular matrix's range contains, tells the matrix is singular. The contract
(the function's docstring): None for a matrix singular to working precision, whatever the load.
The same chain held at its first mass (rank 4, κ ≈ 28) is regular and solved: a unit pull
−1 at the free end carries the force 1 through every spring, each stretched by ``1/k``
(statics), so the displacements are ``0, −3, −10, −21`` (tolerance 1e-12 of the largest:
round-off of a κ ≈ 28 solve).
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.refinement import checked_solve

SPRINGS = (1 / 3, 1 / 7, 1 / 11)


def _chain() -> np.ndarray:
    n = len(SPRINGS) + 1
    K = np.zeros((n, n))
    for i, k in enumerate(SPRINGS):
        K[i : i + 2, i : i + 2] += k * np.array([[1.0, -1.0], [-1.0, 1.0]])
    return K


def test_a_free_free_chain_is_refused_even_for_a_self_equilibrated_load():
    K = _chain()
    load = np.array([[1.0], [0.0], [0.0], [-1.0]])
    assert abs(np.ones(4) @ load[:, 0]) == 0.0  # in the range
    assert checked_solve(K, load) is None


def test_the_chain_held_at_one_end_is_solved_by_statics():
    K = _chain()
    K[0, :], K[:, 0], K[0, 0] = 0.0, 0.0, 1.0  # the first mass held (a unit row: x0 = load0 = 0)
    load = np.array([[0.0], [0.0], [0.0], [-1.0]])
    x = checked_solve(K, load)
    assert x is not None
    # −1 at the free end pulls every spring by 1: extensions 1/k = 3, 7, 11 from the held mass
    np.testing.assert_allclose(x[:, 0], [0.0, -3.0, -10.0, -21.0], rtol=0, atol=1e-12 * 21)
