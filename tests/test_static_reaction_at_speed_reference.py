"""The static reaction of a spinning rotor's integrating bearing is its static constraint force,
not its dynamic law at the spin speed (mutation hunt h35d).

Statics (derived here): tests/jeffcott_bearing.py's rotor (a tube pinned at both ends, L = 1 m)
with a PID magnetic bearing at its disk, loaded there by P = (300, -400) N. The bearing's law is
KI C(s) - KS with the controller C(s) = KP + K_INT/s + KD s (KI the magnet's current gain,
K_INT the integral gain): infinite at s = 0, so the integrator drives the sensed static
displacement to zero. The disk stays at 0, no other load is on the tube, so the tube is not
bent (deflection and slopes zero everywhere), its end supports carry nothing and the bearing
carries all of P: static force (300, -400) N, |F| = 500 N, whatever the spin speed (a constant
load is a zero-frequency input in the fixed frame; the imbalance response at Omega is the
separate, harmonic, case and does not enter the static force). Evaluating the bearing's law at
s = i Omega instead would read a force off the zero static stroke: nothing.

Tolerances. The forces: 1e-9 relative (one static solve of a 4-element model). The
displacements are compared with the scale the load would give without the bearing, the
simply-supported beam's mid-span deflection d0 = |P| L^3 / (48 EI) (slopes with d0 / L, below
the beam's end slope 3 d0 / L): the free tube stiffness has condition number 1.5e5 (measured
with numpy.linalg.cond), so a backward-stable solve errs by ~eps 1.5e5 = 3e-11 of that scale;
1e-9 asserted.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import PID, disk, imbalance_vector, model_with
from rotors import DI, DO, E, L

from flexshaft.analyses.reactions import bearing_reactions
from flexshaft.analyses.response import imbalance_response, static_response

OMEGA = 150.0  # rad/s


def test_integrating_bearing_carries_the_static_load_while_spinning():
    model = model_with(PID)
    v, w = disk(model)
    load = np.zeros(model.dofs.size)
    load[v], load[w] = 300.0, -400.0
    q_static = static_response(model, load)
    d0 = 500.0 * L**3 / (48 * E * np.pi * (DO**4 - DI**4) / 64)  # the unsupported mid-span deflection
    assert abs(q_static[v]) <= 1e-9 * d0 and abs(q_static[w]) <= 1e-9 * d0  # the integrator holds the disk
    nodes = range(model.dofs.shaft_element_x.shape[0] + 1)
    for field, scale in (("v", d0), ("w", d0), ("beta", d0 / L), ("gamma", d0 / L)):
        bent = [q_static[model.dofs.shaft(n, field)] for n in nodes]
        assert np.max(np.abs(bent)) <= 1e-9 * scale, field  # the tube is not bent
    q_dyn = np.asarray(imbalance_response(model, [OMEGA], imbalance_vector(model)))[:, 0]
    assert np.abs(q_dyn[v]) > 0  # the imbalance does move the rotor at Omega ...
    for q_at_speed in (q_dyn, np.zeros(model.dofs.size, complex)):  # ... but not its static force
        r = bearing_reactions(model, q_static, q_at_speed, speed=OMEGA, loads=load)["b"]
        assert r.static_force[1:3] == pytest.approx([300.0, -400.0], rel=1e-9)
        assert r.static_lateral == pytest.approx(500.0, rel=1e-9)
