"""The drive train's documented ranges are the ones a design file is held to.

Reference: docs/limits.md, the table of the drive train and other tables (hand-written):
"gear ratio | 0.01 to 100", "polar inertia | above 0, up to 1e7 kg m²", "input and hub
torsional stiffness (omitted: rigid) | above 0, up to 1e12 N m/rad", "aerodynamic (torsional)
damping | 0 to 1e9 N m s/rad", "torque oscillation, 1P and N/rev | 0 to 10 times the mean
torque", "blades | 1 to 12". Each end is tried on the embedded tuned design's ``[tail_rotor]``
(and on a ``[main_gearbox]`` added to it, below): the end itself is accepted where the table
says "to" (closed), refused where it says "above" (open), and the next float beyond it is
refused, at the field's path. Validation only (no model is built).
"""

from __future__ import annotations

import copy
import math

import pytest

from flexshaft.design import DesignError, design_from_dict, embedded_design


@pytest.fixture(scope="module")
def tuned() -> dict:
    data = embedded_design("tuned").model_dump(mode="json")
    assert data["tail_rotor"] is not None
    return data


def refused_at(data: dict) -> set[str]:
    try:
        design_from_dict(data)
    except DesignError as error:
        return {problem.path for problem in error.problems}
    return set()


def with_rotor(base: dict, key: str, value) -> dict:
    data = copy.deepcopy(base)
    data["tail_rotor"][key] = value
    return data


#: (key, low, low included, high): every high end is closed ("up to", "to").
CLOSED_AND_OPEN_ENDS = [
    ("gearbox_ratio", 0.01, True, 100.0),
    ("polar_inertia", 0.0, False, 1e7),
    ("input_stiffness", 0.0, False, 1e12),
    ("hub_stiffness", 0.0, False, 1e12),
    ("aerodynamic_damping", 0.0, True, 1e9),
    ("torque_oscillation_1p", 0.0, True, 10.0),
    ("torque_oscillation_np", 0.0, True, 10.0),
]


@pytest.mark.parametrize(("key", "low", "low_included", "high"), CLOSED_AND_OPEN_ENDS)
def test_each_documented_end(tuned, key, low, low_included, high):
    path = f"tail_rotor.{key}"
    assert path not in refused_at(with_rotor(tuned, key, high))
    assert path in refused_at(with_rotor(tuned, key, math.nextafter(high, math.inf)))
    assert (path in refused_at(with_rotor(tuned, key, low))) is not low_included
    assert path in refused_at(with_rotor(tuned, key, math.nextafter(low, -math.inf)))


@pytest.mark.parametrize(("blades", "accepted"), [(0, False), (1, True), (12, True), (13, False)])
def test_blade_count(tuned, blades, accepted):
    assert ("tail_rotor.blades" not in refused_at(with_rotor(tuned, "blades", blades))) is accepted


#: docs/limits.md's [main_gearbox] rows: "polar inertia | 0 (default) to 1e7 kg m²" (closed at
#: both ends, unlike the tail rotor's), "torsional stiffness (omitted: rigid) | above 0, up to
#: 1e12 N m/rad".
GEARBOX_ENDS = [("polar_inertia", 0.0, True, 1e7), ("stiffness", 0.0, False, 1e12)]


@pytest.mark.parametrize(("key", "low", "low_included", "high"), GEARBOX_ENDS)
def test_each_documented_end_of_the_main_gearbox(tuned, key, low, low_included, high):
    def with_gearbox(value) -> dict:
        data = copy.deepcopy(tuned)
        data["main_gearbox"] = {"polar_inertia": 2.0, "stiffness": 1e5, key: value}
        return data

    path = f"main_gearbox.{key}"
    assert path not in refused_at(with_gearbox(high))
    assert path in refused_at(with_gearbox(math.nextafter(high, math.inf)))
    assert (path in refused_at(with_gearbox(low))) is not low_included
    assert path in refused_at(with_gearbox(math.nextafter(low, -math.inf)))
