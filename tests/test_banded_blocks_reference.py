"""The banded solver factorises only the uncoupled blocks a load reaches: against a dense solve.

The Jeffcott rotor of tests/jeffcott_bearing.py on its magnetic bearing (4 elements, 24 free
DOFs) has three uncoupled blocks in its dynamic stiffness: the lateral motion (v, w, and the
slopes: 16 DOFs, joined by the gyroscopic and bearing terms), the axial motion and the torsion
(4 each: a straight isotropic tube couples neither to bending). A lateral force has no axial or
torsional response, exactly (Z is block diagonal), so the solver may factorise the lateral block
alone (:meth:`BandedHarmonicSolver.loaded_span`); the module docstring of
:mod:`flexshaft.analyses.banded` says why its LU is the one it would be inside the whole matrix.

Checked:

* the solver's blocks are unions of the connected components of its sparsity pattern (found
  here by :func:`scipy.sparse.csgraph.connected_components`, independently of the solver's
  own bookkeeping), none split, and there are three of them;
* a lateral force, a torque and both together give the dense LU solution of the whole Z built
  by :meth:`term_matrix` (1e-9 relative: the existing dense reference's bound for this rotor,
  tests/test_banded_terms_dense_reference.py; Z's condition number away from resonance is
  about 1.6e3 on the lateral block and 30 on the others here, so both solves err by ~1e-13), and
  the rows a load does not reach are exactly zero (a property of the block structure, exact in
  floating point);
* the span of a lateral load covers the lateral block only, and that of a load on every block,
  every row;
* the DOFs coupled to given rows (:meth:`BandedHarmonicSolver.coupled`, the bearing loops'
  visible DOFs) are the connected components that hold them.

One tiny model: a few ms beyond its assembly.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, disk, model_with
from scipy.sparse.csgraph import connected_components

from flexshaft.analyses.banded import BandedHarmonicSolver

OMEGA = 150.0  # rad/s, well below the first lateral resonance near 326 rad/s


@pytest.fixture(scope="module")
def solver():
    return BandedHarmonicSolver(model_with(ACTIVE))


@pytest.fixture(scope="module")
def model():
    return model_with(ACTIVE)


def _dense(solver, omega, speed):
    return solver.term_matrix(solver.term_weights([omega], [speed])[0]).toarray()


def _free_index(model, solver, dof):
    return int(np.flatnonzero(solver.free == dof)[0])


def test_blocks_are_the_connected_components_of_the_pattern(solver):
    pattern = solver._template.copy()
    pattern.data[:] = 1.0
    n_components, label = connected_components(pattern, directed=False)
    blocks = solver._block
    assert np.all(np.diff(blocks) >= 0), "each block's rows are contiguous in the solver's ordering"
    for c in range(n_components):
        assert np.unique(blocks[label == c]).size == 1, f"component {c} is split between blocks"
    assert np.unique(blocks).size == n_components == 3


def test_a_lateral_force_a_torque_and_both_solve_as_the_dense_matrix(model, solver):
    v, _ = disk(model)
    node = model.dofs.node_at("shaft", 0.5)
    torsion = model.dofs.shaft(node, "theta")
    Z = _dense(solver, OMEGA, model.speed)  # free-DOF ordering
    lateral = np.zeros(solver.n, complex)
    lateral[_free_index(model, solver, v)] = 1.0
    torque = np.zeros(solver.n, complex)
    torque[_free_index(model, solver, torsion)] = 1.0
    for b in (lateral, torque, lateral + torque):
        x = solver.solve(OMEGA, b, model.speed)
        reference = np.linalg.solve(Z, b)
        assert np.linalg.norm(x - reference) <= 1e-9 * np.linalg.norm(reference)
    # what a load does not reach stays exactly zero
    x = solver.solve(OMEGA, lateral, model.speed)
    assert x[_free_index(model, solver, torsion)] == 0
    x = solver.solve(OMEGA, torque, model.speed)
    assert x[_free_index(model, solver, v)] == 0
    assert np.count_nonzero(x) == 4  # the torsion block alone


def test_the_span_of_a_load_covers_the_blocks_it_reaches(model, solver):
    v, _ = disk(model)
    lateral = np.zeros(solver.n, complex)
    lateral[_free_index(model, solver, v)] = 1.0
    lo, hi = solver.loaded_span(lateral[solver.perm])
    blocks = solver._block
    assert hi - lo == np.count_nonzero(blocks == blocks[solver.inverse[_free_index(model, solver, v)]]) == 16
    assert solver.loaded_span(np.ones(solver.n, complex)) == (0, solver.n)
    assert solver.loaded_span(np.zeros(solver.n, complex)) == (0, solver.n)


def test_the_dofs_coupled_to_rows_are_their_connected_components(model, solver):
    """:meth:`BandedHarmonicSolver.coupled` (the bearing loops' visible DOFs) against the
    connected components of Z's pattern, computed here in the model's free-DOF order: rows of
    one block give that block, rows of two blocks their union."""
    pattern = solver._template.copy()
    pattern.data[:] = 1.0
    _, label = connected_components(pattern, directed=False)
    label = label[solver.inverse]  # the template is in the solver's ordering
    for rows in ([0], [solver.n - 1], [0, solver.n - 1], list(range(solver.n))):
        want = np.isin(label, label[rows])
        np.testing.assert_array_equal(solver.coupled(np.array(rows)), want)
    assert not solver.coupled(np.array([0])).all()  # the Jeffcott rotor's blocks are not one
