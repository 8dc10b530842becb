"""A field fixed with ``--set`` stays fixed in every candidate of the optimizer.

docs/optimizer.md: "`--set PATH=VALUE` fixes a field on every candidate, and the default
search then leaves out what it holds (`--set shaft.layup=...` leaves out the ply angles; a
gain shared by both active bearings stays searched at the bearing not set, as its own
variable `amb_2_kp` when the set gain differs) and takes its bounds from the design with the
set fields (a bearing set elsewhere bounds its neighbour's station; a set gain widens the
other bearing's range to it). With `--var`, a
path both set and searched is refused, however it is written or when the searched one is a
table holding the set one: the variable would win in every candidate (a key searched inside a
table set whole refines it)." A candidate's overrides apply the fixed ones first, then the
variables, then a layup template's layup (and its wall with a ply thickness), so before this
rule the default search's wall-thickness variable silently overrode ``--set
shaft.wall_thickness``.

No candidate is evaluated: the default search of the embedded tuned design, its variables'
paths and the problem's overrides are read directly (a few ms).
"""

from __future__ import annotations

import pytest

from flexshaft.cli.optimize import _search_around
from flexshaft.design import tuned_design, with_overrides
from flexshaft.optimize import DesignProblem, DesignVariable, OptimizeError, default_variables


def _paths(variables):
    return {p for v in variables for p in v.paths}


def test_the_default_search_leaves_out_a_set_field_and_holds_it_in_every_candidate():
    base = tuned_design()
    default = default_variables(base, None)
    assert "shaft.wall_thickness" in _paths(default[0])  # the default search has the wall
    fixed = {"shaft.wall_thickness": 0.004}
    variables, template = _search_around(default, fixed, None)
    assert _paths(variables) == _paths(default[0]) - {"shaft.wall_thickness"}
    assert template == default[1]  # the ply angles are still searched
    problem = DesignProblem(variables, base=base, layup=template, fixed=fixed)
    for x in (problem.bounds[0], problem.bounds[1]):  # both corners of the search space
        assert problem.overrides(problem.values(x))["shaft.wall_thickness"] == 0.004


def test_a_set_layup_leaves_out_the_ply_angles_and_their_template():
    base = tuned_design()
    default = default_variables(base, None)
    fixed = {"shaft.layup": "(45/-45/45/-45/0/0)s"}
    variables, template = _search_around(default, fixed, None)
    assert template is None and all(v.placeholder is None for v in variables)
    assert _paths(variables) == {p for v in default[0] if v.placeholder is None for p in v.paths}
    problem = DesignProblem(variables, base=base, layup=template, fixed=fixed)
    assert problem.overrides(problem.values(problem.bounds[0]))["shaft.layup"] == fixed["shaft.layup"]


def test_a_path_both_fixed_and_searched_is_refused():
    with pytest.raises(OptimizeError, match=r"shaft\.wall_thickness is both fixed and a variable's path"):
        DesignProblem(
            (DesignVariable("shaft.wall_thickness", 0.002, 0.003),),
            base=tuned_design(),
            fixed={"shaft.wall_thickness": 0.004},
        )


def test_a_shared_gain_stays_searched_at_the_bearing_not_set():
    """The tuned design's two active bearings share one K_p variable (docs/optimizer.md: "one
    variable shared by every active bearing when their gains are equal, else one a bearing
    (`amb_1_kp`, `amb_2_kp`)"); --set of the first's K_p holds that one and leaves the second's
    searched. The search is built on the design with the set field, whose gains now differ: the
    second's is its own variable ``amb_2_kp``, its range "widened to the design's own gains"
    (1e5-1e7 N/m holds 1e6; a set 5e7 widens the top to 5e7)."""
    from flexshaft.cli.optimize import _default_search

    default = default_variables(tuned_design(), None)
    (shared,) = [v for v in default[0] if set(v.paths) == {"bearings[1].kp", "bearings[2].kp"}]
    assert (shared.lower, shared.upper, shared.log) == (1e5, 1e7, True)
    for set_gain, top in ((1e6, 1e7), (5e7, 5e7)):
        variables, _ = _default_search(tuned_design(), {"bearings[1].kp": set_gain}, None, False)
        (kept,) = [v for v in variables if "bearings[2].kp" in v.paths]
        assert kept.paths == ("bearings[2].kp",) and kept.name == "amb_2_kp"
        assert (kept.lower, kept.upper, kept.log) == (1e5, top, True)
        assert "bearings[1].kp" not in _paths(variables)


def test_a_field_fixed_as_written_another_way_is_refused():
    """``shaft."wall_thickness"`` is ``shaft.wall_thickness`` (with_overrides' quoted-key grammar)."""
    with pytest.raises(OptimizeError, match="both fixed"):
        DesignProblem(
            (DesignVariable("shaft.wall_thickness", 0.002, 0.003),),
            base=tuned_design(),
            fixed={'shaft."wall_thickness"': 0.004},
        )


def test_a_ply_thickness_holds_the_wall_out_of_the_default_search():
    """docs/optimizer.md: "With `--ply-thickness-mm` the wall thickness follows the ply count
    (plies × ply thickness; the default search then leaves its wall variable out)", rather than
    refusing the run as if the user had set the wall too (it did before). The
    tuned design's default template (a/−a/a/−a/b/−b)s has 12 plies: a 0.25 mm ply gives a 3 mm
    wall in every candidate. Through the command, the problem is built and the run is refused
    only by its documented budget bound (docs/limits.md), before any folder is written."""
    from typer.testing import CliRunner

    from flexshaft.cli import app

    base = tuned_design()
    default = default_variables(base, None)
    variables, template = _search_around(default, ["shaft.wall_thickness"], None)
    problem = DesignProblem(variables, base=base, layup=template, ply_thickness=0.25e-3)
    for x in (problem.bounds[0], problem.bounds[1]):
        assert problem.overrides(problem.values(x))["shaft.wall_thickness"] == pytest.approx(12 * 0.25e-3, rel=1e-12)
    result = CliRunner().invoke(app, ["optimize", "--ply-thickness-mm", "0.25", "-n", "100000000"])
    assert result.exit_code == 2
    assert "--budget" in result.output and "ply_thickness" not in result.output


def test_a_key_searched_inside_a_table_fixed_whole_refines_it():
    """overrides() applies the fixed ones first: a variable on tailboom.length after a fixed
    [tailboom] table refines it (its other keys stay), so the problem is accepted and every
    candidate carries the fixed wall with its own length."""
    base = tuned_design()
    boom = base.model_dump(mode="python")["tailboom"]
    fixed = {"tailboom": {**boom, "wall_thickness": 1.25 * boom["wall_thickness"]}}
    problem = DesignProblem((DesignVariable("tailboom.length", 8.0, 9.0),), base=base, fixed=fixed)
    candidate = with_overrides(base, problem.overrides(problem.values(problem.bounds[1])))
    assert candidate.tailboom.length == 9.0
    assert candidate.tailboom.wall_thickness == fixed["tailboom"]["wall_thickness"]


def test_the_default_search_leaves_out_a_field_set_in_another_spelling_or_its_table():
    """``--set 'shaft."wall_thickness"=…'`` is the wall (with_overrides' quoted-key grammar), and
    a --set of the whole [shaft] table holds its wall too: either way the default search leaves
    the wall variable out (docs/optimizer.md: "leaves out what it holds")."""
    default = default_variables(tuned_design(), None)
    for held in ('shaft."wall_thickness"', "shaft"):
        variables, _ = _search_around(default, [held], None)
        assert "shaft.wall_thickness" not in _paths(variables)


def test_a_path_the_layup_template_writes_is_refused_however_written():
    """The template's layup, and with a ply thickness its wall, are written after the fixed
    ones and the variables: a fixed ``shaft."layup"`` or a searched ``shaft."wall_thickness"``
    (with_overrides' quoted-key grammar) would be set for nothing, as their plain spellings are
    (docs/optimizer.md: a path both set and searched is refused, "however it is written"). A
    fixed [shaft] table is refined by the template, not replaced: accepted."""
    base = tuned_design()
    angle = (DesignVariable("layup.a", 30.0, 60.0),)
    with pytest.raises(OptimizeError, match="layup"):
        DesignProblem(angle, base=base, layup="({a}/{-a})s", fixed={'shaft."layup"': "(0/90)s"})
    with pytest.raises(OptimizeError, match="wall thickness follows the ply count"):
        DesignProblem(
            (*angle, DesignVariable('shaft."wall_thickness"', 0.002, 0.003)),
            base=base,
            layup="({a}/{-a})s",
            ply_thickness=0.25e-3,
        )
    shaft = base.model_dump(mode="python")["shaft"]
    problem = DesignProblem(angle, base=base, layup="({a}/{-a})s", fixed={"shaft": shaft})
    candidate = with_overrides(base, problem.overrides(problem.values(problem.bounds[0])))
    assert candidate.shaft.layup == "(30/-30)s"


def test_a_set_neighbour_bounds_the_searched_station():
    """docs/optimizer.md: "each active bearing's station within ±1 m of its own, ≥ 0.3 m from
    its neighbours", where the design is the one every candidate starts from: the base with
    the ``--set`` fields. The tuned design's forward hanger stands at 0.7 m and amb_1 at
    3.21 m (bounds [2.21, 4.21] m: ±1 m); ``--set bearings[0].x=2.5`` moves the hanger, so
    amb_1 may come no closer than 2.5 + 0.3 = 2.8 m. Before, the bounds were those of the base
    design, and candidates put amb_1 0.2 m from the set hanger or on it."""
    from flexshaft.cli.optimize import _default_search

    variables, _ = _default_search(tuned_design(), {"bearings[0].x": 2.5}, None, False)
    (station,) = [v for v in variables if v.paths == ("bearings[1].x",)]
    assert (station.lower, station.upper) == pytest.approx((2.8, 4.21), abs=1e-12)
    assert "bearings[0].x" not in _paths(variables)  # the hanger is passive: never searched


def test_a_set_station_beyond_its_neighbour_bounds_it_from_the_other_side():
    """The same rule with amb_2 (5.63 m) set to 4.0 m: amb_1 (3.21 m) may reach up to
    4.0 − 0.3 = 3.7 m, not the base's 4.21 m, and it may not pass the set bearing."""
    from flexshaft.cli.optimize import _default_search

    variables, _ = _default_search(tuned_design(), {"bearings[2].x": 4.0}, None, False)
    (station,) = [v for v in variables if v.paths == ("bearings[1].x",)]
    assert (station.lower, station.upper) == pytest.approx((2.21, 3.7), abs=1e-12)
    assert "bearings[2].x" not in _paths(variables)


def test_a_gain_set_to_the_shared_value_keeps_the_shared_variable_at_the_other_bearing():
    """--set of the first bearing's K_p to the value both share (the tuned design's 5e5 N/m): the
    design with the set field still has equal gains, so the K_p stays one variable ("one variable
    shared by every active bearing when their gains are equal", docs/optimizer.md), searched
    at the bearing not set ("a gain shared by both active bearings stays searched at the bearing
    not set"), under its shared name and bounds."""
    from flexshaft.cli.optimize import _default_search

    (shared,) = [v for v in default_variables(tuned_design(), None)[0] if v.name == "kp"]
    variables, _ = _default_search(tuned_design(), {"bearings[1].kp": 5e5}, None, False)
    (kept,) = [v for v in variables if "bearings[2].kp" in v.paths]
    assert kept.paths == ("bearings[2].kp",) and kept.name == "kp"
    assert (kept.lower, kept.upper, kept.log) == (shared.lower, shared.upper, shared.log)
    assert "bearings[1].kp" not in _paths(variables)
