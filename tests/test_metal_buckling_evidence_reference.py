"""The buckling evidence of a segmented metal shaft: its weakest segment at the peak torque, and
none while a laminated segment is left unjudged (derived here).

Two isotropic segments carry the same steady torque T = 1000 N m; their torsional buckling
torques are T_cr,a = 6000 N m and T_cr,b = 4000 N m, so their safety factors at the steady torque
are T_cr/T = 6 and 4. The tail rotor's torque oscillation raises the peak torque to f T with
the torque factor f = 1.25; buckling is an instability of the peak load, so the shaft's buckling
safety factor is that of its weakest segment at the peak torque:

    n = min_i T_cr,i/(f T) = 4000/1250 = 3.2.

A shaft with a third, laminated segment (whose buckling is not modelled for a segmented shaft)
gives no evidence at all: the metal tubes alone must not pass the check for the whole shaft.
The segments' results are stand-ins (:class:`~flexshaft.analyses.metal_strength.SegmentBuckling`
records); the arithmetic is exact to round-off (relative 1e-15).
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import pytest

from flexshaft.analyses.metal_strength import SegmentBuckling
from flexshaft.verdict import gather

TORQUE, FACTOR = 1000.0, 1.25
SEGMENTS = (
    SegmentBuckling("a", 1.2, 6000.0, TORQUE, 6000.0 / TORQUE, 3),
    SegmentBuckling("b", 0.8, 4000.0, TORQUE, 4000.0 / TORQUE, 2),
)


def _point(names):
    return NS(
        buckling=None,
        metal_strength=NS(buckling=SEGMENTS),
        model=NS(segments=[NS(name=n) for n in names]),
        torque_factor=FACTOR,
    )


def test_the_weakest_metal_segment_at_the_peak_torque_governs():
    notes: dict[str, str] = {}
    out = gather._buckling(_point(["a", "b"]), notes)
    assert out["buckling_safety_factor"] == pytest.approx(4000.0 / (FACTOR * TORQUE), rel=1e-15)
    assert "segment b" in out["buckling_location"]["case"] and not notes


def test_a_laminated_segment_leaves_the_shaft_unjudged():
    notes: dict[str, str] = {}
    assert gather._buckling(_point(["a", "b", "composite"]), notes) == {}
    assert "composite" in notes["buckling"]
