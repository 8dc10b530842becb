"""A design's own ``[envelope]`` points are the points its envelope conditions are evaluated at.

docs/thermal.md, "The operating envelope": "``[[envelope.points]]`` lists the operating points";
"Default points (used without an ``[envelope]``...)". So
:func:`~flexshaft.thermal.envelope.envelope_conditions` of a design with its own one-point
envelope gives that one point only. Reference, derived here from the documented step 1 and step 2
of :mod:`flexshaft.thermal.envelope`: a single point with ambient 35 °C and
``material_temperature = "ambient"`` has ambient 308.15 K (35 + 273.15, exact in the kelvin
conversion up to one rounding: rel 1e-15 would do, 1e-12 leaves margin) and T_m equal to that
ambient; the result has exactly one entry, named as the point.
"""

from __future__ import annotations

import pytest

from flexshaft.design import baseline_design
from flexshaft.design.envelope import Envelope, EnvelopePoint
from flexshaft.thermal.envelope import envelope_conditions


def test_envelope_conditions_follow_the_designs_own_points():
    point = EnvelopePoint(name="warm_ground_run", ambient_temperature_c=35.0, material_temperature="ambient")
    design = baseline_design().model_copy(update={"envelope": Envelope(points=(point,))})
    conditions = envelope_conditions(design)
    assert [c.name for c in conditions] == ["warm_ground_run"]
    (only,) = conditions
    assert only.ambient_temperature == pytest.approx(308.15, rel=1e-12)
    assert only.material_temperature == only.ambient_temperature
