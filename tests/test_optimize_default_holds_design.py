"""The optimizer's default search holds the design it starts from (``default_variables``;
the bounds of the two-angle family itself: tests/test_optimize_default_search.py).

A search whose box excludes its own starting design cannot return it, nor anything near it:
the tuned design's layup ``(60/-60/60/-60/0/0)s`` lies outside the thesis's two-angle family
``(a/-a/b/-b)s`` (8 plies), so the default search from it found no passing design in 196
evaluations (docs/optimizer.md, the run of 2026-12-06) while a search of its own family
found 52. The references here are the rules of ``default_variables``'s docstring, checked on
ply lists expanded by hand:

* the two-angle family (a in [30, 75]°, b in [0, 30]°) when the layup is written in it with
  its angles inside those bounds; else the design's own layup in its own notation, one
  variable per distinct angle within ±15° of its own (clamped to [0, 90]°), the unsigned 0°
  and 90° plies alternating in sign so that turning them keeps the laminate balanced (every
  +θ ply has a -θ partner: A16 = A26 = 0, Jones, Mechanics of Composite Materials, 2nd ed.,
  sec. 4.3.2);
* wall, K_p and K_d ranges widened to the design's own values.

Everything is exact: angles and bounds are decimal numbers compared as written.
"""

from __future__ import annotations

import pytest

from flexshaft.design import embedded_design, with_overrides
from flexshaft.design.layup import parse_layup
from flexshaft.optimize import DesignProblem, default_variables
from flexshaft.optimize.variables import layup_template


def _problem(design) -> DesignProblem:
    variables, template = default_variables(design)
    return DesignProblem(variables, layup=template, base=design)


@pytest.mark.parametrize("name", ["baseline", "tuned", "current"])
def test_the_default_search_holds_each_embedded_design(name):
    design = embedded_design(name)
    problem = _problem(design)
    base = problem.base_values()
    assert base is not None, f"the default search from {name} excludes {name}"
    for v in problem.variables:
        assert v.lower <= base[v.name] <= v.upper
    if design.shaft.layup is not None:
        assert parse_layup(problem.layup_of(base)) == parse_layup(design.shaft.layup)


def test_the_tuned_layup_gives_its_own_family_within_fifteen_degrees():
    variables, template = default_variables(embedded_design("tuned"))
    assert template == "({a}/-{a}/{a}/-{a}/{b}/{-b})s"
    angles = {v.name: (v.lower, v.upper) for v in variables if v.name.startswith("ply_angle")}
    assert angles == {"ply_angle_a": (45.0, 75.0), "ply_angle_b": (0.0, 15.0)}
    # turned by the search, the laminate stays balanced: a = 52, b = 10 gives, inner to outer,
    # 52/-52/52/-52/10/-10 and its mirror
    problem = _problem(embedded_design("tuned"))
    plies = parse_layup(problem.layup_of({"ply_angle_a": 52.0, "ply_angle_b": 10.0}))
    half = (52.0, -52.0, 52.0, -52.0, 10.0, -10.0)
    assert plies == half + half[::-1]
    assert sorted(plies) == sorted(-p for p in plies)


def test_the_baseline_keeps_the_two_angle_family():
    variables, template = default_variables(embedded_design("baseline"))
    assert template == "({a}/{-a}/{b}/{-b})s"
    angles = {v.name: (v.lower, v.upper) for v in variables if v.name.startswith("ply_angle")}
    assert angles == {"ply_angle_a": (30.0, 75.0), "ply_angle_b": (0.0, 30.0)}


@pytest.mark.parametrize(
    ("layup", "template", "turned", "plies"),
    [
        # a family layup with a out of [30, 75]: its own family, 80 within [65, 90]
        ("(80/-80/0/0)s", "({a}/-{a}/{b}/{-b})s", {"a": 70.0, "b": 5.0}, (70, -70, 5, -5, -5, 5, -70, 70)),
        # shorthand kept: the pair and the ply count are notation, not angles
        ("[±45_2/0]s", "[±{a}_2/{b}]s", {"a": 40.0, "b": 12.0}, (40, -40, 40, -40, 12, 12, -40, 40, -40, 40)),
        # the repeat count 2 is not an angle; 0 and 90 are two magnitudes, each written once
        ("(0/90)2s", "({a}/{b})2s", {"a": 15.0, "b": 75.0}, (15, 75, 15, 75, 75, 15, 75, 15)),
        # a written -90 keeps its sign (it is not one of the unsigned 90° plies that alternate)
        ("(45/-45/90/-90)s", "({a}/-{a}/{b}/-{b})s", {"a": 50.0, "b": 80.0}, (50, -50, 80, -80, -80, 80, -50, 50)),
        # a written sign stays; the unsigned zeros alternate
        ("30/-30/0/0/0", "{a}/-{a}/{b}/{-b}/{b}", {"a": 20.0, "b": 3.0}, (20, -20, 3, -3, 3)),
    ],
)
def test_a_derived_template_keeps_the_notation_and_turns_each_angle(layup, template, turned, plies):
    found = layup_template(layup)
    assert found is not None and found[0] == template
    bounds = {v.placeholder: (v.lower, v.upper) for v in found[1]}
    for letter, magnitude in zip("ab", dict.fromkeys(abs(p) for p in parse_layup(layup))):
        assert bounds[letter] == (max(0.0, magnitude - 15.0), min(90.0, magnitude + 15.0))
    design = with_overrides(embedded_design("tuned"), {"shaft.layup": layup})
    problem = DesignProblem(found[1], layup=found[0], base=design)
    base = problem.base_values()
    assert base is not None and problem.layup_of(base) == layup.replace(" ", "")
    values = {f"ply_angle_{k}": v for k, v in turned.items()}
    assert parse_layup(problem.layup_of(values)) == tuple(float(p) for p in plies)


def test_more_than_four_angles_fall_back_to_the_two_angle_family():
    layup = "(10/20/30/40/50)s"
    assert layup_template(layup) is None
    variables, template = default_variables(with_overrides(embedded_design("tuned"), {"shaft.layup": layup}))
    assert template == "({a}/{-a}/{b}/{-b})s"


def test_ranges_widen_to_the_designs_own_wall_and_gains():
    design = with_overrides(
        embedded_design("tuned"),
        {
            "shaft.wall_thickness": 0.005,
            "bearings[1].kp": 3e7,
            "bearings[2].kp": 3e7,
            "bearings[1].kd": 5000.0,
            "bearings[2].kd": 5000.0,
        },
    )
    found = {v.name: (v.lower, v.upper) for v in default_variables(design)[0]}
    assert found["wall_thickness"] == (0.001, 0.005)
    assert found["kp"] == (1e5, 3e7)
    assert found["kd"] == (0.0, 5000.0)
    assert _problem(design).base_values() is not None


def test_a_two_angle_layup_outside_the_familys_bounds_gets_its_own_box():
    """(80/-80/0/0)s is written in the two-angle family but a = 80° > 75°: the family's box
    would exclude it, so the search is its own: a in [65, 90]°, b in [0, 15]°."""
    design = with_overrides(embedded_design("tuned"), {"shaft.layup": "(80/-80/0/0)s"})
    variables, template = default_variables(design)
    assert template == "({a}/-{a}/{b}/{-b})s"
    angles = {v.name: (v.lower, v.upper) for v in variables if v.name.startswith("ply_angle")}
    assert angles == {"ply_angle_a": (65.0, 90.0), "ply_angle_b": (0.0, 15.0)}
    assert _problem(design).base_values() is not None
