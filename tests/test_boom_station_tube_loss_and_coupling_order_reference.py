"""Where the assembly attaches a bearing's boom side, how a metal tube's loss enters the loss
stiffness, and couplings listed out of station order, against closed forms derived here.

* **A bearing's boom station.** docs/model.md ("Bearing"): the bearing joins the shaft point at
  x to the boom point at its own boom station (``x_boom``: "Boom station the bearing is mounted
  on [m]; defaults to ``x``", the Bearing docstring, src/flexshaft/design/bearings.py), with the
  attachment kinematics v = v_b, w = w_b + hθ_b. Give the boom alone a rigid rotation φ = 1
  about z (every boom node v_b = x, γ_b = 1; the Hermite shape functions hold it exactly): the
  attachment point moves by v = x_boom, so the bearing's relative v (shaft minus attachment) is
  −x_boom, not −x. A rigid rotation about y (w_b = −x, β_b = 1, docs/model.md: β = −∂w/∂x)
  gives relative w = +x_boom. With a contact spring k_v only, the rigid boom rotation about z
  strains nothing but that spring: qᵀ K q = k_v x_boom².
* **The loss of an isotropic tube.** ``E* = E (1 + iη)``, ``G* = G (1 + iη)`` (the isotropic
  material's ``loss_factor``: "both moduli are complex, E(1 + iη)", its docstring in
  src/flexshaft/design/materials.py), so the shaft's loss stiffness is η times its storage
  stiffness. On the bending field v = x² (v_i = x_i², γ_i = 2 x_i, exact in the cubic Hermite
  element) the curvature is 2 everywhere: qᵀ K_loss q = η E I ∫ 2² dx = 4 η E I L; on the
  twist field θ = x (exact in the linear twist) qᵀ K_loss q = η G J L.
* **Couplings listed aft first.** A tube held in twist at its forward end, two torsionally
  flexible couplings, torque T at the aft end: the springs are in series, so
  θ_aft = −T (L/(G J) + 1/k_1 + 1/k_2) whatever order the design lists them in
  (docs/segmented-driveline.md: each coupling joins the two nodes at its station). The design
  must first be accepted: splitting the shaft in listed order turns the doubled station of the
  aft joint into a zero-length element and refuses this valid design (DesignError, non-finite
  matrices); that refusal, failed explicitly, is what catches the mutation.

Tolerances: the rows are shape-function values of order 1 (1e-12 asserted). qᵀ K q sums
terms q_i K_ij q_j whose largest magnitude is at most about 200 times the result (measured:
boom rotation 4.4e8 to a result of 5.05e7, bending loss 1.1e5 to 584.7, twist loss 489 to
108.6), so its round-off is near 1e-13 relative: 1e-9 relative leaves a wide margin and is
still far below any physical slip. The twist solves the free stiffness matrix (condition
number below 1e8 for this 10-element tube): 1e-9 relative (the same statics as
tests/test_segments.py's chain test, whose tolerance this is).

Written for the mutations h54c-build-bearing-boom-side-at-shaft-station,
h54c-build-metal-bending-loss-dropped and h54c-build-couplings-split-unsorted of
scripts/mutations.toml.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from boomed_rotor import shaft_and_boom

from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import torque_load
from flexshaft.design import DesignError, design_from_dict, loads_design

E_AL, G_AL, ETA = 70.0e9, 26.0e9, 0.012
D_O, WALL = 0.05, 0.002
D_I = D_O - 2 * WALL
I_AREA = math.pi * (D_O**4 - D_I**4) / 64
J_POLAR = math.pi * (D_O**4 - D_I**4) / 32

X_SHAFT, X_BOOM, K_V = 0.7, 1.2, 1.0e7

BOOMED = f"""
name = "bearing with its own boom station"
{shaft_and_boom(2.5)}[[bearings]]
name = "hanger"
kind = "contact"
x = {X_SHAFT}
x_boom = {X_BOOM}
stiffness = {{ v = {K_V} }}
[[bearings]]
name = "aft"
kind = "contact"
x = 1.9
stiffness = {{ v = 1e7, w = 1e7 }}
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 5
boom_elements = 4
"""


def _boom_rotation(model, axis: str) -> np.ndarray:
    """Full vector of a unit rigid rotation of the boom alone about ``axis`` ("y" or "z")."""
    dm = model.dofs
    nodes = np.arange(dm.n_boom_nodes)
    q = np.zeros(dm.size)
    if axis == "z":
        q[dm.boom(nodes, "v")] = dm.boom_x
        q[dm.boom(nodes, "gamma")] = 1.0
    else:
        q[dm.boom(nodes, "w")] = -dm.boom_x
        q[dm.boom(nodes, "beta")] = 1.0
    return q


@pytest.fixture(scope="module")
def boomed():
    return build_model(loads_design(BOOMED))


def test_the_boom_side_of_a_bearing_sits_at_its_boom_station(boomed):
    link = next(b for b in boomed.bearings if b.name == "hanger")
    about_z = link.rows @ _boom_rotation(boomed, "z")  # (u, v, w, beta, gamma)
    about_y = link.rows @ _boom_rotation(boomed, "y")
    assert about_z[1] == pytest.approx(-X_BOOM, rel=1e-12)
    assert about_y[2] == pytest.approx(X_BOOM, rel=1e-12)


def test_the_contact_spring_is_strained_at_the_boom_station(boomed):
    """Only the hanger's k_v sees the rigid boom rotation about z (the aft bearing sits at its
    own station 1.9 m: its v spring adds k (1.9)²; the boom elements strain nothing)."""
    q = _boom_rotation(boomed, "z")
    energy = q @ (boomed.K @ q)
    assert energy == pytest.approx(K_V * X_BOOM**2 + 1.0e7 * 1.9**2, rel=1e-9)


def _tube(**extra) -> dict:
    data = {
        "name": "metal tube",
        "materials": {"al": {"kind": "isotropic", "E": E_AL, "G": G_AL, "density": 2700.0, "loss_factor": ETA}},
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": D_O,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": 2.0, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 4},
    }
    data.update(extra)
    return data


def test_a_metal_tube_loses_eta_of_its_bending_and_twist_energy():
    model = build_model(design_from_dict(_tube()))
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    x = dm.shaft_x
    bend = np.zeros(dm.size)
    bend[dm.shaft(nodes, "v")] = x**2
    bend[dm.shaft(nodes, "gamma")] = 2 * x
    twist = np.zeros(dm.size)
    twist[dm.shaft(nodes, "theta")] = x
    loss = model.shaft_loss_stiffness
    assert bend @ (loss @ bend) == pytest.approx(4 * ETA * E_AL * I_AREA * 2.0, rel=1e-9)
    assert twist @ (loss @ twist) == pytest.approx(ETA * G_AL * J_POLAR * 2.0, rel=1e-9)


def test_couplings_listed_aft_first_still_sum_their_compliances():
    k_t = {0.6: 4.0e4, 1.5: 9.0e4}
    couplings = [  # aft first
        {"name": f"c{x}", "x": x, "angular_stiffness": 500.0, "axial_stiffness": "rigid", "torsional_stiffness": k}
        for x, k in sorted(k_t.items(), reverse=True)
    ]
    design = design_from_dict(_tube(couplings=couplings, mesh={"shaft_elements": 10}))
    try:
        model = build_model(design)
    except DesignError as e:
        pytest.fail(f"a valid design listing its couplings aft first was refused: {e}")
    dm = model.dofs
    for link in model.couplings:
        assert dm.shaft_x[link.node_a] == pytest.approx(link.x, abs=1e-12)
        assert dm.shaft_x[link.node_b] == pytest.approx(link.x, abs=1e-12)
    assert sorted(link.x for link in model.couplings) == pytest.approx(sorted(k_t), abs=1e-12)
    torque = 100.0
    q = static_response(model, torque_load(model, torque), speed=0.0)
    compliance = 2.0 / (G_AL * J_POLAR) + sum(1.0 / k for k in k_t.values())
    assert q[dm.shaft(-1, "theta")] == pytest.approx(-torque * compliance, rel=1e-9)
