"""The balanced rotor's lumped parts listed in order of station, and their mass by hand.

``flexshaft.assembly.balance.rotating_parts`` is documented as "every disk and coupling hub, in
order of station"; docs/model.md ("Forced response and strength") takes m as "the mass of the
whole balanced rotor: tubes, disks and coupling hubs".

Model: an aluminium tube (ρ = 2700 kg/m³, D_o = 0.05 m, wall 2 mm: ρ π/4 (D_o² − D_i²) =
0.814301 kg/m) from 0 to 2 m on contact bearings at 0, 1.2 and 2 m, cut at x = 1.0 m by a
coupling whose hub weighs 1.5 kg, with disks "fore" (2.0 kg at 0.3 m) and "aft" (0.5 kg at
1.7 m). The design lists the disks apart from the coupling, so the station order (fore 0.3,
hub 1.0, aft 1.7) interleaves them: a list in input order (couplings, then disks) is not it.
Hand sum: m = 2 · 0.814301 + 1.5 + 2.0 + 0.5 kg.

A sum of a few products: 1e-12 relative (round-off only).

Written for the mutation h99a-balance-parts-unsorted of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.balance import rotating_mass, rotating_parts
from flexshaft.design import design_from_dict

RHO, DO, WALL = 2700.0, 0.05, 0.002
PER_METRE = RHO * math.pi / 4 * (DO**2 - (DO - 2 * WALL) ** 2)  # 0.814301 kg/m


def _model():
    bearing = {"kind": "contact", "stiffness": {"v": 1e7, "w": 1e7}}
    coupling = {
        "name": "hub",
        "x": 1.0,
        "angular_stiffness": 2300.0,
        "axial_stiffness": 2.0e5,
        "torsional_stiffness": 1.0e5,
        "mass": 1.5,
        "diametral_inertia": 1.0e-3,
        "polar_inertia": 2.0e-3,
    }
    disks = [
        {"name": "fore", "x": 0.3, "mass": 2.0, "polar_inertia": 0.01, "diametral_inertia": 0.005},
        {"name": "aft", "x": 1.7, "mass": 0.5, "polar_inertia": 0.002, "diametral_inertia": 0.001},
    ]
    data = {
        "name": "parts in order",
        "materials": {"al": {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": RHO}},
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": DO,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "theta"],
        },
        "bearings": [dict(bearing, name=f"b{i}", x=x) for i, x in enumerate((0.0, 1.2, 2.0))],
        "couplings": [coupling],
        "disks": disks,
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "mesh": {"shaft_elements": 10},
    }
    return build_model(design_from_dict(data))


def test_per_metre_mass_by_hand():
    assert PER_METRE == pytest.approx(0.814301, rel=1e-6)


def test_the_parts_come_in_order_of_station():
    """fore (0.3 m), hub (1.0 m), aft (1.7 m), with their given masses."""
    parts = rotating_parts(_model())
    assert [p.name for p in parts] == ["fore", "hub", "aft"]
    assert [p.x for p in parts] == pytest.approx([0.3, 1.0, 1.7], rel=1e-12)
    assert [p.mass for p in parts] == pytest.approx([2.0, 1.5, 0.5], rel=1e-12)


def test_the_rotor_mass_is_the_tube_and_every_part():
    assert rotating_mass(_model()) == pytest.approx(2.0 * PER_METRE + 1.5 + 2.0 + 0.5, rel=1e-12)
