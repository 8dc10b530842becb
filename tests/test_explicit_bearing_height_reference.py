"""A bearing's height above the boom: an explicit ``offset`` is the height h itself; without it
h is the boom's vertical semi-axis at the station plus ``shaft_clearance``
(docs/design-reference.md, ``offset``).

Kinematics: the bearing joins the shaft at x to the point a height h above the boom's axis at
the same station. Twist the boom alone by a uniform θ (every boom node θ = 1, nothing else):
the attachment point turns about the boom's axis and moves by r × p = (θ, 0, 0) × (0, h, 0) =
(0, 0, θh) (the rotations reference, tests/test_bearing_rotations_reference.py: w = t_z + r_x h).
The bearing's rows give shaft minus attachment, so the relative w is −h and the relative v is 0.
The boom's twist shape function is linear, so a uniform twist is interpolated exactly: the rows
give −h to round-off (1e-12 asserted, h of order 0.3 m).

Numbers: the tapered boom of the rotations reference (vertical semi-axis 0.25 m at the root,
0.12 m at the 2 m tip, clearance 0.05 m). The "hanger" at x = 0.7 m has no offset:
h = 0.25 + (0.7/2)(0.12 − 0.25) + 0.05 = 0.2545 m; the "mount" at x = 1.55 m gives offset = 0.31:
h = 0.31 m, not 0.31 + 0.05.

Written for the mutation h35c-build-explicit-offset-plus-clearance of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from boomed_rotor import shaft_and_boom

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

BOOMED = f"""
name = "shaft on a tapered boom"
{shaft_and_boom(2.0)}[[bearings]]
name = "hanger"
kind = "contact"
x = 0.7
stiffness = {{ v = 1e7, w = 2e7 }}
[[bearings]]
name = "mount"
kind = "contact"
x = 1.55
offset = 0.31
stiffness = {{ v = 1e7, w = 1e7 }}
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 5
boom_elements = 3
"""

HEIGHTS = {"hanger": 0.25 + 0.35 * (0.12 - 0.25) + 0.05, "mount": 0.31}


@pytest.fixture(scope="module")
def model():
    return build_model(loads_design(BOOMED))


@pytest.mark.parametrize("name", sorted(HEIGHTS))
def test_a_boom_twist_moves_the_bearing_sideways_by_its_height(model, name):
    link = next(b for b in model.bearings if b.name == name)
    q = np.zeros(model.dofs.size)
    q[model.dofs.values(np.arange(model.dofs.size), "boom", "theta")] = 1.0  # uniform boom twist
    relative = link.rows @ q  # (u, v, w, beta, gamma), shaft minus attachment
    h = HEIGHTS[name]
    assert link.offset == pytest.approx(h, rel=1e-12)
    assert relative[2] == pytest.approx(-h, rel=1e-12)
    assert np.abs(relative[[0, 1, 3, 4]]).max() <= 1e-12
