"""Iterative refinement of a harmonic solve converges to the solution, from a wrong start.

:class:`~flexshaft.analyses.banded.BandedHarmonicSolver` checks a solve whose band LU has a
pivot of round-off size by iterative refinement, ``x ← x + Ẑ⁻¹ (b − Z x)`` with the computed
LU as Ẑ⁻¹. Derivation: with b = Z x* the step maps the error e = x − x* to e − Ẑ⁻¹ Z e =
(I − Ẑ⁻¹ Z) e, of size about κ ε ‖e‖ (Ẑ = Z + δZ with ‖δZ‖ ≈ ε ‖Z‖): from any start it contracts
when κ ε < 1, and the correction of the second step is round-off. Its accept test (correction
below FORWARD_ERROR_LIMIT = 1e-3 of x) and its singularity test (a correction that does not
halve) rest on that contraction.

Here the damped Jeffcott rotor of tests/rotors.py (ζ = 0.05 dashpot at the disk, 100 N at the
disk at ω = 250 rad/s, at rest), well conditioned (LAPACK's reciprocal condition estimate of its
band LU is about 1e-6): its band LU solution, started 1 %, 10 % and 30 % off, is refined back to
the solution that SuperLU (scipy.sparse.linalg.spsolve, another factorisation of the same
sparse Z in the solver's ordering) gives. Tolerance 1e-9 of the peak: κ ε ≈ 1e6 · 1.1e-16 ≈
1e-10 for either solver (measured 3e-13). The refinement is called directly (the public solve
starts it only from a solution that is already right to κ ε). CPU: a few milliseconds.

Written for the mutation h39b-banded-refinement-step-sign of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse.linalg as spla
from rotors import K_SHAFT, M_DISK, disk_dofs, jeffcott
from scipy.linalg import lapack

from flexshaft.analyses.banded import BandedHarmonicSolver


@pytest.mark.parametrize("error", [0.01, 0.1, 0.3])
def test_refinement_removes_the_error_of_its_start(error):
    model = jeffcott(0.0, 2 * 0.05 * np.sqrt(K_SHAFT * M_DISK))
    solver = BandedHarmonicSolver(model)
    omega, speed = 250.0, 0.0
    v, _ = disk_dofs(model)
    load = np.zeros(model.dofs.size, complex)
    load[v] = 100.0
    b = np.asfortranarray(load[solver.free][solver.perm])  # the solver's ordering
    lu, piv, x, info = lapack.zgbsv(solver.kl, solver.ku, solver.matrix(omega, speed), b)
    assert info == 0
    exact = spla.spsolve(solver.sparse_matrix(omega, speed).tocsc(), b)
    start = x * (1.0 + error)
    refined = solver._refine(solver.matrix_data(omega, speed), lu, piv, b, start, omega, speed, (0, solver.n))
    assert np.abs(refined - exact).max() <= 1e-9 * np.abs(exact).max()
