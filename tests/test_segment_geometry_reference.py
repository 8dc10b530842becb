"""A segment's length and bore, and the stations and couplings the design file refuses
(design/segments.py), on hand-typed values.

References (derived, tube geometry): a zone from x = 1.25 m to x = 2.75 m is 1.5 m long; a
tube of outer diameter 100 mm and wall 2 mm has an inner diameter 100 − 2·2 = 96 mm (a wall on
each side). A zone whose aft end lies before its forward end has no length and a coupling of
zero torsional stiffness carries no torque: the design file refuses both. CPU about 5 ms.
"""

from __future__ import annotations

import pydantic
import pytest

from flexshaft.design.segments import Coupling, ShaftSegment, Tube


def test_tube_length_and_inner_diameter():
    tube = Tube(
        name="aft", x_start=1.25, x_end=2.75, outer_diameter=0.1, wall_thickness=0.002, material="al", layup=None
    )
    assert tube.length == pytest.approx(1.5, rel=1e-15)
    assert tube.inner_diameter == pytest.approx(0.096, rel=1e-15)


def test_a_reversed_zone_is_refused():
    assert ShaftSegment(name="fwd", x_start=1.0, x_end=2.0).x_end == 2.0
    with pytest.raises(pydantic.ValidationError):
        ShaftSegment(name="fwd", x_start=2.0, x_end=1.0)


def test_a_coupling_without_torsional_stiffness_is_refused():
    kwargs = {"name": "disc", "x": 1.0, "angular_stiffness": 500.0, "axial_stiffness": 1e6}
    assert Coupling(**kwargs, torsional_stiffness=1e5).torsional_stiffness == 1e5
    with pytest.raises(pydantic.ValidationError):
        Coupling(**kwargs, torsional_stiffness=0.0)
