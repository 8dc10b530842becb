"""Two integrating magnetic bearings with offset sensors hold their sensors, not their magnets,
at zero under a static load (mutation hunt h37c).

The two PID bearings of tests/test_static_spinning_and_two_integrators_reference.py (magnets at
x = 0.25 and 0.75 m on a 1 m steel tube held only axially and in torsion), each sensing
``sensor_offset`` = 0.1 m further on, at x_s = 0.35 and 0.85 m (docs/magnetic-bearings.md: the
law reads the sensor; tests/test_static_noncollocated_bearing_reference.py). In static
equilibrium an integrator drives its sensed displacement to zero, whatever the current it
takes; the magnets' forces act at the magnets. The shaft is otherwise free in bending, so the
two magnet forces follow from statics alone (moments about the other magnet), as in the
collocated case: F_v = 100 N at 0.4 m → 70 N and 30 N; F_w = 50 N at 0.6 m → 15 N and 35 N.
The displacements at the two sensors are zero; the magnets' stations move (the beam bends
between the loads and the sensors). Tolerance: round-off of a ~130-DOF bordered solve, 1e-9
relative on the forces, 1e-12 of the largest displacement on the held ones; the magnets move by
more than 1e-3 of it (the beam's own curvature between x_a and x_s, about 10 % here).
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import PID
from test_static_spinning_and_two_integrators_reference import TWO_MAGNETS, assert_beam_reactions, two_point_loads

from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

F = 100.0  # N
OFFSET = 0.1  # m


def test_integrating_bearings_hold_their_offset_sensors_at_zero():
    text = TWO_MAGNETS.replace(PID, f"{PID}\nsensor_offset = {OFFSET}")
    assert text.count("sensor_offset") == 2
    model = build_model(loads_design(text))
    dm = model.dofs
    Q = two_point_loads(model)
    assert_beam_reactions(model, Q)
    q = static_response(model, Q)
    scale = np.abs(q).max()
    assert scale > 0.0
    for x in (0.25 + OFFSET, 0.75 + OFFSET):
        node = dm.node_at("shaft", x)
        assert dm.shaft_x[node] == pytest.approx(x, abs=1e-12)
        assert abs(q[dm.shaft(node, "v")]) <= 1e-12 * scale
        assert abs(q[dm.shaft(node, "w")]) <= 1e-12 * scale
    magnets = [q[dm.shaft(dm.node_at("shaft", x), f)] for x in (0.25, 0.75) for f in ("v", "w")]
    assert np.abs(magnets).max() > 1e-3 * scale
