"""A design path with a quoted key (``materials."t700.v2".E_T``) is read with the grammar that
sets it (:func:`flexshaft.design.io.with_overrides`): by the explorer's export, which lists the
changed keys in the file it writes, and by the optimizer, which seeds its search with the base
design's values. Both used to split the quoted name at its dot, so the export listed no change
and the optimizer could not read the base value back.

Reference: the path grammar itself (a quoted key is one key, dots and all) and the values the
test writes into the design by hand.
"""

from __future__ import annotations

import pytest

from flexshaft.design import baseline_design, design_from_dict
from flexshaft.design.io import value_at_path, with_overrides
from flexshaft.explore.export import changed_keys
from flexshaft.optimize import DesignProblem, DesignVariable

NAME = "t700.v2"
PATH = f'materials."{NAME}".E_T'


@pytest.fixture(scope="module")
def dotted():
    """The baseline with its shaft material renamed to a name holding a dot."""
    data = baseline_design().model_dump()
    data["materials"][NAME] = data["materials"].pop(data["shaft"]["material"])
    data["shaft"]["material"] = NAME
    return design_from_dict(data)


def test_value_at_path_reads_quoted_keys_indices_and_refuses_the_rest():
    data = {"a": {"b.c": [1.0, {"d": 2.0}]}}
    assert value_at_path(data, 'a."b.c"[0]') == 1.0
    assert value_at_path(data, 'a."b.c"[1].d') == 2.0
    assert value_at_path(data, "a.b.c") is None  # no key "b", the dot splits the unquoted name
    assert value_at_path(data, 'a."b.c"[2]', "absent") == "absent"
    assert value_at_path(data, "a..b", "malformed") == "malformed"


def test_the_export_lists_a_change_made_through_a_quoted_key(dotted):
    edited = with_overrides(dotted, {PATH: 1.5e8})
    assert edited.materials[NAME].E_T == 1.5e8
    assert changed_keys(dotted, edited, {PATH: 1.5e8}) == [(PATH, 1.5e8, dotted.materials[NAME].E_T)]


def test_the_optimizer_reads_the_base_value_of_a_quoted_key(dotted):
    base = dotted.materials[NAME].E_T
    problem = DesignProblem((DesignVariable(PATH, 0.5 * base, 2.0 * base),), base=dotted)
    assert problem.base_values() == {problem.variables[0].name: base}
