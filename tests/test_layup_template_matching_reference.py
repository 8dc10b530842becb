"""Reading a design's ply angles back from a layup template: a fit, or nothing.

References (derived here): the template ``({a}/{-a}/{b}/{-b})s`` writes the plies
(a, −a, b, −b, −b, b, −a, a). A layup fits it when one a and one b give its plies:

* (55/−55/10/−10)s fits with a = 55°, b = 10°, and the template filled with them expands to
  the same eight plies;
* (55/−50/0/0)s fits no a: its first ply needs a = 55°, its second −a = −50°, i.e. a = 50°.

docs/optimizer.md: the first generation has "the base design's own values as its first member
when they lie in the bounds": a base design the template cannot write has no values in the
search, so it is not seeded (``base_values`` None) rather than replaced by a design that is not
the base.

Cheap: string matching, no model.
"""

from __future__ import annotations

from flexshaft.design import baseline_design, with_overrides
from flexshaft.design.layup import parse_layup
from flexshaft.optimize import DesignProblem, DesignVariable
from flexshaft.optimize.variables import TWO_ANGLE_TEMPLATE, match_layup


def _angles() -> tuple[DesignVariable, ...]:
    return (
        DesignVariable("layup.a", 30.0, 75.0, name="a", units="degree"),
        DesignVariable("layup.b", 0.0, 30.0, name="b", units="degree"),
    )


def test_a_layup_in_the_template_reads_back_its_angles():
    assert TWO_ANGLE_TEMPLATE == "({a}/{-a}/{b}/{-b})s"
    values = match_layup(TWO_ANGLE_TEMPLATE, "(55/-55/10/-10)s")
    assert values == {"a": 55.0, "b": 10.0}
    problem = DesignProblem(_angles(), layup=TWO_ANGLE_TEMPLATE)
    assert list(parse_layup(problem.layup_of(values))) == [55.0, -55.0, 10.0, -10.0, -10.0, 10.0, -55.0, 55.0]


def test_a_layup_the_template_cannot_write_is_not_matched_nor_seeded():
    assert match_layup(TWO_ANGLE_TEMPLATE, "(55/-50/0/0)s") is None  # a = 55 and a = 50 disagree
    assert match_layup(TWO_ANGLE_TEMPLATE, "(55/-55/10/-20)s") is None  # b = 10 and b = 20 disagree
    base = with_overrides(baseline_design(), {"shaft.layup": "(55/-50/0/0)s"})
    problem = DesignProblem(_angles(), base=base, layup=TWO_ANGLE_TEMPLATE)
    assert problem.base_values() is None  # not seeded: no a, b write the base's layup
