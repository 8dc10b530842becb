"""The design schema's cross-table station and drive-end checks at their documented edges.

References: docs/design-reference.md (generated from the schema's field descriptions) and the
checks' documented rules:

* a bearing's ``x`` is "on the shaft": the closed interval [x_start, x_end] = [0, 8.05] m of the
  baseline (Table 3.1), both ends included (the baseline's aft hanger sits at x_end = 8.05);
  its boom station (``x_boom``, default ``x``) lies on the tailboom [0, length] = [0, 8.05] m;
* a coupling's ``x`` is "strictly inside the shaft": its forward end x_start is refused;
* an active bearing's displacement sensor sits at ``x + sensor_offset``, which must be on the
  shaft;
* a line load runs from ``x_start`` to ``x_end``, both on its member;
* ``[tail_rotor]`` drives the aft end's twist, so ``shaft.fixed_end`` must not hold theta (the
  forward end's ``fixed_start = ["theta"]`` of the baseline is unaffected); an elastic
  ``[main_gearbox]`` (a ``stiffness``) drives the forward twist, so ``fixed_start`` must not
  hold theta, while a rigid one (no ``stiffness``) holds it as ``fixed_start`` does.

Each case edits the embedded baseline and only validates it (no model is built): a few
milliseconds each.
"""

from __future__ import annotations

import pytest

from flexshaft.design import DesignError, baseline_design, with_overrides

TAIL_ROTOR = {"blades": 4, "polar_inertia": 2.0, "gearbox_ratio": 3.0}


def _problems(overrides: dict) -> list[str]:
    """The refusal's lines, or [] when the edited baseline validates."""
    try:
        with_overrides(baseline_design(), overrides)
    except DesignError as exc:
        return str(exc).strip().splitlines()
    return []


def _refused_at(overrides: dict, path: str) -> bool:
    return any(line.startswith(f"{path}:") for line in _problems(overrides))


def test_baseline_shaft_and_boom_ranges() -> None:
    design = baseline_design()
    assert (design.shaft.x_start, design.shaft.x_end) == (0.0, 8.05)
    assert design.tailboom is not None and design.tailboom.length == 8.05


def test_bearing_at_either_end_of_the_shaft_is_on_it() -> None:
    # x = x_start = 0: on the shaft, and its default boom station 0 is the boom root
    assert _problems({"bearings[0].x": 0.0}) == []
    assert _problems({"bearings[0].x_boom": 0.0}) == []
    # x = x_end = 8.05 (the baseline's aft hanger is already there)
    assert _problems({"bearings[0].x": 8.05}) == []
    # just outside either end: refused, naming the field
    assert _refused_at({"bearings[0].x": -0.01}, "bearings[0].x")
    assert _refused_at({"bearings[0].x": 8.06}, "bearings[0].x")


def test_coupling_must_be_strictly_inside() -> None:
    def coupling(x: float) -> dict:
        return {
            "couplings": [
                {
                    "name": "joint",
                    "x": x,
                    "angular_stiffness": "rigid",
                    "axial_stiffness": "rigid",
                    "torsional_stiffness": "rigid",
                }
            ]
        }

    assert _problems(coupling(2.0)) == []
    for x in (0.0, 8.05):  # at either end it joins nothing
        lines = _problems(coupling(x))
        assert any(line.startswith("couplings[0].x:") and "strictly inside" in line for line in lines), lines


def test_sensor_station_is_x_plus_offset() -> None:
    # bearings[2] (active) at x = 5.63 (boom station too): offset +2.42 puts the sensor at 8.05 (the aft end, on
    # the shaft), +2.5 at 8.13 (off it); -5.63 at 0 (the forward end), -5.7 at -0.07 (off it)
    assert baseline_design().bearings[2].x == 5.63
    for offset in (2.42, -5.63):
        assert _problems({"bearings[2].sensor_offset": offset}) == [], offset
    for offset in (2.5, -5.7):
        assert _refused_at({"bearings[2].sensor_offset": offset}, "bearings[2].sensor_offset"), offset
    # mounted on the boom at 3.0 m: offset +2.5 puts the sensor's boom station at 5.5 m (on the
    # boom) but its shaft station at 8.13 m, off the shaft: refused by the shaft station alone
    lines = _problems({"bearings[2].x_boom": 3.0, "bearings[2].sensor_offset": 2.5})
    assert any(line.startswith("bearings[2].sensor_offset:") and "x = 8.13 m" in line for line in lines), lines


def test_line_load_end_must_be_on_the_shaft() -> None:
    def line(x_start: float, x_end: float) -> dict:
        load = {"name": "drag", "on": "shaft", "x_start": x_start, "x_end": x_end, "force_per_length": [0, -1.0, 0]}
        return {"loads.line": [load]}

    assert _problems(line(1.0, 8.05)) == []
    assert _refused_at(line(1.0, 9.0), "loads.line[0].x_end")
    assert _refused_at(line(-1.0, 2.0), "loads.line[0].x_start")


def test_drive_ends_and_held_twist() -> None:
    assert baseline_design().shaft.fixed_start == ("theta",)
    # a tail rotor on the aft end with the forward twist held (the baseline's fixed_start)
    assert _problems({"tail_rotor": TAIL_ROTOR}) == []
    assert _refused_at({"tail_rotor": TAIL_ROTOR, "shaft.fixed_end": ["theta"]}, "shaft.fixed_end")
    # a rigid gearbox holds the forward twist as fixed_start does; an elastic one drives it
    assert _problems({"main_gearbox": {"polar_inertia": 1.0}}) == []
    assert _refused_at({"main_gearbox": {"polar_inertia": 1.0, "stiffness": 1e5}}, "shaft.fixed_start")
    assert _problems({"main_gearbox": {"polar_inertia": 1.0, "stiffness": 1e5}, "shaft.fixed_start": []}) == []


@pytest.mark.parametrize("x_boom", [-0.01, 8.06])
def test_boom_station_off_the_boom(x_boom: float) -> None:
    assert _refused_at({"bearings[0].x_boom": x_boom}, "bearings[0].x_boom")
