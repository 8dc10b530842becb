"""Static load vectors of the assembly against their resultants, summed by hand.

A consistent load vector Q does the virtual work of the applied loads on every rigid motion the
shape functions reproduce exactly (the cubic Hermite v, w and the linear θ hold any rigid
translation and rotation). With the DOF convention of docs/model.md ("γ = ∂v/∂x,
β = −∂w/∂x"), a rigid rotation φ about z is v = x φ, γ = φ, and about y is w = −x φ, β = φ,
so (derived here)::

    Σ Q_v = F_y,   Σ (x_i Q_v,i + Q_γ,i) = ∫ x dF_y + M_z,
    Σ Q_w = F_z,   Σ (Q_β,i − x_i Q_w,i) = M_y − ∫ x dF_z,      Σ Q_θ = M_x

over the shaft nodes i at stations x_i. The right-hand sides are hand sums of the loads.

* **A line load over part of an element** (q over [0.6, 0.8] m inside the element [0.5, 1.0] m):
  F_y = q · 0.2 and its first moment q (0.8² − 0.6²)/2 = 0.14 q about x = 0 (centroid 0.7 m,
  not the element's 0.75 m).
* **The design's point load with a moment** (``[[loads.point]]``, read by
  ``external_static_load``): F = (0, F_y, F_z) and M = (M_x, M_y, M_z) at x_p.
* **The tail rotor's torque behind an elastic drive** (docs/model.md, "Torsional ends": the
  mean torque acts on the rotor's DOF): with the forward twist held, the shaft a torsion spring
  k_s = G J/L and the drive k_r in series, the statics of two springs give
  θ_aft = −T/k_s and θ_rotor = −T (1/k_s + 1/k_r) (derived here).

Tolerances: the resultants are sums of a few dozen terms of size 1 to 100, exact up to
round-off, asserted to 1e-12 relative. The torsion statics solve the free stiffness matrix,
condition number 2.3e5 (measured; bending against the 2.26e3 N m/rad twist springs), so
round-off is below 1e-10: asserted to 1e-9 relative.

Written for the mutations h53a-line-load-whole-element, h53a-point-load-moment-dropped and
h53a-torque-on-shaft-end-not-rotor of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load, line_load, torque_load
from flexshaft.design import design_from_dict

LENGTH, DO, WALL = 2.0, 0.05, 0.002
G_MOD = 26.0e9


def _design(**extra) -> dict:
    data = {
        "name": "load resultants",
        "materials": {"al": {"kind": "isotropic", "E": 70.0e9, "G": G_MOD, "density": 2700.0, "loss_factor": 0.0}},
        "shaft": {
            "x_start": 0.0,
            "x_end": LENGTH,
            "outer_diameter": DO,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": LENGTH, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 50.0e3},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 4},
    }
    data.update(extra)
    return data


def _resultants(model, Q) -> dict:
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    x = dm.shaft_x
    part = {f: Q[dm.shaft(nodes, f)] for f in ("v", "w", "theta", "beta", "gamma")}
    return {
        "Fy": part["v"].sum(),
        "Fz": part["w"].sum(),
        "Mx": part["theta"].sum(),
        "Mz_about_0": (x * part["v"]).sum() + part["gamma"].sum(),
        "My_about_0": part["beta"].sum() - (x * part["w"]).sum(),
    }


def test_a_line_load_inside_one_element_keeps_its_centroid():
    model = build_model(design_from_dict(_design()))
    np.testing.assert_allclose(model.dofs.shaft_x, [0.0, 0.5, 1.0, 1.5, 2.0], atol=1e-15)
    q = 40.0  # N/m along y
    r = _resultants(model, line_load(model, "shaft", 0.6, 0.8, (0.0, q, 0.0)))
    assert r["Fy"] == pytest.approx(q * 0.2, rel=1e-12)
    assert r["Mz_about_0"] == pytest.approx(q * (0.8**2 - 0.6**2) / 2, rel=1e-12)


def test_the_design_point_load_carries_its_moment():
    F, M, xp = (0.0, 30.0, -20.0), (7.0, 5.0, -11.0), 1.3
    point = {"name": "p", "on": "shaft", "x": xp, "force": list(F), "moment": list(M)}
    model = build_model(design_from_dict(_design(loads={"eccentricity": 0.0, "point": [point]})))
    r = _resultants(model, external_static_load(model))
    assert r["Fy"] == pytest.approx(F[1], rel=1e-12)
    assert r["Fz"] == pytest.approx(F[2], rel=1e-12)
    assert r["Mx"] == pytest.approx(M[0], rel=1e-12)
    assert r["Mz_about_0"] == pytest.approx(M[2] + xp * F[1], rel=1e-12)
    assert r["My_about_0"] == pytest.approx(M[1] - xp * F[2], rel=1e-12)


def test_the_rotor_torque_acts_behind_the_elastic_drive():
    k_r = 2.0e3  # N m/rad, the drive at the shaft side (input stiffness, no hub spring)
    rotor = {"blades": 4, "polar_inertia": 1.0, "gearbox_ratio": 2.0, "input_stiffness": k_r}
    model = build_model(design_from_dict(_design(tail_rotor=rotor)))
    assert model.drive.elastic_rotor
    torque = 100.0
    q = static_response(model, torque_load(model, torque), speed=0.0)
    J = math.pi * (DO**4 - (DO - 2 * WALL) ** 4) / 32
    k_s = G_MOD * J / LENGTH
    aft = model.dofs.shaft(-1, "theta")
    rotor_dof = model.dofs.extra_dof("tail_rotor")
    assert q[aft] == pytest.approx(-torque / k_s, rel=1e-9)
    assert q[rotor_dof] == pytest.approx(-torque * (1 / k_s + 1 / k_r), rel=1e-9)
