"""A banded sweep, its points a few at a time, solves as the dense matrix at every point.

:meth:`BandedHarmonicSolver.sweep` computes the values of Z(ω, Ω) for a chunk of its points by
one matrix product and reuses one band buffer from point to point: only the matrix's rows of
the buffer are cleared (LAPACK's zgbtrf sets the first kl rows, the LU's fill-in, itself), the
entries of the band outside Z's pattern holding the previous point's factor until then.

Checked on the Jeffcott rotor of tests/jeffcott_bearing.py on its magnetic bearing (4
elements, 24 free DOFs): a sweep of 19 points (two whole chunks and a part one), each at its
own frequency and speed, with a lateral force (the lateral block alone is factorised) and then
with a load on every block, equals at every point the dense LU solution of the whole Z built by
:meth:`term_matrix` (1e-9 relative: the bound of tests/test_banded_blocks_reference.py for this
rotor away from resonance; the points lie between 10 and 300 rad/s, below the first lateral
resonance near 326 rad/s, where Z's condition number is at most a few 1e3 and both solves err
by ~1e-13). The frequencies alternate between the ends of the range, so that a point's matrix
differs from the previous point's factor left in the buffer everywhere.

One tiny model: a few ms beyond its assembly.
"""

from __future__ import annotations

import numpy as np
from jeffcott_bearing import ACTIVE, disk, model_with

from flexshaft.analyses.banded import BandedHarmonicSolver


def test_every_point_of_a_chunked_sweep_solves_as_the_dense_matrix():
    model = model_with(ACTIVE)
    solver = BandedHarmonicSolver(model)
    low, high = np.linspace(10.0, 150.0, 10), np.linspace(300.0, 160.0, 9)
    omegas = np.empty(19)
    omegas[0::2], omegas[1::2] = low, high  # alternating: 10, 300, 25.6, 282.5, ...
    speeds = np.linspace(0.0, 200.0, 19)
    points = list(zip(omegas, speeds))
    v, _ = disk(model)
    lateral = np.zeros(solver.n, complex)
    lateral[int(np.flatnonzero(solver.free == v)[0])] = 1.0
    everywhere = np.linspace(1.0, 2.0, solver.n) * np.exp(1j * np.arange(solver.n))
    assert solver.loaded_span(lateral[solver.perm]) != (0, solver.n)  # the lateral block alone
    for load in (lateral, everywhere, np.column_stack([lateral, everywhere])):
        solutions = list(solver.sweep(points, load))
        assert len(solutions) == len(points)
        for (omega, speed), x in zip(points, solutions):
            Z = solver.term_matrix(solver.term_weights([omega], [speed])[0]).toarray()
            reference = np.linalg.solve(Z, load)
            assert np.linalg.norm(x - reference) <= 1e-9 * np.linalg.norm(reference), (omega, speed)
