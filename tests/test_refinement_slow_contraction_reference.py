"""Iterative refinement that contracts slowly but steadily is accepted, on the exact solution.

:func:`~flexshaft.analyses.refinement.refined` iterates ``x ← x + F⁻¹(b − A x)``. With the
factor of F = A / (1 − q) (a scalar multiple of A) the error e = x − A⁻¹b obeys, derived here,
e_{k+1} = e_k − F⁻¹A e_k = (1 − (1 − q)) e_k = q e_k, exactly, and x₀ = F⁻¹b = (1 − q) A⁻¹b,
so x_k = (1 − q^{k+1}) A⁻¹b: every correction is q times the previous one and x grows towards
A⁻¹b, so the relative change |dx_k|/|x_k| falls by slightly less than q a step. The rule of the
banded harmonic solver that :func:`refined` applies (src/flexshaft/analyses/banded.py, module
docstring: the corrections of a regular system "contract: each step must at least halve them";
a singular one's stay of order one) accepts any q below 1/2 once a change is below 1e-3: with
q = 0.45 the changes are 0.31, 0.12, 0.052, ..., below 1e-3 at the eighth step (9.3e-4), within the 12 allowed.

A = a chain of three springs 1/3, 1/7, 1/11 N/m from the ground, pulled by −1 N at its free end:
by statics (each spring carries the whole load, hand sum of the flexibilities) the
displacements are −3, −3 − 7 = −10 and −10 − 11 = −21 m. After the accepted step the remaining
error is q/(1 − q) = 0.82 times the last correction, below 1e-3 of x; the bar is 2e-3 of the
largest displacement (round-off of a 3 × 3 solve is 1e-15: the bar is the iteration's own
stopping rule, not conditioning). q = 0.45 sits 10 % inside the halving rule, so the contraction
does not rest on round-off; a rule demanding 20 times smaller corrections (0.05) refuses it.

CPU: a 3 × 3 chain, about 1 ms.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from flexshaft.analyses.refinement import refined


def _grounded_chain(springs) -> sp.csc_matrix:
    """Stiffness of springs in series from the ground: spring i joins mass i−1 (ground for i = 0)
    to mass i."""
    n = len(springs)
    K = np.zeros((n, n))
    K[0, 0] = springs[0]
    for i, k in enumerate(springs[1:], start=1):
        K[i - 1 : i + 1, i - 1 : i + 1] += k * np.array([[1.0, -1.0], [-1.0, 1.0]])
    return sp.csc_matrix(K)


def test_refinement_contracting_by_045_a_step_is_accepted_on_the_exact_solution():
    springs = (1 / 3, 1 / 7, 1 / 11)
    A = _grounded_chain(springs)
    exact = np.array([-3.0, -10.0, -21.0])
    b = np.array([[0.0], [0.0], [-1.0]])
    np.testing.assert_allclose(spla.spsolve(A, b[:, 0]), exact, rtol=1e-12)  # the chain is the hand sum's
    q = 0.45
    F = spla.splu(sp.csc_matrix(A / (1 - q)))
    assert np.abs(F.solve(b)[:, 0] - exact).max() > 0.4 * 21  # the factor alone is 45 % off
    x = refined(A, F, b)
    assert x is not None, "a refinement contracting by 0.45 < 1/2 a step was refused as singular"
    np.testing.assert_allclose(x[:, 0], exact, rtol=0, atol=2e-3 * 21)
