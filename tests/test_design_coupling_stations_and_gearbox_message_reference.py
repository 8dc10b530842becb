"""Coupling stations and the elastic-gearbox conflict message, against the hand-written docs.

References (quoted verbatim):

* docs/segmented-driveline.md: "a coupling strictly inside the shaft, at its own station, with
  no bearing, sensor or disk at that station (put them on one side)", and "a bearing, sensor,
  disk or load station closer to one of them than the mesh's merge tolerance (5 % of an
  element) moves onto it". So only the coupling's own station is refused: a disk or bearing
  1 mm to either side of it is on one side and is accepted by the schema (the mesh then
  places it); and a coupling repeating the station of any earlier coupling, not only the one
  just before it, is refused.
* docs/limits.md: "one `error:` line per problem naming the field, the value and what is
  allowed". The elastic-gearbox conflict is a problem of ``shaft.fixed_start``, so its "got"
  must quote the ``fixed_start`` the file gives, not another key's value.

Each case edits the embedded baseline (shaft 0 to 8.05 m, Table 3.1) and only validates it: a
few milliseconds each, no model built.
"""

from __future__ import annotations

from tests.test_schema_stations_reference import _problems, _refused_at
from tests.test_segments import rigid_coupling as _coupling


def _disk(x: float) -> dict:
    return {"name": "flange_disk", "x": x, "mass": 1.0, "polar_inertia": 1e-3, "diametral_inertia": 5e-4}


def test_disk_and_bearing_one_millimetre_beside_a_coupling_are_on_one_side() -> None:
    joint = [_coupling("joint", 2.0)]
    # 1 mm aft and 1 mm forward of the coupling: a station of its own, on one side
    for x in (2.001, 1.999):
        assert _problems({"couplings": joint, "disks": [_disk(x)]}) == [], x
        assert _problems({"couplings": joint, "bearings[0].x": x}) == [], x
    # at the coupling's own station: refused, naming the disk's station
    assert _refused_at({"couplings": joint, "disks": [_disk(2.0)]}, "disks[0].x")


def test_a_coupling_repeating_any_earlier_station_is_refused() -> None:
    # three couplings: the third repeats the first's station, not the second's
    couplings = [_coupling("c1", 2.0), _coupling("c2", 4.0), _coupling("c3", 2.0)]
    lines = _problems({"couplings": couplings})
    assert any(line.startswith("couplings[2].x:") and "repeats" in line for line in lines), lines
    # three distinct stations: accepted
    distinct = [_coupling("c1", 2.0), _coupling("c2", 4.0), _coupling("c3", 6.0)]
    assert _problems({"couplings": distinct}) == []


def test_gearbox_conflict_quotes_the_fixed_start_given() -> None:
    overrides = {
        "main_gearbox": {"polar_inertia": 1.0, "stiffness": 1e5},
        "shaft.fixed_start": ["u", "theta"],
        "shaft.fixed_end": ["w"],
    }
    lines = [line for line in _problems(overrides) if line.startswith("shaft.fixed_start:")]
    assert len(lines) == 1, lines
    got = lines[0].split("(got ", 1)[1]
    # the value found is fixed_start's ["u", "theta"]; fixed_end's "w" is not part of it
    assert '"u"' in got and '"theta"' in got and '"w"' not in got, lines[0]
