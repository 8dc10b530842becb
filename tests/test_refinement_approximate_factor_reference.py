""":func:`~flexshaft.analyses.refinement.refined` with an approximate factor (mutation hunt 46a).

Iterative refinement ``x ← x + F⁻¹(b − A x)`` with a factor F of a nearby matrix contracts the
error e = x − A⁻¹b by ``I − F⁻¹A`` a step (derivation: x_{k+1} − A⁻¹b = e_k − F⁻¹A e_k), so
it converges on A's exact solution whenever ``‖I − F⁻¹A‖ < 1``. A = the held chain of
tests/test_checked_solve_singular_reference.py, springs 1/3, 1/7, 1/11 and a unit row at the
held mass, pulled by −1 at its free end (statics: displacements 0, −3, −10, −21); F = A with
every spring stiffened by 2 % (‖I − F⁻¹A‖ ≈ 0.02: F⁻¹A = I − 0.02/1.02 on the spring rows).
Refinement is accepted once a correction is below 1e-3 of x; the error then is at most
0.02/(1 − 0.02) of that correction, 2.1e-5 of x; the bar is 5e-5 of the largest displacement.
A refinement that subtracted its correction would double the error a step and refuse this
regular system as singular.

CPU: a 4 × 4 chain, about 1 ms.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from flexshaft.analyses.refinement import refined


def _held_chain(springs) -> sp.csc_matrix:
    n = len(springs) + 1
    K = np.zeros((n, n))
    for i, k in enumerate(springs):
        K[i : i + 2, i : i + 2] += k * np.array([[1.0, -1.0], [-1.0, 1.0]])
    K[0, :], K[:, 0], K[0, 0] = 0.0, 0.0, 1.0
    return sp.csc_matrix(K)


def test_refinement_with_an_approximate_factor_reaches_the_exact_solution():
    springs = (1 / 3, 1 / 7, 1 / 11)
    A = _held_chain(springs)
    F = spla.splu(_held_chain(tuple(1.02 * k for k in springs)))
    b = np.array([[0.0], [0.0], [0.0], [-1.0]])
    assert np.abs(F.solve(b)[:, 0] - [0.0, -3.0, -10.0, -21.0]).max() > 0.3  # the factor alone is 2 % off
    x = refined(A, F, b)
    assert x is not None
    np.testing.assert_allclose(x[:, 0], [0.0, -3.0, -10.0, -21.0], rtol=0, atol=5e-5 * 21)
