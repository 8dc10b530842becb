"""The banded solver's terms, its assembled Z(ω, Ω) and its solve against a dense matrix built here.

For the Jeffcott rotor of tests/jeffcott_bearing.py on its magnetic bearing at the disk (k_s,
k_i, PD law, collocated; no loss, no dashpot) the dynamic stiffness on the free DOFs is
(docstring of :mod:`flexshaft.analyses.banded`)

    Z(ω, Ω) = K − ω² M + iωΩ G + (k_i (k_p + iω k_d) − k_s) (e_v e_vᵀ + e_w e_wᵀ),

e_v, e_w the disk's lateral DOFs (the bearing joins them to the ground). It is built here densely
from the assembled M, K, G (rows and columns of the free DOFs, in the order of
``model.dofs.free``) and the bearing's law written by hand, independently of the solver's band
ordering and term storage. Checked:

* :attr:`BandedHarmonicSolver.term_stack` holds, block by block in the order of
  :attr:`term_names`, M, K, G and e_v e_vᵀ + e_w e_wᵀ in the free-DOF ordering (exact: the
  same numbers, only moved);
* :meth:`term_matrix` of :meth:`term_weights` at (ω, Ω) is Z(ω, Ω) (1e-12 of the largest entry:
  one sum of four terms);
* :meth:`solve` of a unit force at the disk agrees with a dense LU solve of Z (1e-9 in norm:
  Z's 2-norm condition number at these frequencies, far from the resonance near 326 rad/s, is
  about 1.5e5 on the 4-element mesh (the tube's element stiffnesses against the disk's), so
  both solves carry relative errors of order 1e-11).

Written for the h26a-banded-term-* mutations of scripts/mutations.toml; one tiny model, 24 free
DOFs: a few ms beyond its assembly.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, KD, KI, KP, KS, disk, model_with

from flexshaft.analyses.banded import BandedHarmonicSolver


@pytest.fixture(scope="module")
def model():
    return model_with(ACTIVE)


def dense(matrix, free):
    return matrix.toarray()[np.ix_(free, free)]


def bearing_pattern(model, free):
    position = {int(d): k for k, d in enumerate(free)}
    pattern = np.zeros((free.size, free.size))
    for dof in disk(model):
        pattern[position[int(dof)], position[int(dof)]] = 1.0
    return pattern


def dynamic_stiffness(model, free, omega, speed):
    law = KI * (KP + 1j * omega * KD) - KS
    return (
        dense(model.K, free)
        - omega**2 * dense(model.M, free)
        + 1j * omega * speed * dense(model.G, free)
        + law * bearing_pattern(model, free)
    )


def test_term_stack_holds_each_term_in_the_free_dof_ordering(model):
    solver = BandedHarmonicSolver(model)
    free = solver.free
    assert np.array_equal(free, model.dofs.free)
    assert solver.term_names == ["M", "K", "G", "A0"]
    stack = solver.term_stack.toarray()
    n = free.size
    expected = [dense(model.M, free), dense(model.K, free), dense(model.G, free), bearing_pattern(model, free)]
    for k, block in enumerate(expected):
        assert np.array_equal(stack[k * n : (k + 1) * n], block), solver.term_names[k]


@pytest.mark.parametrize(("omega", "speed"), [(150.0, 400.0), (420.0, 0.0)])
def test_term_matrix_and_solve_agree_with_the_dense_dynamic_stiffness(model, omega, speed):
    solver = BandedHarmonicSolver(model)
    free = solver.free
    Z = dynamic_stiffness(model, free, omega, speed)
    weights = solver.term_weights([omega], [speed])[0]
    assembled = solver.term_matrix(weights).toarray()
    assert np.abs(assembled - Z).max() <= 1e-12 * np.abs(Z).max()
    stacked = solver.term_matrix(np.stack([weights, 2.0 * weights])).toarray()
    assert np.abs(stacked[free.size :] - 2.0 * Z).max() <= 1e-12 * np.abs(Z).max()
    rhs = np.zeros(free.size, complex)
    rhs[list(free).index(disk(model)[0])] = 1.0
    reference = np.linalg.solve(Z, rhs)
    assert np.linalg.norm(solver.solve(omega, rhs, speed) - reference) <= 1e-9 * np.linalg.norm(reference)
