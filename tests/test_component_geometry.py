"""Geometry of the design's structural components (:mod:`flexshaft.design.components`) by hand.

* A tube of outer diameter D_o and wall t has the inner diameter D_o − 2t (one wall each side)
  and exists only while t < D_o/2 (a wall as thick as the radius leaves no bore).
* A segment's own outer diameter and material replace the ``[shaft]`` values; a segment of
  another material (a metal tube) does not inherit the composite layup (docs/segmented-driveline.md).
* The tailboom's semi-axes taper linearly from the root (x = 0) to the tip (x = L), so the
  wall must be thinner than the smallest semi-axis anywhere, the tip's included.

Exact decimal inputs; tolerance 1e-12 (a few roundings of numbers of order 0.1 m).
"""

from __future__ import annotations

import pytest
from pydantic import ValidationError

from flexshaft.design.components import Shaft, Tailboom
from flexshaft.design.segments import ShaftSegment

TOL = 1e-12


def _shaft(**kwargs) -> Shaft:
    nominal = {"x_start": 0.0, "x_end": 2.0, "outer_diameter": 0.1, "wall_thickness": 0.002, "material": "cf"}
    return Shaft(**{**nominal, "layup": "(45/-45)s", **kwargs})


def test_inner_diameter_is_outer_minus_two_walls():
    shaft = _shaft()
    assert shaft.inner_diameter == pytest.approx(0.1 - 2 * 0.002, rel=TOL)
    assert shaft.length == pytest.approx(2.0, rel=TOL)


def test_wall_must_be_thinner_than_the_radius():
    assert _shaft(wall_thickness=0.049).inner_diameter == pytest.approx(0.002, rel=1e-9)
    with pytest.raises(ValidationError, match="outer_diameter/2"):
        _shaft(wall_thickness=0.06)


def test_segments_take_their_own_diameter_and_material():
    segments = (
        ShaftSegment(name="composite", x_start=0.0, x_end=1.0),
        ShaftSegment(name="steel", x_start=1.0, x_end=2.0, outer_diameter=0.12, material="steel"),
    )
    composite, steel = _shaft(segments=segments).tubes
    assert composite.outer_diameter == pytest.approx(0.1, rel=TOL)
    assert (composite.material, composite.layup) == ("cf", "(45/-45)s")
    assert steel.outer_diameter == pytest.approx(0.12, rel=TOL)
    assert steel.wall_thickness == pytest.approx(0.002, rel=TOL)
    assert (steel.material, steel.layup) == ("steel", None)


def _boom(**kwargs) -> Tailboom:
    nominal = {
        "length": 6.0,
        "root_semi_axes": (0.4, 0.3),
        "tip_semi_axes": (0.1, 0.06),
        "wall_thickness": 0.002,
        "material": "al",
        "shaft_clearance": 0.05,
    }
    return Tailboom(**{**nominal, **kwargs})


def test_boom_tapers_linearly_from_root_to_tip():
    boom = _boom()
    assert boom.semi_axes_at(0.0) == pytest.approx((0.4, 0.3), rel=TOL)
    assert boom.semi_axes_at(6.0) == pytest.approx((0.1, 0.06), rel=TOL)
    assert boom.semi_axes_at(1.5) == pytest.approx((0.4 - 0.25 * 0.3, 0.3 - 0.25 * 0.24), rel=TOL)
    assert boom.shaft_offset_at(1.5) == pytest.approx(0.4 - 0.25 * 0.3 + 0.05, rel=TOL)


def test_boom_wall_thinner_than_the_tip_section():
    """A 70 mm wall is thinner than every root semi-axis but not than the tip's 60 mm."""
    with pytest.raises(ValidationError, match="smallest semi-axis"):
        _boom(wall_thickness=0.07)
