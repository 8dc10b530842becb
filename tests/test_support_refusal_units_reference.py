"""The too-stiff refusal states a support's bound in the unit of its direction.

Reference: docs/limits.md (hand-written), "A contact stiffness, `ki·kp` or `ks` above 1e8 times
the element's stiffness (E A/h axially, E I/h³ laterally, E I/h in rotation, with h = shaft
length / `mesh.shaft_elements`) is refused, naming the largest allowed value for that shaft and
mesh". Derived here: a force per displacement (u, v, w) is in N/m, a moment per rotation
(beta, gamma) in N m/rad, so the named bound 1e8 E I/h of a rotational support is in N m/rad
and 1e8 E I/h³ of a lateral one in N/m.

A steel tube (E = 210 GPa, D_o = 20 mm, wall 1 mm: I = π(D_o⁴ − D_i⁴)/64 = 2.70e-9 m⁴), 2 m in
4 elements (h = 0.5 m): 1e8 E I/h = 1.134e11 N m/rad, 1e8 E I/h³ = 4.538e11 N/m. The refused
stiffness is 1.25 times the bound (25 % away: the physics decides the refusal, not the digits);
the bound is printed to 3 significant digits, so it is compared to 5e-3 relative (half a unit
in the third digit is 5e-3 of the leading one at worst).

CPU: two refused builds of a 4-element tube, well under 0.1 s.
"""

from __future__ import annotations

import re

import pytest

# the steel tube of the rotational-support test (4 elements over 2 m) and its E I, and the
# documented ratio 1e8 of the support limit
from test_rotational_support_and_pid_law_reference import DO, ELEMENTS, LENGTH, RIGID_RATIO, WALL, E, _ei

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, loads_design


def _text(stiffness: str) -> str:
    return f"""
name = "support units"
[materials.steel]
kind = "isotropic"
E = {E!r}
G = 80e9
density = 7800.0
[shaft]
x_start = 0.0
x_end = {LENGTH}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "hanger"
kind = "contact"
x = 0.0
stiffness = {{ {stiffness} }}
[[bearings]]
name = "tail"
kind = "contact"
x = {LENGTH}
stiffness = {{ v = 1e5, w = 1e5 }}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = {ELEMENTS}
"""


@pytest.mark.parametrize(
    ("direction", "power_of_h", "unit"), [("beta", 1, "N m/rad"), ("gamma", 1, "N m/rad"), ("v", 3, "N/m")]
)
def test_the_named_bound_carries_the_unit_of_its_direction(direction, power_of_h, unit):
    """The bound 1e8 E I/h^p named for a refused support is stated in N m/rad in rotation and
    in N/m laterally (docs/limits.md; units derived in the module docstring)."""
    h = LENGTH / ELEMENTS
    limit = RIGID_RATIO * _ei() / h**power_of_h
    others = ", ".join(f"{d} = 1e5" for d in ("v", "w") if d != direction)
    with pytest.raises(DesignError) as refused:
        build_model(loads_design(_text(f"{others}, {direction} = {1.25 * limit!r}")))
    message = str(refused.value)
    assert f"bearings[0].stiffness.{direction}" in message
    allowed = re.search(r"allowed: at most ([0-9.e+-]+) (N m/rad|N/m) ", message)
    assert allowed is not None, message
    assert allowed.group(2) == unit
    assert float(allowed.group(1)) == pytest.approx(limit, rel=5e-3)
