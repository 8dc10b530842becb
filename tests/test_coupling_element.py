"""The flexible-coupling element against its energy: one spring per relative direction.

Reference: the element is defined by its strain energy (module docstring of
flexshaft.elements.coupling, docs/segmented-driveline.md),

    V = ½ k_ax Δu² + ½ k_lat (Δv² + Δw²) + ½ k_t Δθ² + ½ k_ang (Δβ² + Δγ²),

Δ = aft flange (b) minus forward flange (a). So a unit relative motion in one direction stores
½ k of that direction and nothing else, a common (rigid) motion of both flanges stores nothing,
and the four named stiffnesses land on their own directions. The hub is a rigid body of mass m
and inertias I_d, I_p, half on each flange: a common translation carries m, a common spin I_p.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.elements.coupling import COUPLING_FIELDS, coupling_matrices, coupling_stiffness

AXIAL, LATERAL, TORSIONAL, ANGULAR = 2.0e5, 3.0e7, 1.0e5, 2300.0
EXPECTED = {"u": AXIAL, "v": LATERAL, "w": LATERAL, "theta": TORSIONAL, "beta": ANGULAR, "gamma": ANGULAR}


def test_each_relative_direction_stores_its_own_spring_energy():
    K, _, _ = coupling_matrices(coupling_stiffness(AXIAL, LATERAL, TORSIONAL, ANGULAR))
    assert COUPLING_FIELDS == ("u", "v", "w", "theta", "beta", "gamma")
    for i, field in enumerate(COUPLING_FIELDS):
        stroke = np.zeros(12)
        stroke[6 + i] = 1.0  # aft flange moves, forward flange at rest
        assert 0.5 * stroke @ K @ stroke == pytest.approx(0.5 * EXPECTED[field], rel=1e-14), field
        both = np.zeros(12)
        both[[i, 6 + i]] = 1.0  # both flanges together: no relative motion
        assert abs(both @ K @ both) <= 1e-12 * EXPECTED[field]
        # the energy of the forward flange's motion is the same spring (Δ = −1)
        fwd = np.zeros(12)
        fwd[i] = 1.0
        assert fwd @ K @ stroke == pytest.approx(-EXPECTED[field], rel=1e-14)


def test_hub_mass_and_inertia_are_split_between_the_flanges():
    m, Id, Ip = 1.5, 2.0e-3, 3.5e-3
    _, M, G = coupling_matrices(coupling_stiffness(AXIAL, LATERAL, TORSIONAL, ANGULAR), m, Id, Ip)
    for i, (field, value) in enumerate(zip(COUPLING_FIELDS, (m, m, m, Ip, Id, Id))):
        common = np.zeros(12)
        common[[i, 6 + i]] = 1.0
        assert common @ M @ common == pytest.approx(value, rel=1e-14), field
    # the gyroscopic coupling of the two tilts of a spinning hub is its whole polar inertia
    beta, gamma = np.zeros(12), np.zeros(12)
    beta[[4, 10]] = 1.0
    gamma[[5, 11]] = 1.0
    assert beta @ G @ gamma == pytest.approx(Ip, rel=1e-14)
    assert np.allclose(G, -G.T)
