"""The assembled model's bookkeeping against the layout and units its documents state.

* The global DOF vector is ``[shaft node 0: u v w θ β γ | … | boom node 0: v w θ β γ | … |
  extra]`` (:mod:`flexshaft.assembly.dofs`): with 3 shaft nodes and 2 boom nodes the boom's
  DOFs are 6·3 = 18 to 18 + 5·2 − 1 = 27, counted here by hand. :attr:`DofMap.boom_dofs` is what
  the mode classification sums the boom's share of a mode over.
* A coupling's allowable misalignment is given in degrees (``allowable_angle_deg``) and the
  model holds it in radians: 0.5° = 0.5 π/180 rad (definition of the degree), to round-off.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.dofs import DofMap
from flexshaft.design import loads_design

TEXT = """
name = "one coupling"
[materials.al]
kind = "isotropic"
E = 70e9
G = 26e9
density = 2700.0
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.05
wall_thickness = 0.002
material = "al"
fixed_start = ["u", "theta"]
[[couplings]]
name = "flex"
x = 1.0
angular_stiffness = 2300.0
axial_stiffness = 2.0e5
torsional_stiffness = 1.0e5
lateral_stiffness = 1.0e7
mass = 1.0
diametral_inertia = 1e-3
polar_inertia = 2e-3
allowable_angle_deg = 0.5
[[bearings]]
name = "near"
kind = "contact"
x = 0.0
stiffness = { v = 1e9, w = 1e9 }
[[bearings]]
name = "far"
kind = "contact"
x = 2.0
stiffness = { v = 1e9, w = 1e9 }
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 4
"""


def test_the_boom_dofs_follow_six_per_shaft_node():
    dm = DofMap(shaft_x=np.array([0.0, 1.0, 2.0]), boom_x=np.array([0.0, 3.0]))
    np.testing.assert_array_equal(dm.boom_dofs, np.arange(18, 28))


def test_a_couplings_allowable_angle_is_held_in_radians():
    (coupling,) = build_model(loads_design(TEXT)).couplings
    assert coupling.allowable_angle == pytest.approx(0.5 * math.pi / 180.0, rel=1e-15)
