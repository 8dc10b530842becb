"""Each station of a design is judged against its own member, and each bearing is found by its name.

References: documented rules of the design file and the verdict, and a physical argument:

* docs/model.md ("Elements"): a bearing is a "relative displacement over (u, v, w, β, γ)
  between a shaft point and the boom attachment point at height h, interpolated with the
  element shape functions (eq. 2.34)" -- two points on two members. Physically a shaft point
  exists only on the shaft and a boom attachment point only on the boom, and each displacement
  is interpolated in an element of its own member, so ``x`` is judged against the shaft
  [x_start, x_end] and ``x_boom`` against the tailboom [0, length]: a bearing off the shaft is
  refused even when its boom station lies in the shaft's range, and one on the shaft with a
  boom station beyond x_end (but on a longer boom) is accepted. The bearing model's attribute
  docs (the docstring of flexshaft.design.bearings' pydantic model: code, not a hand-written
  doc) say the same: ``x`` "Shaft station of the bearing [m]; on the shaft.", ``x_boom`` "Boom
  station the bearing is mounted on [m]; defaults to ``x``.";
* a point load ``on = "shaft"`` acts at shaft station ``x``, which must be on the shaft, whatever
  the tailboom's length;
* docs/requirements.md, actuator checks: "active bearings: ``gap``, the radial clearance of the
  auxiliary (backup) bearing [m], and ``force_capacity`` ..." -- the limits are per actuator, so
  each actuator is judged with its own bearing's values; bearing names are unique keys, not
  prefixes.

The baseline's shaft and tailboom both span [0, 8.05] m (thesis Table 3.1); the cases lengthen
the boom so that a station can be on one member and off the other. Each case only validates a
design (a few ms); the actuator-limit case builds one coarse model (well under 1 s).
"""

from __future__ import annotations

from test_schema_stations_reference import _problems, _refused_at

from flexshaft.assembly import build_model
from flexshaft.design import baseline_design, with_overrides
from flexshaft.verdict.gather import actuator_limits

#: A tailboom longer than the 8.05 m shaft: stations in (8.05, 10] m are on the boom only.
LONG_BOOM = {"tailboom.length": 10.0}


def test_bearing_shaft_station_is_checked_on_the_shaft_not_at_its_boom_station() -> None:
    """x = 9.0 m is off the 8.05 m shaft: refused at ``bearings[3].x`` although its boom station
    x_boom = 4.0 m lies inside [0, 8.05]; x = 8.05 on the shaft with x_boom = 9.0 on the 10 m
    boom is a valid bearing (its boom station is beyond x_end, which does not matter)."""
    assert _refused_at({**LONG_BOOM, "bearings[3].x": 9.0, "bearings[3].x_boom": 4.0}, "bearings[3].x")
    assert _problems({**LONG_BOOM, "bearings[3].x_boom": 9.0}) == []


def test_shaft_point_load_station_is_checked_on_the_shaft() -> None:
    """A shaft point load at x = 9.0 m is off the 8.05 m shaft (refused at its ``x``) even though
    9.0 m lies on the 10 m tailboom; the same load at 4.0 m is on the shaft and accepted."""

    def shaft_load(x: float) -> dict:
        load = {"name": "probe", "on": "shaft", "x": x, "force": [0.0, 100.0, 0.0]}
        return {**LONG_BOOM, "loads.point": [load]}

    assert _problems(shaft_load(4.0)) == []
    assert _refused_at(shaft_load(9.0), "loads.point[0].x")


def test_actuator_limits_read_each_bearings_own_values() -> None:
    """Two active bearings whose names share a prefix ("amb_1" and "amb") with different backup
    gaps (0.4 mm and 0.2 mm) and capacities (1200 N and 900 N): each actuator's limits are its
    own bearing's values, and ``Design.bearing`` finds a bearing by its whole name."""
    design = with_overrides(
        baseline_design(),
        {
            "bearings[1].gap": 0.4e-3,
            "bearings[1].force_capacity": 1200.0,
            "bearings[2].name": "amb",
            "bearings[2].gap": 0.2e-3,
            "bearings[2].force_capacity": 900.0,
            "mesh.shaft_elements": 8,
            "mesh.boom_elements": 6,
        },
    )
    assert design.bearing("amb").x == 5.63  # the baseline's second active bearing, read as written
    assert design.bearing("amb_1").x == 3.21
    limits = actuator_limits(build_model(design))
    # values are the floats written above, passed through unchanged: exact comparison is sound
    assert (limits["amb_1"].gap, limits["amb_1"].force_capacity) == (0.4e-3, 1200.0)
    assert (limits["amb"].gap, limits["amb"].force_capacity) == (0.2e-3, 900.0)
