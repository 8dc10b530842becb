"""Design-file problems name the field path, the value as given and what is allowed.

Reference: docs/design-reference.md, "Problems are reported before any computation, each with
the field path, the value and what is allowed", and its table rows quoted at each test:

* ``[[bearings]] with kind = "active"``, ``kd``: "[0, 1e9]" N s/m;
* ``[materials.<name>] with kind = "lamina"``, ``loss_E_T``: "[0, 1)" (1 itself refused);
* ``[shaft]``, ``x_end``: "greater than ``x_start``" (an empty interval refused);
* "Unknown keys are refused", names unique (fields.check_unique: "every repeated name after its
  first occurrence").

Each message is worked out by hand from those rows: the TOML path with zero-based array indices
as written in a field path (``bearings[1]`` is the second ``[[bearings]]`` table, as TOML
arrays and flexshaft's overrides count), the value as typed (Python's shortest repr of the
float) and the range in ``%g`` notation. The designs are the embedded tuned design with one key
changed (validation only: no model is built, a few ms each).
"""

from __future__ import annotations

import copy

import pytest

from flexshaft.design import DesignError, design_from_dict, embedded_design


@pytest.fixture(scope="module")
def tuned() -> dict:
    data = embedded_design("tuned").model_dump(mode="json")
    # The hand-worked paths below rely on this layout of the tuned design file.
    assert [b["kind"] for b in data["bearings"]] == ["contact", "active", "active", "contact"]
    assert data["materials"]["t700_adiprene"]["kind"] == "lamina"
    return data


def problems(data: dict) -> dict[str, str]:
    with pytest.raises(DesignError) as caught:
        design_from_dict(data)
    return {problem.path: problem.message for problem in caught.value.problems}


def changed(base: dict, *keys, value) -> dict:
    data = copy.deepcopy(base)
    target = data
    for key in keys[:-1]:
        target = target[key]
    target[keys[-1]] = value
    return data


def test_negative_gain_of_the_second_bearing(tuned):
    # kd of bearings[1] (the first active bearing) below its range [0, 1e9] N s/m.
    found = problems(changed(tuned, "bearings", 1, "kd", value=-0.12345678))
    assert found == {"bearings[1].kd": "must be >= 0 (got -0.12345678); allowed: [0, 1e+09] N s/m (see docs/limits.md)"}


def test_gain_above_its_range_shows_the_value_as_typed(tuned):
    found = problems(changed(tuned, "bearings", 2, "kd", value=1.0000001e9))
    message = "must be <= 1e+09 (got 1000000100.0); allowed: [0, 1e+09] N s/m (see docs/limits.md)"
    assert found == {"bearings[2].kd": message}


@pytest.mark.parametrize("eta", [1.0, 1.5])
def test_loss_factor_of_one_is_refused_with_an_open_upper_bound(tuned, eta):
    found = problems(changed(tuned, "materials", "t700_adiprene", "loss_E_T", value=eta))
    message = f"must be < 1 (got {eta!r}); allowed: [0, 1) (see docs/limits.md)"
    assert found == {"materials.t700_adiprene.loss_E_T": message}


def test_loss_factor_just_below_one_is_accepted(tuned):
    design = design_from_dict(changed(tuned, "materials", "t700_adiprene", "loss_E_T", value=0.999))
    assert design.materials["t700_adiprene"].loss_E_T == 0.999


def test_empty_shaft_is_reported_at_x_end(tuned):
    start = tuned["shaft"]["x_start"]
    assert start == 0.0
    found = problems(changed(tuned, "shaft", "x_end", value=start))
    assert found == {"shaft.x_end": "must be greater than x_start = 0 m (got 0.0)"}


def test_repeated_bearing_name_is_reported_at_the_repeat(tuned):
    first = tuned["bearings"][1]["name"]
    found = problems(changed(tuned, "bearings", 2, "name", value=first))
    assert found == {"bearings[2].name": f'duplicate name (got "{first}"; names must be unique)'}
