"""The static reaction of a spinning rotor's integrating bearing is its static constraint force,
not its dynamic law at the spin speed (mutation hunt h35d).

Statics (derived here): tests/jeffcott_bearing.py's rotor with a PID magnetic bearing at its
disk, loaded there by P = (300, -400) N. An integrating bearing drives its sensor's static
displacement to zero (C(s) ~ K_I/s, infinite at s = 0), so the disk stays at 0, the tube is not
bent, its end supports carry nothing and the bearing carries all of P: static force (300, -400) N,
|F| = 500 N, whatever the spin speed (a constant load is a zero-frequency input in the fixed
frame; the imbalance at Omega is the separate, harmonic, case). Evaluating the bearing's law at
s = i Omega instead would read a force off the zero static stroke: nothing. Tolerance 1e-9
(one static solve of a well-conditioned 4-element model).
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import PID, disk, imbalance_vector, model_with

from flexshaft.analyses.reactions import bearing_reactions
from flexshaft.analyses.response import imbalance_response, static_response

OMEGA = 150.0  # rad/s


def test_integrating_bearing_carries_the_static_load_while_spinning():
    model = model_with(PID)
    v, w = disk(model)
    load = np.zeros(model.dofs.size)
    load[v], load[w] = 300.0, -400.0
    q_static = static_response(model, load)
    q_dyn = np.asarray(imbalance_response(model, [OMEGA], imbalance_vector(model)))[:, 0]
    r = bearing_reactions(model, q_static, q_dyn, speed=OMEGA, loads=load)["b"]
    assert r.static_force[1:3] == pytest.approx([300.0, -400.0], rel=1e-9)
    assert r.static_lateral == pytest.approx(500.0, rel=1e-9)
