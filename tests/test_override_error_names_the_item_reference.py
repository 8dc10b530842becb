"""An override path's error names the list item it went through (``bearings[1]``, not ``bearings``).

References (hand-written):

* ``with_overrides``'s docstring: "Paths use dots for table keys and ``[i]`` for list items"
  (README.md's example ``"bearings[1].kp": 2e6``), and flexshaft.design.io's module docstring:
  the error message lists every problem "with the field path" in that grammar
  (``bearings[2].x: 9.1 is outside the shaft [0.79, 8.05] m``).
* README.md, "Exit codes: ... 2 a user error ..., with a message naming what to change".

So when a path goes wrong below a list item, the place named in the message is that item,
written in the same grammar: ``bearings[1]`` (a bearing's table, which has keys) and
``bearings[0].x`` (a number, which cannot be indexed) -- ``bearings`` alone is the list of four
bearings, which has no keys and says nothing about which bearing. The tuned design has four
``[[bearings]]`` (counted in its file); no numerics.
"""

from __future__ import annotations

import pytest

from flexshaft.design.io import DesignError, tuned_design, with_overrides


@pytest.mark.parametrize(
    "path, place",
    [
        ("bearings[1].no_such_table.x", 'no such key "no_such_table" in bearings[1] '),
        ("bearings[0].x[1]", "bearings[0].x is not a list, cannot index [1]"),
    ],
    ids=["unknown table below an item", "index into a number of an item"],
)
def test_the_message_names_the_item_of_the_list(path: str, place: str) -> None:
    with pytest.raises(DesignError) as caught:
        with_overrides(tuned_design(), {path: 1.0})
    (problem,) = caught.value.problems
    assert problem.path == path
    assert place in problem.message, problem.message
