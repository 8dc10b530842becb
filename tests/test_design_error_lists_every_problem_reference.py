"""A design with several problems in one table reports every one of them, each at its own field.

``DesignError`` (flexshaft.design.problems): "problems — Every problem found, each with a field
path and a message"; ``design_from_dict``: "Listing every schema violation with its field path".
README.md (command line): ``flexshaft check my_design.toml  # validate (--json: every problem
with its field path)``, which a user relies on to fix a file in one pass. Rule checked here,
derived from those statements: the baseline file with all four bearings named ``"hanger"`` repeats the name three
times after its first use (indices 1, 2, 3), and the error lists exactly those three paths, in
order, with the one duplicate-name message each; the validator that finds them (the bearing-name
check) collects all three in one pass, so a collector that forwards only its first finding
would name ``bearings[1]`` alone.

Validation only (no model is built): milliseconds of CPU; no floating point is compared.
"""

from __future__ import annotations

import tomllib

import pytest

from flexshaft.design.io import DesignError, design_from_dict, embedded_text


def test_every_repeated_bearing_name_is_reported() -> None:
    data = tomllib.loads(embedded_text("baseline"))
    assert len(data["bearings"]) == 4
    for bearing in data["bearings"]:
        bearing["name"] = "hanger"
    with pytest.raises(DesignError) as refused:
        design_from_dict(data)
    problems = refused.value.problems
    assert [problem.path for problem in problems] == ["bearings[1].name", "bearings[2].name", "bearings[3].name"]
    assert all(problem.message.startswith("duplicate name") for problem in problems)
    assert str(refused.value).count("duplicate name") == 3


def test_problems_of_two_fields_of_one_table_are_both_reported() -> None:
    """A shaft whose ``x_end`` lies below ``x_start`` and whose wall is not thinner than the
    radius breaks two rules of the ``[shaft]`` check (docs/limits.md, section 2: "the wall
    thinner than the radius", and ``x_end − x_start`` ≥ 1 mm): both fields are named."""
    data = tomllib.loads(embedded_text("baseline"))
    data["shaft"]["x_start"], data["shaft"]["x_end"] = 1.0, 0.5
    data["shaft"]["wall_thickness"] = data["shaft"]["outer_diameter"]  # a wall of D_o > D_o / 2
    with pytest.raises(DesignError) as refused:
        design_from_dict(data)
    paths = [problem.path for problem in refused.value.problems]
    assert "shaft.x_end" in paths and "shaft.wall_thickness" in paths
