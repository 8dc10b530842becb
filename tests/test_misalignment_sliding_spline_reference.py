"""A sliding (axially free) coupling slides without force; a missing allowable angle stays unset.

Two aluminium tubes joined at x = a by a coupling of axial stiffness 0 (a sliding spline), each
held axially at its outer end (x = 0 and x = L). An axial force P at ξ₂ on the aft tube
(a < ξ₂ < L) goes to the aft end only: the aft tube's part from ξ₂ to L is compressed by P,
the part from a to ξ₂ carries nothing, so its flange moves by u_b = P (L − ξ₂)/(E A) with
A = π (D² − d²)/4 (a bar under an end load, statics); the forward tube carries nothing, u_a = 0. The
coupling's axial offset is Δu = u_b − u_a = P (L − ξ₂)/(E A) and its axial force k_ax Δu is
exactly 0: a free direction is flexible with zero stiffness (a number, not the NaN of a rigid
direction, :mod:`flexshaft.analyses.misalignment`). The rigid torsional direction reports NaN.
A coupling without ``allowable_angle_deg`` has no allowable angle (NaN, "not given"), not 0.

The linear bar element is exact for nodal point loads: tolerance 1e-9 relative (round-off of
the assembled solve). One 20-element static solve: about 0.1 s.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.misalignment import coupling_misalignment
from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import design_from_dict

A, L, XI2, P = 0.8, 2.0, 1.5, 1000.0
E, D, WALL = 70.0e9, 0.05, 0.002


@pytest.fixture(scope="module")
def spline():
    data = {
        "name": "sliding spline",
        "materials": {"al": {"kind": "isotropic", "E": E, "G": 26.0e9, "density": 2700.0}},
        "shaft": {
            "x_start": 0.0,
            "x_end": L,
            "outer_diameter": D,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["u", "v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": L, "stiffness": {"u": 0.0}}],
        "couplings": [
            {
                "name": "spline",
                "x": A,
                "angular_stiffness": 100.0,
                "axial_stiffness": 0.0,
                "torsional_stiffness": "rigid",
            }
        ],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 20},
    }
    return build_model(design_from_dict(data))


def test_a_sliding_spline_slides_without_axial_force(spline):
    q = static_response(spline, point_load(spline, "shaft", (P, 0.0, 0.0), x=XI2))
    result = coupling_misalignment(spline, q)
    area = math.pi * (D**2 - (D - 2 * WALL) ** 2) / 4
    assert result.axial_offset[0] == pytest.approx(P * (L - XI2) / (E * area), rel=1e-9)
    assert result.axial_force[0] == 0.0
    assert np.isnan(result.torque[0])


def test_a_coupling_without_an_allowable_angle_has_none(spline):
    q = np.zeros(spline.dofs.size)
    assert np.isnan(coupling_misalignment(spline, q).allowable_angle[0])
