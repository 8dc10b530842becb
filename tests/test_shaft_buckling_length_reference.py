"""The shaft's buckling check uses the tube's length, wherever the shaft starts.

A simply supported shell's critical torque depends on its radius, wall, laminate and length
L = x_end − x_start, not on where the shaft's stations are counted from: translating the shaft
(the same tube from 0.5 to 1.5 m instead of 0 to 1 m) is a change of origin, which no physics
can see. So the check must report L = 1 m for both, and the same critical torque and safety
factor to round-off (the same arithmetic on the same numbers: 1e-12). The classical shell
(Sanders), a 1 m [±45]s tube: at this length the global helical mode depends on L (in
Donnell's moderate-length range the critical torque falls about as L^(−1/2); Batdorf's curve is
checked in tests/test_buckling.py), so a wrong length is seen. Two elements per shaft: the
mesh does not enter the shell solve.
"""

from __future__ import annotations

import pytest

from flexshaft.analyses.shaft_buckling import shaft_buckling
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def _tube(x_start: float) -> str:
    x_end = x_start + 1.0
    return f"""
name = "[45/-45]s tube"
[materials.ply]
kind = "lamina"
density = 1600.0
E_L = 120.0e9
E_T = 8.0e9
G_LT = 4.0e9
nu_LT = 0.3
X_t = 2000.0e6
X_c = 1000.0e6
Y_t = 40.0e6
Y_c = 140.0e6
S = 60.0e6
[shaft]
x_start = {x_start}
x_end = {x_end}
outer_diameter = 0.1016
wall_thickness = 0.002
material = "ply"
layup = "(45/-45)s"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "stop"
kind = "contact"
x = {x_end}
stiffness = {{}}
[operating]
speed_rpm = 4000.0
power = 150e3
[mesh]
shaft_elements = 2
"""


def test_a_translated_shaft_buckles_at_the_same_torque():
    at_origin = shaft_buckling(build_model(loads_design(_tube(0.0))), theory="classical")
    translated = shaft_buckling(build_model(loads_design(_tube(0.5))), theory="classical")
    assert at_origin.result.length == pytest.approx(1.0, rel=1e-12)
    assert translated.result.length == pytest.approx(1.0, rel=1e-12)
    assert translated.result.critical_torque == pytest.approx(at_origin.result.critical_torque, rel=1e-12)
    assert translated.safety_factor == pytest.approx(at_origin.safety_factor, rel=1e-12)
