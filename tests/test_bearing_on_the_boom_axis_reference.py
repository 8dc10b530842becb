"""A bearing given ``offset = 0`` sits on the boom's own axis.

A bearing's ``offset`` is the height h of the shaft axis above the boom's neutral axis at the
mount (docs/model.md: the bearing joins the shaft to the attachment point at height h); the
design schema allows h = 0 (docs/limits.md:34: a bearing ``offset`` is a ``Clearance``, 0 to
10 m) and only an omitted ``offset`` falls back to the boom's vertical semi-axis plus
``shaft_clearance``. Kinematics, derived here and matching the documented attachment
kinematics w = w_b + hθ_b (docs/model.md:52): twisting the boom alone by a uniform θ moves a
point at height h by (θ, 0, 0) × (0, h, 0) = (0, 0, θ h),
so with h = 0 a boom twist does not move the attachment point at all, while a boom translation
v = 1 moves it by 1 (the bearing's rows give shaft minus attachment: relative v = −1). The
companion bearing without ``offset`` on the same circular boom (radius R, clearance 0.05 m)
moves by −(R + 0.05) under the unit twist. The boom's twist and translation shape functions
interpolate uniform fields exactly: the rows give these to round-off (1e-12 on entries of
order 1).

Written for the mutation h85a-explicit-zero-offset-ignored of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

R, T_WALL, L_BOOM = 0.2, 0.002, 2.0

DESIGN = f"""
name = "shaft over a circular aluminium boom"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800.0
loss_factor = 0.0
[materials.al]
kind = "isotropic"
E = 70e9
G = 26e9
density = 2700.0
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.08
wall_thickness = 0.003
material = "steel"
fixed_start = ["u", "v", "w", "theta", "beta", "gamma"]
[tailboom]
length = {L_BOOM}
root_semi_axes = [{R}, {R}]
tip_semi_axes = [{R}, {R}]
wall_thickness = {T_WALL}
material = "al"
shaft_clearance = 0.05
[[bearings]]
name = "on the axis"
kind = "contact"
x = 0.9
offset = 0.0
stiffness = {{}}
[[bearings]]
name = "above the boom"
kind = "contact"
x = 1.5
stiffness = {{}}
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 4
boom_elements = 4
"""


@pytest.fixture(scope="module")
def model():
    return build_model(loads_design(DESIGN))


def _boom_field(model, field: str) -> np.ndarray:
    q = np.zeros(model.dofs.size)
    q[model.dofs.values(np.arange(model.dofs.size), "boom", field)] = 1.0
    return q


def test_a_bearing_given_zero_height_sits_on_the_boom_axis(model):
    link = next(b for b in model.bearings if b.name == "on the axis")
    assert link.offset == 0.0  # the given height, not the boom's semi-axis plus clearance
    twisted = link.rows @ _boom_field(model, "theta")  # (u, v, w, beta, gamma), shaft minus boom point
    assert np.abs(twisted).max() <= 1e-12, twisted
    lifted = link.rows @ _boom_field(model, "v")
    assert lifted[1] == pytest.approx(-1.0, abs=1e-12)
    # the default height is the semi-axis plus the clearance: the boom twist moves that point
    other = next(b for b in model.bearings if b.name == "above the boom")
    assert (other.rows @ _boom_field(model, "theta"))[2] == pytest.approx(-(R + 0.05), rel=1e-12)
