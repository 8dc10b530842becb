"""A sweep refuses a design path set in two places, before it computes anything.

Overrides are applied ``fixed`` first, then the variables in order (``Study.overrides_at``), so
a path set twice takes the last value. A fixed value would then be stored in the results'
``fixed_overrides`` attribute but never used, and a second variable on the same path would be
a grid axis along which the design does not change. Either is a silent mistake in the user's
study, so ``Study.validate`` (which ``run_sweep`` calls before any point) refuses it and names
the path and both setters.
"""

from __future__ import annotations

import functools

import pytest

from flexshaft.sweep import Study, SweepError, Variable, run_sweep

WALLS = [0.002, 0.003]  # [m]


def wall_mm(point):
    """The output is the wall the point's design carries, in mm."""
    return {"wall_mm": 1e3 * point.design.shaft.wall_thickness}


def wall_overrides(value, scale=1.0):
    """A user mapping that sets the wall (and the diameter) from one value."""
    return {"shaft.wall_thickness": scale * value, "shaft.outer_diameter": 0.12}


def _refused(study: Study, tmp_path) -> str:
    calls_before = len(_CALLED)
    with pytest.raises(SweepError) as info:
        run_sweep(study, tmp_path / "run", progress=False)
    assert len(_CALLED) == calls_before, "the refusal must come before any point is evaluated"
    return str(info.value)


_CALLED: list[int] = []


def counted_wall_mm(point):
    _CALLED.append(point.index)
    return wall_mm(point)


def test_a_variable_on_a_fixed_path_is_refused(tmp_path):
    study = Study(
        "twice",
        [Variable(path="shaft.wall_thickness", values=WALLS)],
        ["wall_mm"],
        counted_wall_mm,
        fixed={"shaft.wall_thickness": 0.004},
    )
    message = _refused(study, tmp_path)
    assert "'shaft.wall_thickness'" in message
    assert "fixed overrides" in message and "variable 'shaft.wall_thickness'" in message


def test_two_variables_on_one_path_are_refused(tmp_path):
    study = Study(
        "twice",
        [Variable("a", WALLS, path="shaft.wall_thickness"), Variable("b", WALLS, path="shaft.wall_thickness")],
        ["wall_mm"],
        counted_wall_mm,
    )
    message = _refused(study, tmp_path)
    assert "'shaft.wall_thickness'" in message and "variable 'a'" in message and "variable 'b'" in message


def test_an_overrides_function_reaching_a_fixed_path_is_refused(tmp_path):
    study = Study(
        "twice",
        [Variable("wall", WALLS, overrides=wall_overrides)],
        ["wall_mm"],
        counted_wall_mm,
        fixed={"shaft.outer_diameter": 0.1},
    )
    message = _refused(study, tmp_path)
    assert "'shaft.outer_diameter'" in message and "variable 'wall'" in message


def test_paths_set_once_still_run_and_give_the_values_set():
    """Disjoint paths are accepted and each point's design carries its own value: the wall read
    back equals the value set. Doubling is exact in binary, so (2w)·1e3 and 2e3·w are each one
    rounding of the same exact product 2000w: equal to 1 ulp, inside the 1e-12 tolerance."""
    study = Study(
        "once",
        [Variable("wall", WALLS, overrides=functools.partial(wall_overrides, scale=2.0))],
        ["wall_mm"],
        wall_mm,
        fixed={"loads.eccentricity": 0.0},
    )
    study.validate()
    for wall in WALLS:
        design = study.design_at({"wall": wall})
        assert design.shaft.wall_thickness * 1e3 == pytest.approx(2e3 * wall, rel=1e-12)
        assert design.loads.eccentricity == 0.0


def test_one_field_written_two_ways_or_inside_its_table_is_one_path(tmp_path):
    """with_overrides reads ``shaft."wall_thickness"`` as ``shaft.wall_thickness`` (a quoted key,
    its docstring's grammar) and a value for the table ``shaft`` replaces every key in it, so
    either collides with the wall set elsewhere."""
    alias = Study(
        "alias",
        [Variable(path="shaft.wall_thickness", values=WALLS)],
        ["wall_mm"],
        counted_wall_mm,
        fixed={'shaft."wall_thickness"': 0.004},
    )
    assert "shaft.wall_thickness" in _refused(alias, tmp_path)
    table = Study(
        "table",
        [Variable("shaft", WALLS, overrides=whole_shaft)],
        ["wall_mm"],
        counted_wall_mm,
        fixed={"shaft.wall_thickness": 0.0045},
    )
    assert "'shaft'" in _refused(table, tmp_path / "table")


def whole_shaft(value):
    """A user mapping that replaces the whole [shaft] table of the baseline with a new wall."""
    from flexshaft.design import baseline_design

    shaft = baseline_design().model_dump(mode="python")["shaft"]
    return {"shaft": {**shaft, "wall_thickness": value}}


def test_a_key_refining_a_table_fixed_before_it_runs():
    """Overrides apply fixed first, then the variables: a variable on a key of a table fixed whole
    refines that table (its other keys stay as fixed), which with_overrides' own advice
    ("override the whole table instead") makes a normal study. Each point carries its own
    length and the fixed table's other keys."""
    from flexshaft.design import baseline_design

    boom = baseline_design().model_dump(mode="python")["tailboom"]
    fixed = {"tailboom": {**boom, "wall_thickness": 1.25 * boom["wall_thickness"]}}
    study = Study("refine", [Variable(path="tailboom.length", values=[8.5, 9.0])], ["wall_mm"], wall_mm, fixed=fixed)
    study.validate()
    for length in (8.5, 9.0):
        design = study.design_at({"tailboom.length": length})
        assert design.tailboom.length == length
        assert design.tailboom.wall_thickness == fixed["tailboom"]["wall_thickness"]
