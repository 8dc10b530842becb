"""The layup parser's ply-count limit after a mirror, and its nesting limit, at their edges.

docs/limits.md, section 1, "Text": "the parser at most 1000 plies, repeat counts 1–100,
nesting 20". The expansions are counted by hand:

* ``(0_10)50s``: 10 plies of 0°, repeated 50 times (500), mirrored (``s``): 1000 plies, the
  limit itself, accepted. ``(0_10)100s``: 10 × 100 = 1000 plies before the mirror, 2000 after:
  refused, although it is one lone group (no ``/`` follows it, so the count after the mirror is
  the only check that sees the 2000). Likewise ``[0_10/90_10]50s``: 20 plies, × 50 = 1000,
  mirrored 2000.
* ``(±45)s`` nested in 20 groups: each group adds nothing, so 20 levels expand to the
  textbook [45, −45, −45, 45] (the standard notation: ± gives the pair 45/−45, ``s`` mirrors
  it); 21 levels exceed the documented nesting and are refused.

Text only: no laminate is built (a millisecond each). The angles are parsed from integer text
and the counts are small integers, so the comparisons are exact.
"""

from __future__ import annotations

import pytest

from flexshaft.design.layup import parse_layup


def test_a_mirrored_lone_group_is_held_to_one_thousand_plies() -> None:
    assert parse_layup("(0_10)50s") == (0.0,) * 1000
    for text in ("(0_10)100s", "[0_10/90_10]50s"):
        with pytest.raises(ValueError, match="more than 1000 plies"):
            parse_layup(text)


def test_groups_nest_twenty_deep_and_no_deeper() -> None:
    def nested(depth: int) -> str:
        return "(" * depth + "(±45)s" + ")" * depth

    # 19 plain groups around (±45)s make 20 levels of groups in all.
    assert parse_layup(nested(19)) == (45.0, -45.0, -45.0, 45.0)
    with pytest.raises(ValueError, match="nested more than 20 deep"):
        parse_layup(nested(20))
