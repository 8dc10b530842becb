"""Whether a model's magnetic bearings are described by their PD gains alone
(``Model.all_pd``, flexshaft.assembly.model), against the force law written by hand.

Derived reference. A magnet at shaft node a with the thesis's PD law (k_i = 1, k_s = 0)
pushes on the shaft with f = −(K_p + s K_d) d_s, d_s the displacement at its sensor. When the
sensor sits at the magnet (d_s = q_a) the bearing's dynamic stiffness is the diagonal entry
Z[a, a] = K_p + s K_d on each lateral axis: exactly the model's ``Kp + s Kd`` (Σ B_aᵀ k B_a),
so the gains describe it. With the sensor at node b ≠ a it is the off-diagonal entry
Z[a, b] = K_p + s K_d and Z[a, a] = 0 (tests/test_noncollocated_dynamic_stiffness_reference.py):
no matrix on B_aᵀB_a reproduces it, and ``all_pd`` must say False, so that the studies that
read a bearing through its gains (the gain maps of the thesis studies) are not run on it.

Rotor: the Jeffcott test tube (tests/rotors.py), 10 elements of 0.1 m; magnet at x = 0.3 m,
the sensor at +0.1 m or on the magnet, both on nodes (unit rows). Tolerance 1e-12 of the gain
(entries are the gains themselves, one rounding each). CPU: two small builds, milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KP, KD = 2.0e6, 50.0  # [N/m], [N s/m]
S = 30.0 + 400j  # a Laplace point [1/s]


def _model(sensor_offset: float):
    text = jeffcott_text(0.0, 0.0, elements=10)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    magnet = (
        f'[[bearings]]\nname = "m"\nx = 0.3\nkind = "active"\nsensor_offset = {sensor_offset}\nkp = {KP}\nkd = {KD}\n'
    )
    return build_model(loads_design(head + magnet + tail))


@pytest.mark.parametrize("offset", [0.0, 0.1])
def test_the_gains_describe_a_bearing_only_when_it_senses_at_its_magnet(offset):
    model = _model(offset)
    dm = model.dofs
    magnet, sensor = (int(np.flatnonzero(np.isclose(dm.shaft_x, x))[0]) for x in (0.3, 0.3 + offset))
    law = KP + KD * S
    expected = np.zeros((dm.size, dm.size), dtype=complex)
    for f in ("v", "w"):
        expected[dm.shaft(magnet, f), dm.shaft(sensor, f)] = law  # force at the magnet, law of the sensed motion
    got = model.controller_matrix(S).toarray()
    assert np.max(np.abs(got - expected)) <= 1e-12 * abs(law)
    by_gains = (model.Kp + S * model.Kd).toarray()  # the description by the gains alone
    describes = bool(np.max(np.abs(by_gains - expected)) <= 1e-12 * abs(law))
    assert describes == (offset == 0.0)
    assert model.all_pd == describes
