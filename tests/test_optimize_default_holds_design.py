"""The optimizer's default search holds the design it starts from (``default_variables``;
the bounds of the two-angle family itself: tests/test_optimize_default_search.py).

A search whose box excludes its own starting design cannot return it, nor anything near it:
the tuned design's layup ``(60/-60/60/-60/0/0)s`` lies outside the thesis's two-angle family
``(a/-a/b/-b)s`` (8 plies), so the default search from it found no passing design in 196
evaluations (docs/optimizer.md, the run of 2026-12-06) while a search of its own family
found 52. The references here are the rules of ``default_variables``'s docstring, checked on
ply lists expanded by hand:

* the two-angle family (a in [30, 75]°, b in [0, 30]°) when the layup is in it with its
  angles inside those bounds (or a template is given); else the design's own layup in its own
  notation, one variable per distinct angle within ±15° of its own (clamped to [0, 90]°), the
  unsigned 0° and 90° plies alternating in sign so that turning them keeps the laminate
  balanced, and held as written where they cannot pair off. Balanced: every +θ ply has a −θ
  partner, so A16 = A26 = 0 (Q̄16 and Q̄26 are odd in θ: the pair's terms cancel);
* wall, K_p and K_d ranges widened to the design's own values.

Everything is exact: angles and bounds are decimal numbers compared as written.
"""

from __future__ import annotations

import pytest

from flexshaft.design import embedded_design, with_overrides
from flexshaft.design.layup import parse_layup
from flexshaft.optimize import DesignProblem, default_variables
from flexshaft.optimize.variables import layup_template


def _same_plies(a, b) -> bool:
    """Equal ply by ply, a ply at -90° being the one at 90° (the fibre direction is a line)."""
    return len(a) == len(b) and all(p == q or abs(p) == abs(q) == 90.0 for p, q in zip(a, b))


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
    ("layup", "template", "bounds", "turned", "plies"),
    [
        # a family layup with a out of [30, 75]: its own family, 80 within [65, 90]
        (
            "(80/-80/0/0)s",
            "({a}/-{a}/{b}/{-b})s",
            {"a": (65.0, 90.0), "b": (0.0, 15.0)},
            {"a": 70.0, "b": 5.0},
            (70, -70, 5, -5, -5, 5, -70, 70),
        ),
        # shorthand kept (the pair and the ply count are notation, not angles); the one 0° ply
        # of each half has no partner to turn against: it stays
        ("[±45_2/0]s", "[±{a}_2/0]s", {"a": (30.0, 60.0)}, {"a": 40.0}, (40, -40, 40, -40, 0, 0, -40, 40, -40, 40)),
        # a written -90 keeps its sign (it is not one of the unsigned 90° plies that alternate)
        (
            "(45/-45/90/-90)s",
            "({a}/-{a}/{b}/-{b})s",
            {"a": (30.0, 60.0), "b": (75.0, 90.0)},
            {"a": 50.0, "b": 80.0},
            (50, -50, 80, -80, -80, 80, -50, 50),
        ),
        # two unsigned 90° plies: 90 and -90 are one ply, read back as 90
        (
            "(45/-45/90/90)s",
            "({a}/-{a}/{b}/{-b})s",
            {"a": (30.0, 60.0), "b": (75.0, 90.0)},
            {"a": 50.0, "b": 80.0},
            (50, -50, 80, -80, -80, 80, -50, 50),
        ),
        # a written sign stays; three unsigned zeros cannot pair off: they stay
        ("30/-30/0/0/0", "{a}/-{a}/0/0/0", {"a": (15.0, 45.0)}, {"a": 20.0}, (20, -20, 0, 0, 0)),
        # angles written with an exponent
        (
            "4.5e1/-4.5e1/0/0",
            "{a}/-{a}/{b}/{-b}",
            {"a": (30.0, 60.0), "b": (0.0, 15.0)},
            {"a": 40.0, "b": 10.0},
            (40, -40, 10, -10),
        ),
    ],
)
def test_a_derived_template_keeps_the_notation_and_turns_each_angle(layup, template, bounds, turned, plies):
    found = layup_template(layup)
    assert found is not None and found[0] == template
    assert {v.placeholder: (v.lower, v.upper) for v in found[1]} == bounds
    design = with_overrides(embedded_design("tuned"), {"shaft.layup": layup})
    problem = _problem(design)
    assert problem.layup == template
    base = problem.base_values()
    assert base is not None
    assert _same_plies(parse_layup(problem.layup_of(base)), parse_layup(layup))
    values = {f"ply_angle_{k}": v for k, v in turned.items()}
    assert parse_layup(problem.layup_of(values)) == tuple(float(p) for p in plies)


def test_a_repeated_zero_ninety_group_is_not_searched():
    """(0/90)2s: each angle is written once and repeated, so no turn of it pairs off; the
    search keeps the layup as written (no template, no ply-angle variable)."""
    assert layup_template("(0/90)2s") == ("(0/90)2s", ())
    design = with_overrides(embedded_design("tuned"), {"shaft.layup": "(0/90)2s"})
    variables, template = default_variables(design)
    assert template is None and not [v for v in variables if v.name.startswith("ply_angle")]
    assert _problem(design).base_values() is not None


def test_the_family_written_otherwise_keeps_the_familys_bounds():
    """[55/-55/0/0]s is the baseline's (55/-55/0/0)s written with brackets: the family's
    bounds, in the design's own notation (so that the design is read back)."""
    design = with_overrides(embedded_design("tuned"), {"shaft.layup": "[55/-55/0/0]s"})
    variables, template = default_variables(design)
    assert template == "[{a}/-{a}/{b}/{-b}]s"
    angles = {v.name: (v.lower, v.upper) for v in variables if v.name.startswith("ply_angle")}
    assert angles == {"ply_angle_a": (30.0, 75.0), "ply_angle_b": (0.0, 30.0)}
    assert _problem(design).base_values() is not None


def test_a_given_template_gets_the_familys_bounds():
    """``flexshaft optimize --layup T`` without ``--var``: T's a and b within the family's
    bounds, whatever the design's own layup (the meaning the option had before)."""
    variables, template = default_variables(embedded_design("tuned"), "({a}/{-a}/{b}/{-b})s")
    assert template == "({a}/{-a}/{b}/{-b})s"
    angles = {v.name: (v.lower, v.upper) for v in variables if v.name.startswith("ply_angle")}
    assert angles == {"ply_angle_a": (30.0, 75.0), "ply_angle_b": (0.0, 30.0)}


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


def test_bearings_with_their_own_gains_get_their_own_variables():
    """amb_1 at K_p 5e5, amb_2 at 8e5 (K_d 1250 both): one shared K_p cannot hold both, so each
    bearing gets its own (``amb_1_kp``, ``amb_2_kp``), K_d stays shared; the design is read back."""
    design = with_overrides(embedded_design("tuned"), {"bearings[2].kp": 8e5})
    found = {v.name: v for v in default_variables(design)[0]}
    assert found["amb_1_kp"].paths == ("bearings[1].kp",) and found["amb_2_kp"].paths == ("bearings[2].kp",)
    assert (found["amb_1_kp"].lower, found["amb_1_kp"].upper) == (1e5, 1e7)
    assert "kp" not in found and found["kd"].paths == ("bearings[1].kd", "bearings[2].kd")
    base = _problem(design).base_values()
    assert base is not None and (base["amb_1_kp"], base["amb_2_kp"], base["kd"]) == (5e5, 8e5, 1250.0)


def test_bearings_with_their_own_damping_and_unusual_names():
    """K_d 1250 and 900 N s/m: one K_d a bearing; a bearing named "1" (no identifier of its own)
    gets ``bearings_1_kd`` and ``bearings_1_x``. K_p (5e5 both) stays shared."""
    design = with_overrides(embedded_design("tuned"), {"bearings[1].name": "1", "bearings[2].kd": 900.0})
    found = {v.name: v for v in default_variables(design)[0]}
    assert found["bearings_1_kd"].paths == ("bearings[1].kd",) and found["amb_2_kd"].paths == ("bearings[2].kd",)
    assert found["kp"].paths == ("bearings[1].kp", "bearings[2].kp")
    assert found["bearings_1_x"].paths == ("bearings[1].x",) and "amb_2_x" in found
    base = _problem(design).base_values()
    assert base is not None and (base["bearings_1_kd"], base["amb_2_kd"]) == (1250.0, 900.0)
