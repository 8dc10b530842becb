"""The shortest shaft, a segment's tiling tolerance and a shaft on the boom's top (hunt h41a).

References (the documented limits, each with its physical content):

* ``MIN_SHAFT_LENGTH`` (:mod:`flexshaft.design.quantities`, docs/limits.md): "Shortest shaft
  x_end − x_start [m]" is 1 mm, *at least* that length being allowed (the refusal says
  "allowed: at least 0.001 m"). A shaft of exactly 1e-3 m (binary-inexact, but the same double
  on both sides of the comparison: 0.001 − 0 is 0.001 exactly) and one of 0.5 m are accepted;
  one of 0.9 mm is refused.
* Segments tile the shaft "without gap or overlap" (:class:`~flexshaft.design.components.Shaft`):
  the tolerance is round-off, 1e-9 of the length. A 0.5 mm gap between two zones of a 2 m
  shaft is 2.5e-4 of it, a real gap: refused, as is a last zone 0.5 mm short.
* The boom's clearance (:mod:`flexshaft.design.quantities`): "distance between the shaft and
  boom axes from 0 to 10 m". Zero is a shaft axis on the boom's top surface: the offset h of
  :meth:`~flexshaft.design.components.Tailboom.shaft_offset_at` is then the vertical semi-axis
  alone, a(x) = a_root + (x/L)(a_tip − a_root) by hand, in numbers exact in binary so that
  every step of it is exact: 0.5 → 0.125 over 6 m at x = 3 m is 0.5 + 0.5 · (−0.375) = 0.3125 m.

Exact comparisons; no model is solved (validation only), well under 10 ms.
Written for h41a-comp-min-length-exclusive, h41a-q-min-shaft-length-metre,
h41a-comp-segment-tolerance-mm and h41a-q-clearance-zero-refused of scripts/mutations.toml.
"""

from __future__ import annotations

import pytest

from flexshaft.design import DesignError, design_from_dict
from flexshaft.design.components import Tailboom

AL = {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0}


def _design(length: float, segments=()) -> dict:
    shaft = {"x_start": 0.0, "x_end": length, "outer_diameter": 0.05, "wall_thickness": 0.002, "material": "al"}
    if segments:
        shaft["segments"] = list(segments)
    return {
        "name": "edges",
        "materials": {"al": AL},
        "shaft": shaft,
        "bearings": [
            {"name": "fore", "kind": "contact", "x": 0.0, "stiffness": {"v": 1e7, "w": 1e7}},
            {"name": "aft", "kind": "contact", "x": length, "stiffness": {"v": 1e7, "w": 1e7}},
        ],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "mesh": {"shaft_elements": 2},
    }


@pytest.mark.parametrize("length", [1e-3, 0.5])
def test_a_shaft_of_at_least_the_shortest_length_is_accepted(length):
    design = design_from_dict(_design(length))
    assert design.shaft.length == length


def test_a_shaft_shorter_than_a_millimetre_is_refused():
    with pytest.raises(DesignError, match=r"shaft\.x_end: gives a shaft length"):
        design_from_dict(_design(0.9e-3))


def test_segments_that_tile_the_shaft_are_accepted():
    zones = [{"name": "a", "x_start": 0.0, "x_end": 1.0}, {"name": "b", "x_start": 1.0, "x_end": 2.0}]
    assert [t.x_end for t in design_from_dict(_design(2.0, zones)).shaft.tubes] == [1.0, 2.0]


def test_a_half_millimetre_gap_between_segments_is_refused():
    zones = [{"name": "a", "x_start": 0.0, "x_end": 1.0}, {"name": "b", "x_start": 1.0005, "x_end": 2.0}]
    with pytest.raises(DesignError, match=r"segments\[1\]\.x_start: must equal the x_end of segment"):
        design_from_dict(_design(2.0, zones))


def test_a_last_segment_half_a_millimetre_short_is_refused():
    zones = [{"name": "a", "x_start": 0.0, "x_end": 1.0}, {"name": "b", "x_start": 1.0, "x_end": 1.9995}]
    with pytest.raises(DesignError, match=r"segments\[1\]\.x_end: must equal shaft\.x_end"):
        design_from_dict(_design(2.0, zones))


def test_a_shaft_on_the_booms_top_has_the_vertical_semi_axis_as_offset():
    boom = Tailboom(
        length=6.0,
        root_semi_axes=(0.5, 0.25),
        tip_semi_axes=(0.125, 0.0625),
        wall_thickness=0.002,
        material="al",
        shaft_clearance=0.0,
    )
    assert boom.shaft_offset_at(3.0) == 0.3125
    assert boom.shaft_offset_at(0.0) == 0.5
