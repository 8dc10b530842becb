"""Rules of the ``[shaft]``, ``[[shaft.segments]]`` and ``[tailboom]`` tables that the design
file enforces on load (design/components.py, design/segments.py, design/fields.py).

References (documented rules and geometry derived here):

* docs/segmented-driveline.md: segments are "zones of the shaft" and results name them
  (``Model.segments``, the metal strength per segment); two zones of one name could not be told
  apart, so the second use of a name is refused at ``shaft.segments[1].name``.
* docs/model.md: "shaft ends are constrained in the DOFs listed in shaft.fixed_start /
  shaft.fixed_end". That a list naming a DOF twice is refused (at the end it concerns,
  fixed_end as well as fixed_start) is derived here, the validator's rule: the build would
  constrain the DOF once, but the size estimate of the model would count it twice.
* A layup is a stacking sequence in the notation of ``[shaft] layup`` (groups in parentheses):
  "(55/-55" opens a group it never closes, so it is no layup; a segment's layup is refused on
  load at ``shaft.segments[0].layup``, as the shaft's is, not later by the model build.
* docs/limits.md, section 2: a boom's wall must be thinner than its radius (smallest
  semi-axis), and the Tailboom docstring: "less than the smallest semi-axis". Only the
  refusal at exactly t = s is tested at the boundary (0.999 s accepted); the skin is built
  directly as a ``Tailboom``, not through a design file.

CPU about 20 ms (design files are parsed, no model is built).
"""

from __future__ import annotations

import pydantic
import pytest

from flexshaft.design import DesignError, loads_design
from flexshaft.design.components import Tailboom
from tests.rotors import jeffcott_text

SEGMENTS = """
[[shaft.segments]]
name = "{first}"
x_start = 0.0
x_end = 0.25
{extra}
[[shaft.segments]]
name = "{second}"
x_start = 0.25
x_end = 1.0
"""

LAMINA = """
[materials.glass]
kind = "lamina"
E_L = 40e9
E_T = 10e9
G_LT = 4e9
nu_LT = 0.3
density = 1900.0
X_t = 1e9
X_c = 6e8
Y_t = 4e7
Y_c = 1.2e8
S = 6e7
"""


def _with_segments(first: str, second: str, extra: str = "", text: str | None = None) -> str:
    base = jeffcott_text(0.0, 0.0) if text is None else text
    return base.replace("[[bearings]]", SEGMENTS.format(first=first, second=second, extra=extra) + "[[bearings]]", 1)


def _paths(text: str) -> list[str]:
    with pytest.raises(DesignError) as info:
        loads_design(text)
    return [problem.path for problem in info.value.problems]


def test_two_segments_of_one_name_are_refused():
    assert [t.name for t in loads_design(_with_segments("fwd", "aft")).shaft.tubes] == ["fwd", "aft"]
    assert "shaft.segments[1].name" in _paths(_with_segments("tube", "tube"))


@pytest.mark.parametrize("end", ["fixed_start", "fixed_end"])
def test_a_dof_held_twice_at_either_end_is_refused(end):
    text = jeffcott_text(0.0, 0.0)
    line = {"fixed_start": 'fixed_start = ["u", "v", "w", "theta"]', "fixed_end": 'fixed_end = ["v", "w"]'}[end]
    assert line in text
    twice = line.replace('"v", "w"', '"v", "w", "v"')
    assert f"shaft.{end}" in _paths(text.replace(line, twice))


def test_a_malformed_segment_layup_is_refused_on_load():
    composite = jeffcott_text(0.0, 0.0).replace("[shaft]", LAMINA + "[shaft]", 1)
    composite = composite.replace('material = "steel"', 'material = "glass"\nlayup = "(55/-55)s"', 1)
    good = loads_design(_with_segments("fwd", "aft", 'layup = "(45/-45)s"', text=composite))
    assert good.shaft.tubes[0].ply_angles_deg == (45.0, -45.0, -45.0, 45.0)  # own layup, inner ply first
    assert good.shaft.tubes[1].ply_angles_deg == (55.0, -55.0, -55.0, 55.0)  # the [shaft] layup
    assert "shaft.segments[0].layup" in _paths(_with_segments("fwd", "aft", 'layup = "(55/-55"', text=composite))


def _boom(wall: float) -> Tailboom:
    return Tailboom(
        length=2.0,
        root_semi_axes=(0.1, 0.08),
        tip_semi_axes=(0.06, 0.04),
        wall_thickness=wall,
        material="al",
        shaft_clearance=0.08,
    )


def test_a_boom_skin_as_thick_as_its_smallest_semi_axis_is_refused():
    assert _boom(0.999 * 0.04).wall_thickness == pytest.approx(0.03996, rel=1e-12)
    with pytest.raises(pydantic.ValidationError, match="smallest semi-axis"):
        _boom(0.04)
