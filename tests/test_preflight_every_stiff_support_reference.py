"""``model_guards`` reports every support direction the model's build refuses, not the first.

The rule (docs/limits.md, section 2, "Support stiffness against one shaft element"): a contact
stiffness above 1e8 times the element's stiffness (E I/h³ laterally, h = shaft length /
``mesh.shaft_elements``) is refused, naming the largest allowed value; ``model_guards`` returns
the build's problems "as a list of problems", so that ``flexshaft check`` shows each field to
fix (docs/limits.md: "returns them as a list of problems").

Worked by hand (derived here). A pinned-pinned tube of length L = 1 m, D_o = 0.05 m,
D_i = 0.04 m, in 8 elements (h = 0.125 m), of a soft E = 1e5 Pa (so that the limit lies within
the schema's 1e12 N/m of a stiffness): I = π(D_o⁴ − D_i⁴)/64 = 1.8113e-7 m⁴,
E I/h³ = 1e5 · 1.8113e-7/0.125³ = 9.274 N/m, limit 9.274e8 N/m. A midspan contact bearing of
1e9 N/m in v and w exceeds it in both directions: two problems, one per direction; with only v
that stiff, one problem. About 10 ms (the build stops at the check).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.analyses.preflight import model_guards
from flexshaft.design import loads_design

E, L, DO, DI, ELEMENTS = 1e5, 1.0, 0.05, 0.04, 8


def soft_tube(stiffness: str):
    return loads_design(f"""
name = "soft pinned-pinned tube on a stiff midspan bearing"
[materials.foam]
kind = "isotropic"
E = {E}
G = 4e4
density = 100.0
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "foam"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "mid"
kind = "contact"
x = {L / 2}
stiffness = {stiffness}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = {ELEMENTS}
""")


def _limit() -> float:
    inertia = math.pi * (DO**4 - DI**4) / 64
    return 1e8 * E * inertia / (L / ELEMENTS) ** 3


def test_the_hand_limit():
    assert _limit() == pytest.approx(9.274e8, rel=1e-3)
    assert 1e9 > _limit() > 1e8


def test_both_stiff_directions_are_reported():
    problems = model_guards(soft_tube("{ v = 1e9, w = 1e9 }"))
    assert sorted(p.path for p in problems) == ["bearings[0].stiffness.v", "bearings[0].stiffness.w"], problems
    assert all("9.27e+08 N/m" in p.message for p in problems)


def test_one_stiff_direction_is_reported_once():
    problems = model_guards(soft_tube("{ v = 1e9, w = 1e8 }"))
    assert [p.path for p in problems] == ["bearings[0].stiffness.v"], problems


def test_the_limit_sits_where_the_hand_sum_puts_it():
    """Within ±1 % of the hand limit 9.274e8 N/m: 9.2e8 is accepted, 9.35e8 refused."""
    problems = model_guards(soft_tube("{ v = 9.2e8, w = 9.35e8 }"))
    assert [p.path for p in problems] == ["bearings[0].stiffness.w"], problems
