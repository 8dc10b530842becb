"""The layup parser's size limits at their documented edges (docs/limits.md, section 1, "Text").

docs/limits.md: "a layup at most 2000 [characters] (and the parser at most 1000 plies, repeat
counts 1–100, nesting 20, ...)". So a layup that expands to exactly 1000 plies and a repeat count
of exactly 100 (a group's ``]100`` and a ply's ``_100``) are accepted; 1001 plies and a count of
101 are refused. The expansions are counted by hand:

* ``[0_10]50s``: 10 plies of 0°, repeated 50 times (500), mirrored (``s``): 1000 plies, all 0°;
  ``[0_10]50s/90`` adds one 90° ply: 1001.
* ``[0/90]100``: the pair 0/90 repeated 100 times: 200 plies alternating, 0° first.
* ``45_100``: 100 plies of 45°; ``45_101`` and ``[0/90]101`` exceed the count.

Text only: no laminate is built (a millisecond each). The comparisons are of exact small
integers and of angles parsed from integer text, so they are exact.
"""

from __future__ import annotations

import pytest

from flexshaft.design.layup import parse_layup


def test_a_layup_of_exactly_one_thousand_plies_is_accepted() -> None:
    plies = parse_layup("[0_10]50s")
    assert plies == (0.0,) * 1000
    with pytest.raises(ValueError, match="more than 1000 plies"):
        parse_layup("[0_10]50s/90")


def test_a_repeat_count_of_one_hundred_is_accepted() -> None:
    assert parse_layup("[0/90]100") == (0.0, 90.0) * 100
    assert parse_layup("45_100") == (45.0,) * 100
    for text in ("[0/90]101", "45_101"):
        with pytest.raises(ValueError, match=r"repeat count must be an integer in \[1, 100\], got '101'"):
            parse_layup(text)
