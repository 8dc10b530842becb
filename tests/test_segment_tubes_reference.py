"""Segmented shafts: tiling of [[shaft.segments]] and the tube each zone resolves to.

References, independent of flexshaft's segment bookkeeping:

* geometry of a tiling: zones that overlap (or leave a gap) do not partition [x_start, x_end],
  which the design file's docs/DESIGN require ("without gap or overlap");
* the design file's convention, written in its input: a layup lists the plies inner ply first
  (``[shaft] layup``, ``[[shaft.segments]] layup``); the model's laminate must carry the angles
  of the string in that order, the order that sets the sign of an unsymmetric laminate's
  bending-extension coupling B;
* the tube mass by hand: rho * pi * (D^2 - d^2) / 4 * L summed over the zones, with d = D - 2 t
  and each zone's own or inherited D and t.

Cheap: 2 m tubes with 4-8 elements (mass and laminate do not depend on the mesh).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, design_from_dict, tuned_design

AL = {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0, "loss_factor": 0.0}
D_O, WALL = 0.05, 0.002


def tube(segments, materials=None) -> dict:
    """A 2 m aluminium tube on pinned ends with the given segments, as a design-file dict."""
    return {
        "name": "segment reference",
        "materials": materials or {"al": AL},
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": D_O,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
            "segments": segments,
        },
        "bearings": [{"name": "far", "kind": "contact", "x": 2.0, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 8},
    }


@pytest.mark.parametrize(
    "segments",
    [
        [{"name": "a", "x_start": 0.0, "x_end": 1.1}, {"name": "b", "x_start": 1.0, "x_end": 2.0}],  # overlap
        [{"name": "a", "x_start": 0.0, "x_end": 0.9}, {"name": "b", "x_start": 1.0, "x_end": 2.0}],  # gap
    ],
)
def test_segments_that_do_not_tile_the_shaft_are_refused(segments):
    # 0.1 m of overlap counts 0.1 m of tube twice; a 0.1 m gap leaves it out: neither tiles.
    with pytest.raises(DesignError, match=r"shaft\.segments\[1\]\.x_start: must equal the x_end of segment"):
        design_from_dict(tube(segments))


def test_a_laminated_segment_carries_its_plies_inner_ply_first():
    cf = dict(tuned_design().model_dump()["materials"]["t700_adiprene"])
    cf.pop("temperature_table", None)
    layup = "30/-60/0/90"  # unsymmetric on purpose: reversed, it is another laminate
    segments = [
        {"name": "metal", "x_start": 0.0, "x_end": 1.0},
        {"name": "fmc", "x_start": 1.0, "x_end": 2.0, "material": "cf", "layup": layup, "wall_thickness": 0.003},
    ]
    model = build_model(design_from_dict(tube(segments, {"al": AL, "cf": cf})))
    laminate = model.segments[1].properties.laminate
    np.testing.assert_array_equal(laminate.angles, np.radians([30.0, -60.0, 0.0, 90.0]))
    assert model.segments[0].properties.laminate is None  # the metal zone keeps no plies


def test_tube_mass_is_rho_a_l_of_each_zone_with_its_own_or_the_inherited_tube():
    segments = [
        {"name": "a", "x_start": 0.0, "x_end": 0.5},  # inherits D_O and WALL
        {"name": "b", "x_start": 0.5, "x_end": 1.25, "outer_diameter": 0.06},  # inherits WALL
        {"name": "c", "x_start": 1.25, "x_end": 2.0, "wall_thickness": 0.003},  # inherits D_O
    ]
    model = build_model(design_from_dict(tube(segments)))

    def ring(D, t):
        return math.pi * (D**2 - (D - 2 * t) ** 2) / 4

    by_hand = 2700.0 * (ring(D_O, WALL) * 0.5 + ring(0.06, WALL) * 0.75 + ring(D_O, 0.003) * 0.75)
    assert model.shaft_mass == pytest.approx(by_hand, rel=1e-12)  # exact arithmetic, rounding only
