"""Edges of the design schema where a physical argument, not a convention, sets the limit.

* **A segment's bore.** A tube of outer diameter D_o and wall t has the bore D_i = D_o − 2t,
  which must be positive: t < D_o/2 for every zone of a segmented shaft as for ``[shaft]``. A
  segment of D_o = 30 mm with t = 15 mm (D_i = 0) or 16 mm (D_i = −2 mm) is refused, with
  t = 14 mm (D_i = 2 mm) accepted, and its built tube has D_i = 2 mm and the mass
  ρ π (D_o² − D_i²)/4 · L by hand.
* **A ply's major Poisson ratio above ½.** Only the positive definiteness of the ply's compliance
  bounds ν_LT: ν_LT < √(E_L/E_T) (Jones, Mechanics of Composite Materials, 1999, restrictions
  on the elastic constants; tests/test_schema_bounds_reference.py). The isotropic bound ν < ½
  does not apply to an orthotropic ply, so with E_L/E_T = 15 a ν_LT of 0.7 and of 1.0 (the
  schema's documented top, docs/limits.md) are accepted.
* **A rigid support.** The bearing stiffness range reaches 1e12 N/m, documented as rigid for
  any shaft. A steel tube (D_o = 50 mm, wall 5 mm, L = 1 m) on two such bearings at its ends is
  simply supported: a mid-span force P deflects it by δ = P L³/(48 E I) (Euler-Bernoulli; the
  cubic elements are exact for a point load at a node). Each spring adds P/(2 k_b) under its
  reaction, 1e-6 of δ here, and the static solve loses about eps · k_b L³/(E I) ≈ 1e-8: 1e-5
  relative asserted. A 60-DOF static solve, cheap.

Written for the mutations h35c-comp-segment-wall-against-diameter, h35c-q-poisson-at-most-half
and h35c-q-stiffness-cap-1e9 of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, design_from_dict
from flexshaft.design.materials import Lamina

AL = {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0}
STEEL = {"kind": "isotropic", "E": 210.0e9, "G": 80.0e9, "density": 7800.0}


def tube(segments=(), material="al", length=2.0, outer=0.05, wall=0.002, bearings=None, elements=8) -> dict:
    shaft = {
        "x_start": 0.0,
        "x_end": length,
        "outer_diameter": outer,
        "wall_thickness": wall,
        "material": material,
        "fixed_start": ["u", "theta"],
    }
    if segments:
        shaft["segments"] = list(segments)
    return {
        "name": "range edges",
        "materials": {"al": AL, "steel": STEEL},
        "shaft": shaft,
        "bearings": bearings
        or [
            {"name": "fore", "kind": "contact", "x": 0.0, "stiffness": {"v": 1e7, "w": 1e7}},
            {"name": "aft", "kind": "contact", "x": length, "stiffness": {"v": 1e7, "w": 1e7}},
        ],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "mesh": {"shaft_elements": elements},
    }


def _segments(wall: float) -> list[dict]:
    return [
        {"name": "a", "x_start": 0.0, "x_end": 1.0},
        {"name": "b", "x_start": 1.0, "x_end": 2.0, "outer_diameter": 0.03, "wall_thickness": wall},
    ]


@pytest.mark.parametrize("wall", [0.015, 0.016])
def test_a_segment_without_a_bore_is_refused(wall):
    with pytest.raises(DesignError, match=r"segments\[1\]\.wall_thickness: must be less than outer_diameter/2"):
        design_from_dict(tube(_segments(wall)))


def test_a_segment_with_a_thin_bore_is_built_with_it():
    model = build_model(design_from_dict(tube(_segments(0.014))))
    segment = model.segments[1].properties
    assert segment.inner_diameter == pytest.approx(0.002, rel=1e-12)
    mass = 2700.0 * math.pi * (0.03**2 - 0.002**2) / 4 * 1.0
    assert model.segments[1].mass == pytest.approx(mass, rel=1e-12)


@pytest.mark.parametrize("nu", [0.7, 1.0])
def test_a_ply_poisson_ratio_above_one_half_is_accepted(nu):
    ply = {
        "kind": "lamina",
        "density": 1500.0,
        "E_L": 150e9,
        "E_T": 10e9,
        "G_LT": 5e9,
        "nu_LT": nu,
        "X_t": 1e9,
        "X_c": 8e8,
        "Y_t": 4e7,
        "Y_c": 1e8,
        "S": 5e7,
    }
    assert nu < math.sqrt(150e9 / 10e9)
    assert Lamina.model_validate(ply).nu_LT == nu


def test_bearings_at_the_rigid_top_of_the_range_simply_support_the_shaft():
    rigid = {"v": 1e12, "w": 1e12}
    bearings = [
        {"name": "fore", "kind": "contact", "x": 0.0, "stiffness": rigid},
        {"name": "aft", "kind": "contact", "x": 1.0, "stiffness": rigid},
    ]
    model = build_model(
        design_from_dict(tube(material="steel", length=1.0, wall=0.005, bearings=bearings, elements=10))
    )
    dm = model.dofs
    free = dm.free
    load = np.zeros(dm.size)
    mid = dm.shaft(dm.node_at("shaft", 0.5), "v")
    load[mid] = 1e3
    q = np.zeros(dm.size)
    q[free] = np.linalg.solve(model.K[free][:, free].toarray(), load[free])
    inertia = math.pi * (0.05**4 - 0.04**4) / 64
    assert q[mid] == pytest.approx(1e3 * 1.0**3 / (48 * 210e9 * inertia), rel=1e-5)
