"""A list of tables is judged by the tables the user wrote, not by those that validated.

Reference: docs/limits.md ("Counts: 1 to 64 bearings, ... 64 materials"; a temperature table
has at least two rows, docs/thermal.md: "at least two strictly increasing temperatures"): a
count is the number of tables, rows or entries written in the file. pydantic counts only the
items that validated, so a file with one bearing whose stiffness is negative used to read,
beside the stiffness's own problem, "bearings: must have at least 1 items (got 0)": a second,
false problem that sent the user looking for a missing table. The counts below are worked out
by hand from the files.
"""

from __future__ import annotations

import copy

import pytest

from flexshaft.design import DesignError, design_from_dict, embedded_design


@pytest.fixture(scope="module")
def tuned() -> dict:
    data = embedded_design("tuned").model_dump(mode="json")
    assert data["bearings"][0]["kind"] == "contact"
    return data


def problems(data: dict) -> dict[str, str]:
    with pytest.raises(DesignError) as caught:
        design_from_dict(data)
    return {problem.path: problem.message for problem in caught.value.problems}


def test_one_invalid_bearing_is_one_problem_not_a_missing_list(tuned):
    data = copy.deepcopy(tuned)
    data["bearings"] = [copy.deepcopy(tuned["bearings"][0])]
    data["bearings"][0]["stiffness"]["u"] = -1.0
    found = problems(data)
    assert list(found) == ["bearings[0].stiffness.u"], found
    assert found["bearings[0].stiffness.u"].startswith("must be >= 0 (got -1.0)")


def test_no_bearing_at_all_is_counted_as_written(tuned):
    data = copy.deepcopy(tuned)
    data["bearings"] = []
    assert problems(data) == {"bearings": "must have at least 1 items (got 0)"}


def test_too_many_bearings_are_counted_as_written(tuned):
    # 65 valid contact bearings, one above the count of 64 (the count is judged before the
    # stations: no other problem is asked for).
    data = copy.deepcopy(tuned)
    first = tuned["bearings"][0]
    data["bearings"] = [dict(copy.deepcopy(first), name=f"b{i}") for i in range(65)]
    found = problems(data)
    assert found.get("bearings") == "must have at most 64 items (got 65)", found


def test_a_one_row_temperature_table_is_counted_as_written(tuned):
    """One row whose temperature is itself invalid (below absolute zero): the row is counted,
    "got 1", not pydantic's count of the rows that validated (0)."""
    data = copy.deepcopy(tuned)
    table = data["materials"]["t700_adiprene"]["temperature_table"]
    for key in [k for k, v in table.items() if v is not None]:
        table[key] = table[key][:1]
    table["temperature_c"] = [-500.0]
    found = problems(data)
    path = "materials.t700_adiprene.temperature_table.temperature_c"
    assert found.get(path) == "must have at least 2 items (got 1)", found


def test_too_many_materials_are_counted_as_written(tuned):
    """65 valid materials, one above the count of 64: a table of tables is counted too."""
    data = copy.deepcopy(tuned)
    first = next(iter(tuned["materials"].values()))
    data["materials"] = dict(
        tuned["materials"], **{f"m{i}": copy.deepcopy(first) for i in range(65 - len(tuned["materials"]))}
    )
    assert len(data["materials"]) == 65
    assert problems(data).get("materials") == "must have at most 64 items (got 65)"
