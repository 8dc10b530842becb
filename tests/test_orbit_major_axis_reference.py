"""Orbits the reactions report are the ellipses of BOTH lateral components (mutation hunt h35d).

Kinematics (typed here): a lateral motion (v, w) = (Re(V e^{i phi}), Re(W e^{i phi})) traces an
ellipse whose largest radius over the cycle is its major semi-axis
sqrt((|V|^2 + |W|^2 + |V^2 + W^2|)/2); a motion in w alone (V = 0, W real) is a straight line of
semi-axis |W|, a forward circle (W = -iV) one of radius |V|. Neither component alone is the
orbit: a vertical line has no horizontal amplitude at all.

* the actuator's excursion: tests/jeffcott_bearing.py's rotor with its collocated PD magnetic
  bearing at 0.5 m, moved in rigid vertical translation w = 20 um (v = 0): the magnet's orbit is
  that line, excursion 20 um, and the bearing carries per axis F = (k_i (k_p + i omega k_d) - k_s) d
  (docs/magnetic-bearings.md, sensor at the magnet), a line of semi-axis
  |k_i (k_p + i omega k_d) - k_s| * 20 um;
* the worst load case over the shaft: case "line" (w = 30 um, v = 0 at every node) and case
  "circle" (radius 10 um): every node's orbit is 30 um and 10 um, the line is the worst case,
  in either order.

The motions are set directly at the nodes and read through the shape functions at a node:
exact to round-off, 1e-12.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, CONTACT, KD, KI, KP, KS, model_with

from flexshaft.analyses.reactions import actuator_response, worst_case_orbits

OMEGA = 150.0  # rad/s


def _translation(model, V: complex, W: complex) -> np.ndarray:
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    q = np.zeros(dm.size, complex)
    q[dm.shaft(nodes, "v")], q[dm.shaft(nodes, "w")] = V, W
    return q


def test_a_vertical_line_orbit_is_the_actuators_excursion():
    model = model_with(ACTIVE)
    (actuator,) = model.actuators
    assert actuator.collocated
    disp, force = actuator_response(model, _translation(model, 0.0, 20e-6)[:, None], np.array([OMEGA]))
    assert disp[actuator.name] == pytest.approx([20e-6], rel=1e-12)
    expected = abs(KI * (KP + 1j * OMEGA * KD) - KS) * 20e-6
    assert force[actuator.name] == pytest.approx([expected], rel=1e-12)


@pytest.mark.parametrize("order", [(0, 1), (1, 0)])
def test_the_worst_case_is_the_largest_orbit_of_both_components(order):
    model = model_with(CONTACT)
    motions = [_translation(model, 0.0, 30e-6), _translation(model, 10e-6, -10e-6j)]  # line, circle
    radii = [30e-6, 10e-6]
    q = np.stack([motions[k] for k in order], axis=1)[:, :, None]  # (ndof, cases, 1 speed)
    amp, case = worst_case_orbits(model, q)
    expected = np.broadcast_to(np.array([radii[k] for k in order])[None, :, None], amp.shape)
    np.testing.assert_allclose(amp, expected, rtol=1e-12)
    assert int(case[0]) == order.index(0)
