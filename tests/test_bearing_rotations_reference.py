"""A bearing's rotational rows: a rigid motion of shaft and boom strokes no bearing, and a
bearing's ``beta`` and ``gamma`` stiffness act about the y and z axes respectively.

* **Rigid motion.** A bearing joins the shaft at x to the boom's attachment point, a height h
  above the boom's neutral axis at the same station (docs/design-reference.md, ``offset``). Move
  shaft and boom together as one rigid body, translation t = (0, t_y, t_z) (the boom has no
  axial DOF) and small rotation r = (r_x, r_y, r_z) about the origin on the boom's axis: a point
  p moves by t + r × p. With the package's fields (γ = dv/dx is the rotation about z, β = −dw/dx
  the rotation about y, θ about x) the shaft's axis (y = h) moves by

      u = −r_z h,  v = t_y + r_z x,  w = t_z + r_x h − r_y x,  θ = r_x,  β = r_y,  γ = r_z

  and the boom's axis (y = 0) by v = t_y + r_z x, w = t_z − r_y x, θ = r_x, β = r_y, γ = r_z. The
  two points move together, so every relative displacement (u, v, w, β, γ) of every bearing is
  zero, each rotation taken alone. The rows are sums of a few shape-function values (cubic
  polynomials) times stations of order 1 m: zero to round-off, 1e-12 asserted.
* **A moment bearing at the tip of a cantilever.** A tube clamped at x = 0 with a bearing at its
  free end x = L holding only ``beta`` (k_β, to ground). A tip moment M about y bends the tube
  at constant curvature and turns the spring: β = M/(EI/L + k_β); a tip moment about z meets no
  spring: γ = M L/(EI) (Euler-Bernoulli; the cubic elements are exact for a constant curvature,
  so the finite-element answer equals the closed form to round-off: 1e-9 asserted, the static
  solve's conditioning being about EI/L³ against k_β).

Written for the mutations h33a-bearing-attachment-beta-sign and
h33a-build-bearing-moment-planes-swapped of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from boomed_rotor import shaft_and_boom

from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import loads_design

BOOMED = f"""
name = "shaft on a tapered boom"
{shaft_and_boom(2.0)}[[bearings]]
name = "hanger"
kind = "contact"
x = 0.7
stiffness = {{ u = 1e6, v = 1e7, w = 2e7, beta = 3e4, gamma = 5e4 }}
[[bearings]]
name = "mount"
kind = "contact"
x = 1.55
offset = 0.31
stiffness = {{ v = 1e7, w = 1e7, beta = 1e4, gamma = 1e4 }}
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 5
boom_elements = 3
"""

# (t_y, t_z, r_x, r_y, r_z): one rigid motion at a time
MOTIONS = {
    "translation y": (1.0, 0.0, 0.0, 0.0, 0.0),
    "translation z": (0.0, 1.0, 0.0, 0.0, 0.0),
    "rotation x": (0.0, 0.0, 1.0, 0.0, 0.0),
    "rotation y": (0.0, 0.0, 0.0, 1.0, 0.0),
    "rotation z": (0.0, 0.0, 0.0, 0.0, 1.0),
}


@pytest.fixture(scope="module")
def boomed():
    return build_model(loads_design(BOOMED))


def _rigid(model, h: float, ty: float, tz: float, rx: float, ry: float, rz: float) -> np.ndarray:
    """The rigid motion on the full DOF vector, the shaft's axis at height h above the boom's."""
    dm = model.dofs
    q = np.zeros(dm.size)
    ns, xs = np.arange(dm.n_shaft_nodes), np.asarray(dm.shaft_x, dtype=float)
    nb, xb = np.arange(dm.n_boom_nodes), np.asarray(dm.boom_x, dtype=float)
    shaft = {"u": -rz * h, "v": ty + rz * xs, "w": tz + rx * h - ry * xs, "theta": rx, "beta": ry, "gamma": rz}
    boom = {"v": ty + rz * xb, "w": tz - ry * xb, "theta": rx, "beta": ry, "gamma": rz}
    for f, value in shaft.items():
        q[dm.shaft(ns, f)] = value
    for f, value in boom.items():
        q[dm.boom(nb, f)] = value
    return q


@pytest.mark.parametrize("motion", MOTIONS)
def test_a_rigid_motion_of_shaft_and_boom_strokes_no_bearing(boomed, motion):
    assert len(boomed.bearings) == 2
    for link in boomed.bearings:
        q = _rigid(boomed, link.offset, *MOTIONS[motion])
        assert link.rows @ q == pytest.approx(np.zeros(5), abs=1e-12), link.name


E, DO, WALL, LENGTH = 210e9, 0.06, 0.004, 1.0
EI = E * np.pi * (DO**4 - (DO - 2 * WALL) ** 4) / 64
K_BETA = 0.7 * EI / LENGTH

CANTILEVER = f"""
name = "cantilever with a moment bearing at its tip"
[materials.steel]
kind = "isotropic"
E = {E}
G = 80e9
density = 7800.0
[shaft]
x_start = 0.0
x_end = {LENGTH}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "v", "w", "theta", "beta", "gamma"]
[[bearings]]
name = "tip"
kind = "contact"
x = {LENGTH}
stiffness = {{ beta = {K_BETA} }}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 3
"""


def test_a_beta_bearing_resists_the_moment_about_y_only():
    model = build_model(loads_design(CANTILEVER))
    dm = model.dofs
    tip = dm.node_at("shaft", LENGTH)
    moment = 250.0  # N m
    about_y = static_response(model, point_load(model, "shaft", (0.0, 0.0, 0.0), (0.0, moment, 0.0), x=LENGTH))
    about_z = static_response(model, point_load(model, "shaft", (0.0, 0.0, 0.0), (0.0, 0.0, moment), x=LENGTH))
    assert about_y[dm.shaft(tip, "beta")] == pytest.approx(moment / (EI / LENGTH + K_BETA), rel=1e-9)
    assert about_z[dm.shaft(tip, "gamma")] == pytest.approx(moment * LENGTH / EI, rel=1e-9)
