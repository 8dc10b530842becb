"""Static equilibrium of a spinning tube on three bearings, one of them integrating, with the
rotating-frame internal damping (closed form: the equilibrium of a rigid body, derived here).

A free-free steel tube (tests/rotors.py's section, L = 1 m, 4 elements; axial and torsional
motion held at x = 0 only) rests on contact bearings of stiffness k = 48 EI/L³ at x = 0 and
x = L and on a PID magnetic bearing (tests/jeffcott_bearing.py's gains) at x = L/2, and carries
P = 1000 N along v at x = L/4. The shaft's material has a loss factor 0.1 and the rotating-frame
internal damping; the design spins at 3000 rpm.

Statics. Whatever the shaft's stiffness, its elastic and loss forces are internal, so the forces
the three bearings carry balance the load as on a rigid body:

    Σ F_v = P,   Σ F_w = 0,   Σ x F_v = P L/4,   Σ x F_w = 0.

The tube is statically indeterminate on three supports, two of them elastic, so how the load
splits depends on the shaft: spinning, the rotating-frame loss adds the circulatory stiffness
(the deflection turns slightly sideways, flexshaft.analyses.loss), and the bearings carry
w-forces (measured here: about 7 N at the PID bearing, 0.7 % of P) that still balance. The PID
bearing's static force is its constraint force (static_actuator_forces); computed for the shaft
at rest while the contact bearings' forces come from the deflection at speed, the sums would miss
by those 7 N.

Tolerance: the sums are a residual, not a forward error: for the rigid-body vectors r,
ΣF − P = −rᵀ(A x − b) − (K_shaft r)ᵀ q, whose componentwise bound ε rᵀ(|A| |x|) is 1.1e-14 P on
this model; and the product's solve is better conditioned than the unscaled constraint system
[[K, −B_aᵀ], [B_s, 0]] (2-norm condition number 2.6e15): its pivot ratio is below the refinement
screen, so it rescales rows and columns (condition number then about 1e2) and refines. 1e-8 P
is asserted: about 1e6 above that bound (measured 1e-16 to 7e-16 P on Prescott, Haswell and
numpy 1.26) and 7e5 below the 6.9 N by which a reaction taken for the shaft at rest misses.
After the sums, a guard checks that the case is exercised: the PID bearing's w-force above
1e-3 P.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import K_INT, KD, KI, KP, KS
from rotors import DI, DO, E, G, L

from flexshaft.analyses.reactions import bearing_reactions
from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

P = 1000.0  # N
KB = 48 * E * np.pi * (DO**4 - DI**4) / 64 / L**3  # N/m


def _text() -> str:
    return f"""
name = "tube on three bearings"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G}
density = 0.1
loss_factor = 0.1
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "steel"
fixed_start = ["u", "theta"]
fixed_end = []
[[bearings]]
name = "left"
kind = "contact"
x = 0.0
stiffness = {{ v = {KB}, w = {KB} }}
damping = {{}}
[[bearings]]
name = "pid"
kind = "active"
x = {L / 2}
kp = {KP}
kd = {KD}
integral_gain = {K_INT}
ks = {KS}
ki = {KI}
[[bearings]]
name = "right"
kind = "contact"
x = {L}
stiffness = {{ v = {KB}, w = {KB} }}
damping = {{}}
[operating]
speed_rpm = 3000.0
power = 0.0
[analysis]
internal_damping = "rotating"
[mesh]
shaft_elements = 4
"""


def test_bearing_reactions_balance_the_load_with_the_rotating_loss_at_speed():
    model = build_model(loads_design(_text()))
    dm = model.dofs
    load = np.zeros(dm.size)
    load[dm.shaft(dm.node_at("shaft", L / 4), "v")] = P
    q_static = static_response(model, load)
    reactions = bearing_reactions(model, q_static, np.zeros(dm.size, complex), loads=load)
    fv = sum(r.static_force[1] for r in reactions.values())
    fw = sum(r.static_force[2] for r in reactions.values())
    mv = sum(r.x_shaft * r.static_force[1] for r in reactions.values())
    mw = sum(r.x_shaft * r.static_force[2] for r in reactions.values())
    assert fv == pytest.approx(P, abs=1e-8 * P)
    assert fw == pytest.approx(0.0, abs=1e-8 * P)
    assert mv == pytest.approx(P * L / 4, abs=1e-8 * P * L)
    assert mw == pytest.approx(0.0, abs=1e-8 * P * L)
    assert abs(reactions["pid"].static_force[2]) > 1e-3 * P  # the loss turns the reactions sideways
