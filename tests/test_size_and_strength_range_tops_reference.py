"""The tops of the size and strength ranges: a design at each documented top is accepted and built.

docs/limits.md, section 1 (hand-written), gives the range of every number of the schema:

* "| `Station` | `x`, `x_start`, `x_end`, `x_boom`, load stations | ±1000 m | a tail-rotor
  driveline is under 20 m, the longest line shafts about 100 m; ...";
* "| `Diameter` | `outer_diameter` | 1 mm to 10 m | from a spindle to ten times the largest
  marine shaft |";
* "| `Strength` | `X_t`, `X_c`, `Y_t`, `Y_c`, `S` | 1 kPa to 100 GPa | up to the ideal strength
  of graphene (carbon fibres reach 7 GPa) |".

Each top is exercised with a result that follows from it by hand, so that the test checks the
value is used, not only let through:

* **A 2000 m line shaft from x = −1000 m to +1000 m** (steel, D_o = 0.5 m, wall 20 mm, 8
  elements) has its mesh ends at ±1000 m exactly and the tube mass
  m = ρ π (D_o² − D_i²)/4 · L, D_i = D_o − 2t (derived here). Its diameter is well inside
  the diameter range (below 1 m too), so this test exercises the station top alone.
* **A 10 m diameter tube** (steel, wall 0.1 m, 20 m long) has the same tube mass by hand.
* **A ply of 100 GPa strengths** X_t = X_c = 1e11 Pa: with equal tensile and compressive
  strengths F1 = 1/X_t − 1/X_c = 0 and F11 = 1/(X_t X_c) = 1/X² (Tsai-Wu, Jones 1999 eq. 2.159
  as quoted in flexshaft/strength.py), so a uniaxial fibre stress σ1 alone gives
  F11 (R σ1)² = 1, R = X/σ1: 100 at σ1 = 1 GPa.

Tolerances: the masses and R are a handful of products and one square root of doubles, a few
ulp; rel 1e-12 is far above that and far below any change of the inputs (the mesh ends are
copied stations and compared to 1e-12 m for the same reason). Each test builds at most an
8-element model: milliseconds of CPU.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict
from flexshaft.design.materials import Lamina
from flexshaft.strength import datasheet_strengths, tsai_wu_safety_factor

STEEL = {"kind": "isotropic", "E": 210.0e9, "G": 80.0e9, "density": 7800.0}


def tube(x_start: float, x_end: float, outer: float, wall: float) -> dict:
    """A steel tube on two contact bearings at its ends, 8 elements, at rest with no power."""
    return {
        "name": "range tops",
        "materials": {"steel": STEEL},
        "shaft": {
            "x_start": x_start,
            "x_end": x_end,
            "outer_diameter": outer,
            "wall_thickness": wall,
            "material": "steel",
            "fixed_start": ["u", "theta"],
        },
        "bearings": [
            {"name": "fore", "kind": "contact", "x": x_start, "stiffness": {"v": 1e7, "w": 1e7}},
            {"name": "aft", "kind": "contact", "x": x_end, "stiffness": {"v": 1e7, "w": 1e7}},
        ],
        "operating": {"speed_rpm": 0.0, "power": 0.0},
        "mesh": {"shaft_elements": 8},
    }


def tube_mass(outer: float, wall: float, length: float) -> float:
    inner = outer - 2.0 * wall
    return STEEL["density"] * math.pi * (outer**2 - inner**2) / 4.0 * length


def test_a_line_shaft_from_minus_to_plus_1000_m_is_built_with_its_stations():
    model = build_model(design_from_dict(tube(-1000.0, 1000.0, 0.5, 0.02)))
    x = np.asarray(model.dofs.shaft_x)
    assert x[0] == pytest.approx(-1000.0, abs=1e-12)
    assert x[-1] == pytest.approx(1000.0, abs=1e-12)
    assert model.shaft_mass == pytest.approx(tube_mass(0.5, 0.02, 2000.0), rel=1e-12)


def test_a_10_m_diameter_tube_is_built_with_its_mass():
    design = design_from_dict(tube(0.0, 20.0, 10.0, 0.1))
    assert design.shaft.outer_diameter == 10.0
    model = build_model(design)
    assert model.shaft.outer_diameter == pytest.approx(10.0, rel=1e-12)
    assert model.shaft_mass == pytest.approx(tube_mass(10.0, 0.1, 20.0), rel=1e-12)


def test_a_ply_of_100_gpa_strengths_fails_at_its_strength():
    top = 1e11
    lamina = Lamina.model_validate(
        {
            "kind": "lamina",
            "density": 1600.0,
            "E_L": 140e9,
            "E_T": 10e9,
            "G_LT": 5e9,
            "nu_LT": 0.3,
            "X_t": top,
            "X_c": top,
            "Y_t": top,
            "Y_c": top,
            "S": top,
        }
    )
    assert (lamina.X_t, lamina.X_c, lamina.S) == (top, top, top)
    sigma1 = 1e9
    R = tsai_wu_safety_factor(sigma1, 0.0, 0.0, datasheet_strengths(lamina))
    assert float(R) == pytest.approx(top / sigma1, rel=1e-12)
