"""The explorer's controls: which design field each one writes, in which unit, within which range.

References: a control state set by hand and the design fields it must give, with the unit
factors written out (1 mm = 1e-3 m; 1 rpm = 2π/60 rad/s, so 4800 rpm = 502.6548 rad/s and
3000 rpm = 314.1593 rad/s); docs/explorer.md ("the wall thickness and outer diameter [mm],
each active bearing's station [m], K_p [N/m] and K_d [N s/m] ... The arrow keys step each value
(K_p and the grade by a factor 1.1). Each field's bounds are the design schema's
(`minimum`/`maximum` of design.schema.json) converted to the field's unit"); the schema file
docs/design.schema.json, read here as JSON (its ``exclusiveMinimum``/``exclusiveMaximum`` say
which bounds are refused), and its description of the speed, "shaft speed from 0 to 1e6 rev/min
expressed in rad/s".
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from flexshaft.design import tuned_design, with_overrides

pytest.importorskip("starlette")

from flexshaft.explore.controls import control_overrides, design_controls

SCHEMA = json.loads((Path(__file__).parents[1] / "docs" / "design.schema.json").read_text(encoding="utf-8"))
RPM = 2 * math.pi / 60  # rad/s per rpm


@pytest.fixture(scope="module")
def tuned():
    return tuned_design()


def test_a_control_state_becomes_the_design_fields(tuned) -> None:
    """Outer diameter 90 mm, wall 3 mm, actuator 1's K_d 800 N s/m and K_p 3e5 N/m, its station
    1.2 m: the design gets 0.09 m, 0.003 m, 800, 3e5 and 1.2, each in its own field and no
    other (relative 1e-15: one division by 1000)."""
    state = {
        "shaft.outer_diameter": 90.0,
        "shaft.wall_thickness": 3.0,
        "bearings[1].kd": 800.0,
        "bearings[1].kp": 3e5,
        "bearings[1].x": 1.2,
    }
    out = control_overrides(tuned, state)
    assert set(out) == set(state)
    assert out["shaft.outer_diameter"] == pytest.approx(0.09, rel=1e-15)
    assert out["shaft.wall_thickness"] == pytest.approx(0.003, rel=1e-15)
    assert (out["bearings[1].kd"], out["bearings[1].kp"], out["bearings[1].x"]) == (800.0, 3e5, 1.2)
    design = with_overrides(tuned, out)
    assert design.shaft.outer_diameter == pytest.approx(0.09, rel=1e-15)
    assert design.shaft.wall_thickness == pytest.approx(0.003, rel=1e-15)
    assert (design.bearings[1].kd, design.bearings[1].kp) == (800.0, 3e5)


def test_a_speed_given_in_rad_s_is_shown_and_set_in_rpm(tuned) -> None:
    """A design whose speed is 502.6548 rad/s shows 4800 rpm; 3000 rpm on the page sets
    314.1593 rad/s; the range is the schema's 0 to 1e6 rpm (relative 1e-12: one product)."""
    design = with_overrides(tuned, {"operating.speed_rpm": None, "operating.speed": 4800 * RPM})
    speed = next(c for c in design_controls(design) if c.key == "operating.speed")
    assert speed.unit == "rpm" and speed.paths == ("operating.speed",)
    assert speed.value == pytest.approx(4800.0, rel=1e-12)
    assert (speed.minimum, speed.maximum) == (0.0, pytest.approx(1e6, rel=1e-12))
    out = control_overrides(design, {"operating.speed": 3000.0})
    assert out == {"operating.speed": pytest.approx(3000 * RPM, rel=1e-12)}


def _schema_bounds(definition: str, name: str) -> dict:
    prop = SCHEMA["$defs"][definition]["properties"][name]
    return next((o for o in prop.get("anyOf", ()) if o.get("type") == "number"), prop)


@pytest.mark.parametrize(
    ("key", "definition", "name", "per_file_unit"),
    [
        ("shaft.wall_thickness", "Shaft", "wall_thickness", 1000.0),  # m shown in mm
        ("shaft.outer_diameter", "Shaft", "outer_diameter", 1000.0),
        ("bearings[1].kp", "ActiveBearing", "kp", 1.0),
        ("bearings[1].kd", "ActiveBearing", "kd", 1.0),
        ("operating.speed_rpm", "Operating", "speed_rpm", 1.0),
        ("loads.balance_grade", "Loads", "balance_grade", 1.0),
    ],
)
def test_ranges_are_the_schema_files(tuned, key, definition, name, per_file_unit) -> None:
    """Lower bound below upper bound, each the schema's, exclusive exactly where the schema
    says so (the grade's 0 is refused, its 4000 mm/s allowed; every other bound allowed)."""
    control = next(c for c in design_controls(tuned) if c.key == key)
    schema = _schema_bounds(definition, name)
    low = schema.get("minimum", schema.get("exclusiveMinimum"))
    high = schema.get("maximum", schema.get("exclusiveMaximum"))
    assert control.minimum < control.maximum
    assert control.minimum == pytest.approx(low * per_file_unit, rel=1e-15)
    assert control.maximum == pytest.approx(high * per_file_unit, rel=1e-15)
    assert control.exclusive_minimum == ("exclusiveMinimum" in schema)
    assert control.exclusive_maximum == ("exclusiveMaximum" in schema)


def test_gains_and_grade_step_by_a_factor(tuned) -> None:
    """docs/explorer.md: K_p and the grade step by a factor 1.1; the wall by adding."""
    controls = {c.key: c for c in design_controls(tuned)}
    for key in ("bearings[1].kp", "bearings[2].kp", "loads.balance_grade"):
        assert (controls[key].log, controls[key].step) == (True, 1.1), key
    assert not controls["shaft.wall_thickness"].log


@pytest.mark.parametrize(
    ("layup", "angle", "first_plies"),
    [
        ("(∓45/0_2)s", -45.0, (-45.0, 45.0)),  # its own value: the plies stay -45/45
        ("(∓45/0_2)s", -30.0, (-30.0, 30.0)),
        ("(±45/0_2)s", -30.0, (-30.0, 30.0)),
        ("(±45/0_2)s", 30.0, (30.0, -30.0)),
    ],
)
def test_a_pair_symbol_keeps_the_sign_of_the_first_ply(tuned, layup, angle, first_plies) -> None:
    """The layup grammar (flexshaft.design.layup.parse_layup): '±45' is 45/-45 and '∓45' is
    -45/45. A ± token's control shows its first ply's angle (-45 for '∓45'), so setting a to
    the control gives the plies a/-a, whichever sign a has (was: the token was always written
    '±|a|', so '∓45' set to its own -45 became '±45', the mirror laminate)."""
    from flexshaft.design.layup import parse_layup

    design = with_overrides(tuned, {"shaft.layup": layup})
    assert next(c for c in design_controls(design) if c.key == "layup.0").value == parse_layup(layup)[0]
    written = control_overrides(design, {"layup.0": angle})["shaft.layup"]
    assert parse_layup(written)[:2] == first_plies, written
