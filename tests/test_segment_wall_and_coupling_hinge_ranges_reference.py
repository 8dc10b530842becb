"""The documented ranges of a segment's wall and of a coupling's angular stiffness, at their edges.

* docs/limits.md, section 1: ``WallThickness`` is used for "shaft and boom walls" with the range
  "10 µm to 1 m" ("a tenth of one ply"), while ``Diameter`` (``outer_diameter``) runs "1 mm to
  10 m". A ``[[shaft.segments]]`` zone may override the ``[shaft]`` wall
  (docs/segmented-driveline.md: "any of outer_diameter, wall_thickness, material, layup may
  change"), so a zone's wall obeys the shaft-wall range: a 0.5 mm zone (above 10 µm, below the
  1 mm floor of a diameter) is accepted, and a 5 µm one is refused at that zone's
  ``wall_thickness``. The accepted zone resolves to a tube whose stations tile the shaft (hand
  sum: 4.0 m + 4.05 m = the baseline's 8.05 m) and whose bore is D_i = D_o − 2 t
  = 0.1016 − 2 × 0.0005 = 0.1006 m, with the ``[shaft]`` diameter, material and layup inherited.
* docs/segmented-driveline.md, its example ``[[couplings]]``: each stiffness line ends with
  ``; or "rigid"``, and only the torsional one carries "(> 0)":
  ``angular_stiffness = 2300.0   # N m/rad, each bending plane; or "rigid"`` beside
  ``torsional_stiffness = 1.0e5  # N m/rad (> 0); or "rigid"``. (API contract, supporting text:
  the ``Coupling`` docstring in design/segments.py says "each a number or ``"rigid"``" and
  "``torsional_stiffness`` [N m/rad] (> 0: it carries the torque)".) The coupling
  element's energy ½ k_ang (Δβ² + Δγ²) is well defined at k_ang = 0: an ideal hinge (a universal
  joint, or a disc pack far softer than the tubes). A hinge of zero angular stiffness is
  therefore accepted, alone and in a design, and a zero torsional stiffness is still refused.

Validation only (no model is built): milliseconds of CPU. The one float compared, the bore, is a
single subtraction of exactly given numbers: 1e-15 m covers its rounding (a few ulp of 0.1 m).
"""

from __future__ import annotations

import tomllib

import pydantic
import pytest

from flexshaft.design.io import DesignError, design_from_dict, embedded_text
from flexshaft.design.segments import Coupling

#: docs/limits.md: WallThickness "10 µm to 1 m"; Diameter "1 mm to 10 m".
THIN_ZONE_WALL = 5e-4  # m: inside the wall range, below the diameter floor
TOO_THIN_WALL = 5e-6  # m: below the documented 10 µm


def _baseline() -> dict:
    return tomllib.loads(embedded_text("baseline"))


def _two_zones(wall: float) -> dict:
    data = _baseline()
    data["shaft"]["segments"] = [
        {"name": "forward", "x_start": 0.0, "x_end": 4.0},
        {"name": "thin", "x_start": 4.0, "x_end": data["shaft"]["x_end"], "wall_thickness": wall},
    ]
    return data


def test_a_zone_takes_a_half_millimetre_wall_like_the_shaft() -> None:
    data = _two_zones(THIN_ZONE_WALL)
    shaft = data["shaft"]
    assert shaft["x_end"] == 8.05 and shaft["outer_diameter"] == 0.1016  # the hand numbers above
    tubes = design_from_dict(data).shaft.tubes
    assert [tube.name for tube in tubes] == ["forward", "thin"]
    assert tubes[0].length + tubes[1].length == pytest.approx(8.05, abs=1e-12)
    thin = tubes[1]
    assert thin.wall_thickness == THIN_ZONE_WALL
    assert (thin.outer_diameter, thin.material, thin.layup) == (0.1016, shaft["material"], shaft["layup"])
    assert thin.inner_diameter == pytest.approx(0.1006, abs=1e-15)


def test_a_zone_refuses_a_wall_below_ten_micrometres() -> None:
    with pytest.raises(DesignError) as refused:
        design_from_dict(_two_zones(TOO_THIN_WALL))
    assert [problem.path for problem in refused.value.problems] == ["shaft.segments[1].wall_thickness"]


def _hinge(**stiffness: float | str) -> dict:
    return {"name": "hinge", "x": 4.0, "axial_stiffness": "rigid", **stiffness}


def test_a_coupling_of_zero_angular_stiffness_is_an_accepted_hinge() -> None:
    coupling = Coupling.model_validate(_hinge(angular_stiffness=0.0, torsional_stiffness="rigid"))
    assert coupling.angular_stiffness == 0.0
    data = _baseline()  # bearings at 0.79, 3.21, 5.63, 8.05 m: none at the hinge's 4.0 m
    data["couplings"] = [_hinge(angular_stiffness=0.0, torsional_stiffness=1.0e5)]
    design = design_from_dict(data)
    assert design.segmented and design.couplings[0].angular_stiffness == 0.0


def test_a_coupling_of_zero_torsional_stiffness_is_refused() -> None:
    with pytest.raises(pydantic.ValidationError) as refused:
        Coupling.model_validate(_hinge(angular_stiffness=0.0, torsional_stiffness=0.0))
    assert {error["loc"][0] for error in refused.value.errors()} == {"torsional_stiffness"}
