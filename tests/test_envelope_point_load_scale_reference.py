"""An envelope point's ``load_scale`` below 1 scales every static load, by hand.

docs/design-reference.md and :class:`~flexshaft.design.envelope.EnvelopePoint`: ``load_scale``
multiplies the manoeuvre load factor and every point load (force and moment) and line load of
``[loads]``; the imbalance is not scaled; 0 means no manoeuvre or point loads (a ground point).
A scale of 1 is the design's own loads. The reference is that definition applied by hand to a
baseline design given one point load with a moment and one line load: s = 0.5 halves each
component, s = 0 zeroes them (a value is scaled by a power of two or by zero, so the products
are exact in binary floating point and compared exactly).

The point's thermal conditions are left out (an empty ``thermal``/``materials`` change, which
:func:`~flexshaft.design.points.design_at_point` accepts from any object with those two
mappings): only the loads are under test.
"""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from flexshaft.design import baseline_design
from flexshaft.design.envelope import EnvelopePoint
from flexshaft.design.io import design_from_dict
from flexshaft.design.points import design_at_point

NO_CHANGE = SimpleNamespace(thermal={}, materials={})


@pytest.fixture(scope="module")
def design():
    data = baseline_design().model_dump()
    data["loads"]["point"][0]["moment"] = (10.0, -20.0, 40.0)
    data["loads"]["line"] = [
        {"name": "gust", "on": "shaft", "x_start": 1.0, "x_end": 3.0, "force_per_length": (0.0, -8.0, 6.0)}
    ]
    return design_from_dict(data, "<scaled loads>")


@pytest.mark.parametrize("scale", [0.5, 0.0])
def test_a_scale_below_one_scales_every_static_load(design, scale):
    point = EnvelopePoint(name="light", load_scale=scale)
    scaled = design_at_point(design, point, NO_CHANGE)
    base = design.loads
    assert base.load_factor == (0.0, -3.5, 0.0)
    assert scaled.loads.load_factor == (0.0, -3.5 * scale, 0.0)
    assert scaled.loads.point[0].force == (0.0, 0.0, 5000.0 * scale)
    assert scaled.loads.point[0].moment == (10.0 * scale, -20.0 * scale, 40.0 * scale)
    assert scaled.loads.line[0].force_per_length == (0.0, -8.0 * scale, 6.0 * scale)
    assert scaled.loads.eccentricity == base.eccentricity  # the imbalance is not scaled


def test_a_scale_of_one_keeps_the_design():
    plain = baseline_design()
    assert design_at_point(plain, EnvelopePoint(name="same"), NO_CHANGE) == plain
