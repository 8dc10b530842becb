"""Load vectors of :mod:`flexshaft.assembly.loads` against statics written by hand.

A consistent nodal load vector Q is the virtual work of the load on the shape functions:
``Q · δq = ∫ f · δu``. The Hermite cubics (and the linear axial/twist functions) reproduce rigid
motion exactly, so for a rigid translation δv = 1 (every node's v = 1, rotations 0) ``Σ Q_v`` is
the load's resultant, and for a rigid turn about z through x = 0 (v = x, γ = dv/dx = 1,
docs/model.md) ``Σ (Q_v x + Q_γ)`` is its first moment about the z axis. These two sums are
checked against the load's resultant and moment computed here by hand:

* a load factor n [g] on every mass: resultant m n g with m the tube's ρ π (r_o² − r_i²) L, the
  boom's ρ t ∮ds along the taper (∮ds = 4a E(1 − b²/a²), the complete elliptic integral,
  scipy.special.ellipe) plus the end mass; g = 9.80665 m/s², the standard acceleration of
  gravity (3rd CGPM, 1901). Translational inertia is isotropic: a vertical factor loads the boom
  vertically only and a lateral one laterally with the same resultant;
* a uniform line load q between x₁ and x₂ (not on element ends): resultant q (x₂ − x₁), moment
  q (x₂² − x₁²)/2;
* the design imbalance, mid-bay (ISO 21940-11: F = e_c m Ω², m the whole rotor; per unit Ω²
  here): one bay between bearings at both ends, resultant e_c m and moment e_c m L/2 (the
  force at mid-bay), Q_w = −i Q_v (a forward-rotating force, the module's convention);
* a bay's own unbalance U e^{iψ} at a fraction p of the bay: resultant U e^{iψ}, moment
  U e^{iψ} p L.

A point moment about y bends the beam in the x–z plane only (w, β), never in x–y (v, γ): the
tube is axisymmetric, so the two bending planes decouple exactly; with the moment at midspan of
a beam on symmetric supports the deflection is antisymmetric about midspan.

Tolerance: the sums are a few dozen products of O(1) numbers and the boom's perimeter and
integral along the taper are exact to ~1e-13 (quad, epsrel 1e-13; the element's Gauss rule is
exact to ~1e-12 on the smooth taper): rel 1e-9. A 10-element shaft and a 4-element boom
suffice, since the identities hold at any mesh (CPU budget).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import ellipe

from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads, inertial_load, line_load, per_bay_imbalance_loads, point_load
from flexshaft.design import loads_design

G0 = 9.80665  # m/s², standard gravity (3rd CGPM 1901)
L, D_O, WALL, RHO = 2.0, 0.05, 0.002, 2700.0
BOOM_L, ROOT, TIP, BOOM_T, RHO_BOOM, END_MASS = 3.0, (0.20, 0.15), (0.10, 0.08), 0.002, 2800.0, 12.0
ECC = 3.0e-5

TEXT = f"""
name = "load vectors by hand"
[materials.al]
kind = "isotropic"
E = 70e9
G = 26e9
density = {RHO}
[materials.boom]
kind = "isotropic"
E = 71e9
G = 27e9
density = {RHO_BOOM}
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {D_O}
wall_thickness = {WALL}
material = "al"
fixed_start = ["u", "theta"]
[[bearings]]
name = "near"
kind = "contact"
x = 0.0
stiffness = {{ v = 1e9, w = 1e9 }}
[[bearings]]
name = "far"
kind = "contact"
x = {L}
stiffness = {{ v = 1e9, w = 1e9 }}
[operating]
speed_rpm = 3000.0
power = 0.0
[loads]
eccentricity = {ECC}
[mesh]
shaft_elements = 10
boom_elements = 4
"""

BOOM = f"""
[tailboom]
length = {BOOM_L}
root_semi_axes = [{ROOT[0]}, {ROOT[1]}]
tip_semi_axes = [{TIP[0]}, {TIP[1]}]
wall_thickness = {BOOM_T}
material = "boom"
shaft_clearance = 0.05
[tailboom.end_mass]
mass = {END_MASS}
offset = [0.0, 0.0, 0.0]
inertia = [0.5, 0.5, 0.5]
"""


@pytest.fixture(scope="module")
def tube():
    """The pinned aluminium tube alone."""
    return build_model(loads_design(TEXT))


@pytest.fixture(scope="module")
def boomed():
    """The same tube on a tapered elliptical tailboom with an end mass."""
    return build_model(loads_design(TEXT + BOOM))


def tube_mass() -> float:
    return RHO * math.pi * (D_O**2 - (D_O - 2 * WALL) ** 2) / 4 * L


def boom_mass() -> float:
    def perimeter(x):
        s = x / BOOM_L
        a, b = (1 - s) * ROOT[0] + s * TIP[0], (1 - s) * ROOT[1] + s * TIP[1]
        return 4 * a * ellipe(1 - (b / a) ** 2)  # a ≥ b

    return RHO_BOOM * BOOM_T * quad(perimeter, 0.0, BOOM_L, epsabs=0, epsrel=1e-13)[0]


def shaft_sums(model, Q, plane: str = "v"):
    """(resultant, first moment about x = 0) of Q's shaft components in the x–y plane (v, γ)
    or x–z plane (w, −β: a rigid turn w = x has β = −dw/dx = −1)."""
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    x = np.asarray(dm.shaft_x, dtype=float)
    if plane == "v":
        force, rotation = Q[dm.shaft(nodes, "v")], Q[dm.shaft(nodes, "gamma")]
    else:
        force, rotation = Q[dm.shaft(nodes, "w")], -Q[dm.shaft(nodes, "beta")]
    return force.sum(), (force * x).sum() + rotation.sum()


def boom_sum(model, Q, field: str) -> float:
    dm = model.dofs
    return float(Q[dm.boom(np.arange(dm.n_boom_nodes), field)].sum())


@pytest.mark.parametrize("factor", [(0.0, -3.5, 0.0), (0.0, 0.0, 2.0)])
def test_a_load_factor_loads_each_member_with_its_mass_times_n_g(boomed, factor):
    Q = inertial_load(boomed, factor)
    _, n_y, n_z = factor
    shaft_y, _ = shaft_sums(boomed, Q, "v")
    shaft_z, _ = shaft_sums(boomed, Q, "w")
    assert shaft_y == pytest.approx(tube_mass() * n_y * G0, rel=1e-9, abs=1e-9)
    assert shaft_z == pytest.approx(tube_mass() * n_z * G0, rel=1e-9, abs=1e-9)
    boom = boom_mass() + END_MASS
    assert boom_sum(boomed, Q, "v") == pytest.approx(boom * n_y * G0, rel=1e-9, abs=1e-9)
    assert boom_sum(boomed, Q, "w") == pytest.approx(boom * n_z * G0, rel=1e-9, abs=1e-9)


def test_a_uniform_line_load_has_the_resultant_and_moment_of_q_over_its_span(tube):
    q, x1, x2 = 150.0, 0.5, 1.3  # N/m; both ends inside elements of 0.2 m
    resultant, moment = shaft_sums(tube, line_load(tube, "shaft", x1, x2, (0.0, q, 0.0)), "v")
    assert resultant == pytest.approx(q * (x2 - x1), rel=1e-9)
    assert moment == pytest.approx(q * (x2**2 - x1**2) / 2, rel=1e-9)


def test_a_moment_about_y_bends_the_tube_in_the_x_z_plane_only(tube):
    response = static_response(tube, point_load(tube, "shaft", (0.0, 0.0, 0.0), (0.0, 40.0, 0.0), x=L / 2))
    dm = tube.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    w, v = response[dm.shaft(nodes, "w")], response[dm.shaft(nodes, "v")]
    assert np.abs(w).max() > 0.0
    assert np.abs(v).max() <= 1e-12 * np.abs(w).max()
    # antisymmetric about midspan (symmetric supports, a couple at midspan); nodes at x and L − x
    np.testing.assert_allclose(w, -w[::-1], rtol=0, atol=1e-9 * np.abs(w).max())


def test_the_mid_bay_imbalance_is_e_m_at_midspan_turning_forward(tube):
    (Q,) = imbalance_loads(tube, "mid_bay").T
    force = ECC * tube_mass()
    resultant, moment = shaft_sums(tube, Q, "v")
    assert resultant == pytest.approx(force, rel=1e-9)
    assert moment == pytest.approx(force * L / 2, rel=1e-9)
    resultant_w, moment_w = shaft_sums(tube, Q, "w")
    assert resultant_w == pytest.approx(-1j * force, rel=1e-9)
    assert moment_w == pytest.approx(-1j * force * L / 2, rel=1e-9)


def test_a_bays_unbalance_acts_at_its_fraction_from_the_forward_bearing(tube):
    U, psi, p = 2.0e-3, 0.7, 0.3
    Q = per_bay_imbalance_loads(tube, U, psi, p)
    amplitude = U * complex(math.cos(psi), math.sin(psi))
    resultant, moment = shaft_sums(tube, Q, "v")
    assert resultant == pytest.approx(amplitude, rel=1e-9)
    assert moment == pytest.approx(amplitude * p * L, rel=1e-9)
    resultant_w, _ = shaft_sums(tube, Q, "w")
    assert resultant_w == pytest.approx(-1j * amplitude, rel=1e-9)
