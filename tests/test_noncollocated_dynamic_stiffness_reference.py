"""The dynamic stiffness of a magnetic bearing whose sensor is off its magnet, entry by entry
against the force law (mutation hunt 23d).

Derived reference. A magnet at shaft node a, its displacement sensor at node b, both on the
ground (no housing DOFs), acts on the shaft with (per lateral axis v and w)

    f_shaft = −(G(s) d_s − k_s d_a),   G(s) = k_i (K_p + K_d s),   d_a = q_a, d_s = q_b,

the control force follows the SENSED displacement and pushes at the MAGNET, and the magnet's
open-loop negative stiffness k_s pulls the shaft further off (f = +k_s d_a). Moved to the left
of [−ω²M + iωΩG + K + Z(s)] q = Q, the bearing's dynamic stiffness Z(s) has, per axis,

    Z[a, b] = G(s),   Z[a, a] = −k_s,   Z[b, a] = Z[b, b] = 0,

and nothing else: a non-symmetric matrix (the sensor node feels no force). Rotor: the Jeffcott
test tube (tests/rotors.py), 10 elements of 0.1 m; magnet at x = 0.3 m and sensor offset
+0.1 m, both on nodes, so the rows are unit rows and no shape function enters. Tolerance
1e-12 relative to |G| (the entries are products of the given gains, one rounding each).
CPU: one small model build, a few milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KI, KP, KD, KS = 100.0, 5.0e3, 2.0, 2.0e5  # [N/A], [A/m], [A s/m], [N/m]


@pytest.fixture(scope="module")
def model():
    text = jeffcott_text(0.0, 0.0, elements=10)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    magnet = (
        '[[bearings]]\nname = "m"\nx = 0.3\nkind = "active"\nsensor_offset = 0.1\n'
        f"ki = {KI}\nkp = {KP}\nkd = {KD}\nks = {KS}\n"
    )
    return build_model(loads_design(head + magnet + tail))


@pytest.mark.parametrize("s", [0.0, 300j, 40.0 + 2000j])
def test_the_force_follows_the_sensor_and_acts_at_the_magnet(model, s):
    (act,) = model.actuators
    assert not act.collocated
    dm = model.dofs
    magnet, sensor = (int(np.flatnonzero(np.isclose(dm.shaft_x, x))[0]) for x in (0.3, 0.4))
    a = {f: int(dm.shaft(magnet, f)) for f in ("v", "w")}
    b = {f: int(dm.shaft(sensor, f)) for f in ("v", "w")}
    gain = KI * (KP + KD * s)
    expected = np.zeros((dm.size, dm.size), dtype=complex)
    for f in ("v", "w"):
        expected[a[f], b[f]] = gain
        expected[a[f], a[f]] = -KS
    got = model.controller_matrix(s).toarray()
    assert np.max(np.abs(got - expected)) <= 1e-12 * abs(gain)
