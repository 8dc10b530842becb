"""Omitted design keys add nothing, and a speed given in rad/s reads back in rev/min.

A design file's optional keys default to "nothing there" (docs/model.md: the shaft ends are
constrained in the DOFs listed in ``shaft.fixed_start`` / ``shaft.fixed_end``; the end mass and
the point loads carry what the file gives them). References, derived here:

* **No fixed_start, no held twist.** The shaft's torsion stiffness is that of a chain of
  elements GJ/L_e whose rows sum to zero, so a uniform twist θ = 1 on every shaft node carries
  no strain energy: K_ff t = 0 on the free DOFs. Holding θ at the forward node (what a default
  ``["theta"]`` would do) removes that node from the free set and the first free row becomes
  2k − k = k ≠ 0.
* **An end mass without inertia is a point mass.** At zero offset from the tip node its kinetic
  energy is m (v̇² + ẇ²)/2 on the tip's translations only (the boom's node has
  (v, w, θ, β, γ)), so the model with it minus the model without it is diag(m, m, 0, 0, 0) on
  the tip node and zero elsewhere.
* **A point load without moment is a force.** Its consistent load vector's rigid-motion sums
  (the Hermite shape functions reproduce rigid motion exactly) are the resultant Σ Q_v = F_y
  and the first moment about z through x = 0, Σ (Q_v x + Q_γ) = F_y x_F (γ = ∂v/∂x,
  docs/model.md), and about the shaft axis Σ Q_θ = 0.
* **rad/s to rev/min.** n = Ω · 60/(2π): 500 rad/s is 4774.648 rev/min.

Tolerances: the stiffness rows are sums of a few entries of size GJ/L_e, so their cancellation
leaves ~1e-16 of that scale: atol 1e-9 × max |K_θθ|, far above rounding and far below the k of
a held node. The mass difference carries one rounding of m (atol 1e-12 m). The load sums are a
dozen products of O(1e2) numbers: rel 1e-12 (atol 1e-9 N m for the zero twist sum). The unit
conversion is one product: rel 1e-12. CPU: two 4-element models, a few ms each.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load
from flexshaft.design import loads_design
from flexshaft.design.loads import Operating

L, D_O, WALL, END_MASS = 1.2, 0.06, 0.002, 7.5
X_F, F_Y = 0.45, -120.0  # point load station [m] and its y force [N]

END_MASS_BLOCK = f"""
[tailboom.end_mass]
mass = {END_MASS}
offset = [0.0, 0.0, 0.0]
"""

TEXT = f"""
name = "omitted keys"
[materials.al]
kind = "isotropic"
E = 70e9
G = 26e9
density = 2700.0
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {D_O}
wall_thickness = {WALL}
material = "al"
fixed_end = ["u"]
[[bearings]]
name = "near"
kind = "contact"
x = 0.0
stiffness = {{ v = 1e8, w = 1e8 }}
[[bearings]]
name = "far"
kind = "contact"
x = {L}
stiffness = {{ v = 1e8, w = 1e8 }}
[tailboom]
length = {L + 0.3}
root_semi_axes = [0.15, 0.12]
tip_semi_axes = [0.08, 0.07]
wall_thickness = 0.002
material = "al"
shaft_clearance = 0.05
{END_MASS_BLOCK}
[operating]
speed_rpm = 0.0
power = 0.0
[[loads.point]]
name = "hanger"
on = "shaft"
x = {X_F}
force = [0.0, {F_Y}, 0.0]
[mesh]
shaft_elements = 4
boom_elements = 3
"""


@pytest.fixture(scope="module")
def model():
    return build_model(loads_design(TEXT))


def test_a_shaft_without_fixed_start_is_free_in_twist(model):
    dm = model.dofs
    theta = np.atleast_1d(dm.shaft(np.arange(dm.n_shaft_nodes), "theta"))
    free = np.asarray(dm.free)
    K = model.K.tocsr()[free][:, free].toarray()
    twist = np.isin(free, theta).astype(float)  # θ = 1 on every free shaft twist, 0 elsewhere
    scale = np.abs(K[np.ix_(twist > 0, twist > 0)]).max()
    np.testing.assert_allclose(K @ twist, 0.0, rtol=0, atol=1e-9 * scale)
    assert np.isin(theta, free).all()  # and that is every shaft node's twist: none is held


def test_an_end_mass_without_inertia_is_a_point_mass(model):
    without = build_model(loads_design(TEXT.replace(END_MASS_BLOCK, "")))
    dm = model.dofs
    assert dm.size == without.dofs.size
    tip = [dm.boom(-1, f) for f in ("v", "w", "theta", "beta", "gamma")]
    expected = np.zeros((dm.size, dm.size))
    expected[tip, tip] = [END_MASS, END_MASS, 0.0, 0.0, 0.0]
    added = (model.M - without.M).toarray()
    np.testing.assert_allclose(added, expected, rtol=0, atol=1e-12 * END_MASS)


def test_a_point_load_without_moment_is_its_force_alone(model):
    dm = model.dofs
    Q = external_static_load(model)
    nodes = np.arange(dm.n_shaft_nodes)
    x = np.asarray(dm.shaft_x, dtype=float)
    v, gamma = Q[dm.shaft(nodes, "v")], Q[dm.shaft(nodes, "gamma")]
    assert v.sum() == pytest.approx(F_Y, rel=1e-12)
    assert (v * x).sum() + gamma.sum() == pytest.approx(F_Y * X_F, rel=1e-12)
    assert Q[dm.shaft(nodes, "theta")].sum() == pytest.approx(0.0, abs=1e-9)
    w, beta = Q[dm.shaft(nodes, "w")], Q[dm.shaft(nodes, "beta")]
    assert np.abs(w).max() == 0.0 and np.abs(beta).max() == 0.0  # nothing in the x–z plane


def test_a_speed_in_rad_s_reads_back_in_rev_min():
    operating = Operating(speed=500.0, power=1.0e4)
    assert operating.rpm == pytest.approx(500.0 * 60.0 / (2.0 * math.pi), rel=1e-12)
    assert operating.rpm == pytest.approx(4774.648, rel=1e-7)
    assert Operating(speed_rpm=4800.0, power=1.0e4).rpm == 4800.0  # as written
