"""Two bearing layouts on one mesh: the banded solve of each against its own dense Z(ω, Ω).

The Jeffcott rotor of tests/jeffcott_bearing.py (8 elements, its shaft also held axially at
the far end, so that this mesh is used by no other test) carries its magnetic bearing at the
disk (x = 0.5), first collocated, then with its sensor 0.25 m outboard (x = 0.75, already a
node: both models have the same DOFs and stations). On the free DOFs (docs/magnetic-bearings.md,
"The element": Z += B_aᵀ G(s) B_s − k_s B_aᵀ B_a with G = k_i A C, here A = 1 and C = k_p + k_d s)

    Z(ω, Ω) = K − ω² M + iωΩ G + iω C + k_i (k_p + iω k_d) B_aᵀ B_s − k_s B_aᵀ B_a,

with B_s = B_a when collocated. The sensed bearing's B_aᵀ B_s couples the disk node to a node
two elements away: entries outside the collocated model's pattern. Z is built here densely from
the assembled matrices and the law written by hand; a unit forward-whirl force at the disk is
solved by a dense LU and by the banded solver, the collocated model first (the order of a study
over sensor positions on one mesh), so the sensed model's solver is built after a model with
the same mesh but a narrower pattern.

Tolerance 1e-9 relative (2-norm): Z's condition number is about 1e6 at these points (measured
with numpy.linalg.cond, tube stiffness against the disk's), so both LU solves carry relative
errors of order 1e-10 at most (measured differences 1e-13). The two layouts' responses differ
by 10 % at ω = 150 rad/s and 2 % at 700 rad/s (measured), and a solver that reused the
collocated pattern for the sensed bearing was off by 180 % and 10 % there.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, KD, KI, KP, KS, disk
from rotors import jeffcott_text

from flexshaft.analyses.banded import BandedHarmonicSolver
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def bearing_model(bearing: str):
    text = jeffcott_text(0.0, 0.0, elements=8)
    assert 'fixed_end = ["v", "w"]' in text  # the axial hold below keeps this mesh unique to this test
    text = text.replace('fixed_end = ["v", "w"]', 'fixed_end = ["u", "v", "w"]')
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    return build_model(loads_design(f'{head}[[bearings]]\nname = "b"\nx = 0.5\n{bearing}\n{tail}'))


def dense_response(model, omega, speed):
    free = model.dofs.free

    def d(matrix):
        return matrix.toarray()[np.ix_(free, free)]

    (a,) = model.actuators
    B_a, B_s = a.lateral_rows.toarray()[:, free], a.sensing_rows.toarray()[:, free]
    Z = d(model.K) - omega**2 * d(model.M) + 1j * omega * speed * d(model.G) + 1j * omega * d(model.C)
    Z = Z + KI * (KP + 1j * omega * KD) * B_a.T @ B_s - KS * B_a.T @ B_a
    force = np.zeros(free.size, complex)
    position = {int(dof): k for k, dof in enumerate(free)}
    v, w = disk(model)
    force[position[int(v)]], force[position[int(w)]] = 1.0, -1j
    return force, np.linalg.solve(Z, force)


@pytest.mark.parametrize(("omega", "speed"), [(150.0, 400.0), (700.0, 300.0)])
def test_a_sensed_bearing_after_a_collocated_one_on_the_same_mesh(omega, speed):
    collocated = bearing_model(ACTIVE)
    sensed = bearing_model(ACTIVE + "\nsensor_offset = 0.25")
    assert collocated.actuators[0].collocated and not sensed.actuators[0].collocated
    assert np.array_equal(collocated.dofs.free, sensed.dofs.free)
    assert np.array_equal(collocated.dofs.stations, sensed.dofs.stations)
    for model in (collocated, sensed):
        force, reference = dense_response(model, omega, speed)
        x = BandedHarmonicSolver(model).solve(omega, force, speed)
        assert np.linalg.norm(x - reference) <= 1e-9 * np.linalg.norm(reference)
    # the sensor's position moves the response by 2-10 % here: the check above separates the layouts
    apart, near = dense_response(sensed, omega, speed)[1], dense_response(collocated, omega, speed)[1]
    assert np.linalg.norm(apart - near) > 0.01 * np.linalg.norm(near)
