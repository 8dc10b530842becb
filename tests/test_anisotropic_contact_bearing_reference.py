"""A contact bearing's v and w stiffness act in their own planes: the static deflection of a tube
on two anisotropic bearings (mutation hunt h37c).

A steel tube (E = 210 GPa, D 50 mm, wall 5 mm, L = 1 m, held only axially and in torsion at its
forward end) on two contact bearings at its ends, each k_v = 2e6 N/m and k_w = 8e6 N/m, loaded
by P = 100 N at midspan, once in v and once in w, at rest. Statically determinate: each bearing
carries P/2 and gives P/(2k), and the tube bends between its supports by P L³/(48 E I)
(simply supported beam, Roark's Table 8.1 case 1e), so the midspan deflection is

    v = P/(2 k_v) + P L³/(48 E I),    w = P/(2 k_w) + P L³/(48 E I),

the planes uncoupled at rest. Cubic beam elements are exact under nodal point loads, so only the
round-off of a ~70-DOF solve is left: 1e-10 relative. The bearings give 25 and 6.25 µm beside
the bending's 54.8 µm, so a stiffness read in the wrong plane moves either deflection by about
a quarter (79.8 ↔ 61.0 µm).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

E, DO, WALL, L, P = 210e9, 0.05, 0.005, 1.0, 100.0
KV, KW = 2.0e6, 8.0e6

TEXT = f"""
name = "tube on two anisotropic bearings"
[materials.steel]
kind = "isotropic"
E = {E}
G = 80e9
density = 7800.0
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "fore"
kind = "contact"
x = 0.0
stiffness = {{ v = {KV}, w = {KW} }}
[[bearings]]
name = "aft"
kind = "contact"
x = {L}
stiffness = {{ v = {KV}, w = {KW} }}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 10
"""


def test_each_plane_deflects_on_its_own_bearing_stiffness():
    model = build_model(loads_design(TEXT))
    dm = model.dofs
    mid = dm.node_at("shaft", L / 2)
    assert dm.shaft_x[mid] == pytest.approx(L / 2, abs=1e-12)
    I = np.pi * (DO**4 - (DO - 2 * WALL) ** 4) / 64
    bending = P * L**3 / (48 * E * I)
    for field, k in (("v", KV), ("w", KW)):
        Q = np.zeros(dm.size)
        Q[dm.shaft(mid, field)] = P
        q = static_response(model, Q, speed=0.0)
        assert q[dm.shaft(mid, field)] == pytest.approx(P / (2 * k) + bending, rel=1e-10)
        other = "w" if field == "v" else "v"
        assert abs(q[dm.shaft(mid, other)]) <= 1e-12 * P / (2 * k)
