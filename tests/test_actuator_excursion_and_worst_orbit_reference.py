"""What the bearings report: the actuator's excursion at the magnet, not at its sensor, and a
bearing's worst load case by its largest relative orbit.

* **Excursion at the magnet.** tests/jeffcott_bearing.py's rotor (shaft from 0 to L = 1 m) with a
  PD magnetic bearing at x = 0.5 m whose sensor sits 0.125 m aft of it. Given the motion of a
  rigid forward tilt about the origin, v = x, w = −ix (γ = dv/dx = 1, β = −dw/dx = i), the magnet
  describes a circle of radius 0.5 m and the sensor one of radius 0.625 m: the actuator's
  excursion is 0.5 (the orbit's major semi-axis at the magnet). The force it carries is
  F = k_i (k_p + iωk_d) d_s − k_s d_a per axis (docs/magnetic-bearings.md), a circle of radius
  |k_i (k_p + iωk_d) 0.625 − k_s 0.5|. The rows are cubic shape functions at a node: exact to
  round-off, 1e-12 asserted.
* **The worst load case of a bearing** is the case of its largest relative orbit: two cases at the
  contact bearing of the same rotor, a forward circle of radius 10 µm and a straight line of
  semi-axis 30 µm (the ellipse's major semi-axis √((|a|² + |b|² + |a² + b²|)/2), 10 and 30 µm):
  the second, whatever its order.

Written for the mutations h33a-reactions-actuator-orbit-at-sensor and
h33a-reactions-worst-orbit-least of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, CONTACT, KD, KI, KP, KS, model_with

from flexshaft.analyses.reactions import actuator_response, bearing_reactions

OMEGA = 150.0  # rad/s
OFFSET = 0.125  # m, sensor aft of the magnet


def _tilt(model) -> np.ndarray:
    dm = model.dofs
    nodes, x = np.arange(dm.n_shaft_nodes), np.asarray(dm.shaft_x, dtype=float)
    q = np.zeros(dm.size, complex)
    q[dm.shaft(nodes, "v")], q[dm.shaft(nodes, "w")] = x, -1j * x
    q[dm.shaft(nodes, "gamma")], q[dm.shaft(nodes, "beta")] = 1.0, 1j
    return q


def test_the_actuator_excursion_is_read_at_the_magnet_not_at_the_sensor():
    model = model_with(f"{ACTIVE}\nsensor_offset = {OFFSET}")
    (actuator,) = model.actuators
    assert not actuator.collocated
    disp, force = actuator_response(model, _tilt(model)[:, None], np.array([OMEGA]))
    assert disp[actuator.name] == pytest.approx([0.5], rel=1e-12)
    expected = abs(KI * (KP + 1j * OMEGA * KD) * (0.5 + OFFSET) - KS * 0.5)
    assert force[actuator.name] == pytest.approx([expected], rel=1e-12)


@pytest.mark.parametrize("order", [(0, 1), (1, 0)])
def test_a_bearings_worst_case_is_its_largest_relative_orbit(order):
    model = model_with(CONTACT)
    dm = model.dofs
    node = dm.node_at("shaft", 0.5)
    v, w = dm.shaft(node, "v"), dm.shaft(node, "w")
    cases = [(10e-6, -10e-6j), (30e-6, 0.0)]  # circle r = 10 µm, line of semi-axis 30 µm
    q = np.zeros((dm.size, 2), complex)
    for column, k in enumerate(order):
        q[v, column], q[w, column] = cases[k]
    (reaction,) = bearing_reactions(model, np.zeros(dm.size), q, speed=OMEGA).values()
    worst = order.index(1)
    assert reaction.worst_case == worst
    assert reaction.orbit == pytest.approx((30e-6, 0.0), abs=1e-18)
