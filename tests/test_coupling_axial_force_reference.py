"""The axial force a flexible coupling transmits, against the statics of a bar in series.

A tube pinned at both ends, held axially at x = 0 and free axially at x = L, cut at x = a by a
coupling of axial stiffness k_ax (and a different, finite or rigid, lateral stiffness), pulled by
an axial end force P.
The bar is statically determinate: every section beyond x = 0, the coupling included, carries
N = P (equilibrium of the free body from the coupling to the end). The coupling's flanges then
separate by Δu = P/k_ax and the force it reports is k_ax Δu = P whatever k_ax, k_lat. The linear
axial element is exact for a point load at a node: tolerance 1e-9 (the rigid DOFs' round-off).
"""

from __future__ import annotations

import pytest

from flexshaft.analyses.misalignment import coupling_misalignment
from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import design_from_dict

LENGTH, A, K_AX, P = 1.0, 0.4, 2.0e6, 1500.0
AL = {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0}


def _pulled(lateral) -> tuple:
    data = {
        "name": "coupled bar",
        "materials": {"al": AL},
        "shaft": {
            "x_start": 0.0,
            "x_end": LENGTH,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": LENGTH, "stiffness": {"u": 0.0}}],
        "couplings": [
            {
                "name": "disc",
                "x": A,
                "angular_stiffness": 500.0,
                "axial_stiffness": K_AX,
                "torsional_stiffness": "rigid",
                "lateral_stiffness": lateral,
            }
        ],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 5},
    }
    model = build_model(design_from_dict(data))
    q = static_response(model, point_load(model, "shaft", (P, 0.0, 0.0), x=LENGTH))
    return model, q


@pytest.mark.parametrize("lateral", [5.0e7, "rigid"])
def test_the_coupling_carries_the_end_force(lateral):
    """Δu = P/k_ax and the reported axial force equals P (not k_lat Δu)."""
    model, q = _pulled(lateral)
    result = coupling_misalignment(model, q)
    assert result.axial_offset[0] == pytest.approx(P / K_AX, rel=1e-9)
    assert result.axial_force[0] == pytest.approx(P, rel=1e-9)
    assert result.static_angle[0] == pytest.approx(0.0, abs=1e-12)
