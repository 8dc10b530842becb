"""The operating speed's keys and a line load's interval against what they mean, derived here.

* **One speed.** ``[operating]`` takes the shaft speed as ``speed_rpm`` n [rev/min] or as
  ``speed`` Ω [rad/s], Ω = 2πn/60. Given both, the point is defined twice: 4800 rev/min and
  4800 rad/s differ by the factor 60/(2π) ≈ 9.55, so the torque P/Ω, the gyroscopic terms and
  the imbalance force e m Ω² would follow whichever one the code happened to read. The only
  physical answer is to refuse the disagreeing pair.
* **The speed range** (docs/limits.md: "Also bounded: the speed (0 to 1e6 rev/min)"): a shaft
  turning backwards is not an operating point (a negative Ω flips the sense of the gyroscopic
  coupling and of every whirl label), so Ω = −1 rad/s is refused in rad/s as in rev/min, by
  the speed's own bound: docs/limits.md, "one `error:` line per problem naming the field, the
  value and what is allowed", so the one error names ``speed`` (``speed_rpm``), not ``power``
  through the torque check P ≤ T_max Ω; and the bound lives in the generated schema
  (docs/limits.md: "The bounds [...] are in the generated JSON schema
  (`flexshaft.design.Design.model_json_schema()`: `minimum`, `maximum` [...])"), where
  Operating.speed has the minimum 0 rad/s (exactly: the literal bound). And
  2e5 rev/min, inside the documented range, is accepted in both spellings with
  Ω = 2π·2e5/60 = 20943.95... rad/s (one multiplication and one division: relative 1e-15,
  compared at 1e-14). The top of the range, 1e6 rev/min, is accepted as Ω = 2π·1e6/60 rad/s.
* **A line load's interval.** A uniform line load q on [x_start, x_end] has the resultant
  q (x_end − x_start) (docs/testing.md's row for test_static_and_boom_line_loads_reference.py):
  an interval given backwards has a negative length, so its resultant would point against the
  load written, or vanish if the assembly found no element between the ends. It is refused;
  the same load with its ends in order is accepted, and the assembled static load of a 2 m
  shaft carrying it (``external_static_load``, no load factor) has Σ Q_v = q_y (1.5 − 0.5) =
  −250 N over the shaft nodes (a consistent load vector does the virtual work of the load on
  the rigid translation v = 1, derived here): a sum of a few terms of size ≤ 250, exact up to
  round-off, asserted to 1e-12 relative.

Written for the mutations h57f-loads-both-speeds-accepted, h57f-loads-max-speed-1e5-rpm,
h57f-loads-negative-rad-s-accepted (the torque check P ≤ T_max Ω still refuses every Ω < 0 since
P ≥ 0, but names ``power``, and the schema's minimum moves) and
h57f-loads-reversed-line-load-accepted of scripts/mutations.toml. Only the line load's static
vector assembles a model (a 4-element shaft); the rest builds the pydantic models alone.
"""

from __future__ import annotations

import math

import numpy as np
import pydantic
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load
from flexshaft.design import Design, design_from_dict
from flexshaft.design.loads import LineLoad, Operating


def _shaft_design(**loads) -> dict:
    """A 2 m aluminium tube on 4 elements, pinned at both ends, with the given ``[loads]``."""
    return {
        "name": "line load interval",
        "materials": {"al": {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0, "loss_factor": 0.0}},
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": 2.0, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 50.0e3},
        "loads": {"eccentricity": 0.0, **loads},
        "mesh": {"shaft_elements": 4},
    }


def test_a_speed_given_both_in_rpm_and_in_rad_s_is_refused():
    with pytest.raises(pydantic.ValidationError):
        Operating(speed_rpm=4800.0, speed=4800.0, power=300.0e3)


def test_either_spelling_alone_gives_the_same_operating_point():
    """Ω = 2πn/60 and T = P/Ω: 300 kW at 4800 rev/min give 300e3·60/(2π·4800) N m."""
    by_rpm = Operating(speed_rpm=4800.0, power=300.0e3)
    by_rad = Operating(speed=4800.0 * 2.0 * math.pi / 60.0, power=300.0e3)
    omega = 4800.0 * 2.0 * math.pi / 60.0
    for point in (by_rpm, by_rad):
        assert point.speed_rad_s == pytest.approx(omega, rel=1e-14)
        assert point.torque == pytest.approx(300.0e3 * 60.0 / (2.0 * math.pi * 4800.0), rel=1e-14)


def test_a_backward_spinning_shaft_is_refused_in_rad_s_as_in_rpm():
    with pytest.raises(pydantic.ValidationError) as exc:
        Operating(speed=-1.0, power=0.0)
    assert [e["loc"] for e in exc.value.errors()] == [("speed",)]  # docs/limits.md: names the field
    with pytest.raises(pydantic.ValidationError) as exc:
        Operating(speed_rpm=-1.0, power=0.0)
    assert [e["loc"] for e in exc.value.errors()] == [("speed_rpm",)]
    assert Operating(speed=0.0, power=0.0).speed_rad_s == 0.0


def test_the_schema_bounds_the_rad_s_speed_from_zero():
    """docs/limits.md: the bounds are the schema's ``minimum``; the speed is 0 to 1e6 rev/min."""
    schema = Design.model_json_schema()
    (number,) = [s for s in schema["$defs"]["Operating"]["properties"]["speed"]["anyOf"] if s["type"] == "number"]
    assert number["minimum"] == 0.0
    assert number["maximum"] == pytest.approx(1.0e6 * 2.0 * math.pi / 60.0, rel=1e-14)


@pytest.mark.parametrize("rpm", [2.0e5, 1.0e6])
def test_speeds_up_to_one_million_rpm_are_accepted_in_both_spellings(rpm):
    omega = rpm * 2.0 * math.pi / 60.0
    assert Operating(speed_rpm=rpm, power=0.0).speed_rad_s == pytest.approx(omega, rel=1e-14)
    assert Operating(speed=omega, power=0.0).speed_rad_s == pytest.approx(omega, rel=1e-14)


def test_a_line_load_given_backwards_is_refused():
    q = (0.0, -250.0, 0.0)  # N/m
    with pytest.raises(pydantic.ValidationError):
        LineLoad(name="q", on="shaft", x_start=1.5, x_end=0.5, force_per_length=q)
    forward = {"name": "q", "on": "shaft", "x_start": 0.5, "x_end": 1.5, "force_per_length": q}
    model = build_model(design_from_dict(_shaft_design(line=[forward])))
    dm = model.dofs
    Q = external_static_load(model)
    assert Q[dm.shaft(np.arange(dm.n_shaft_nodes), "v")].sum() == pytest.approx(-250.0, rel=1e-12)
