"""The shaft's minimum length is a length, x_end − x_start, wherever the shaft starts.

Documented rule (docs/limits.md, the quantity table: "the shaft's ``x_end − x_start`` must be at
least 1 mm too"; and its geometry list: "``x_end − x_start`` ≥ 1 mm"). A shaft from 1.0 m to
1.0005 m is 0.5 mm long and is refused, although both its stations lie far above 1 mm; the same
0.5 mm shaft at the origin is refused too, and a 1.5 mm shaft starting at 1.0 m is accepted.
The stations are exact to ~1e-16 m, far from the 0.5 mm margins, so the verdicts do not hinge on
rounding. CPU: a few pydantic validations, well under 1 ms.
"""

from __future__ import annotations

import pytest
from pydantic import ValidationError

from flexshaft.design.components import Shaft


def _shaft(x_start: float, x_end: float) -> Shaft:
    return Shaft(x_start=x_start, x_end=x_end, outer_diameter=0.05, wall_thickness=0.002, material="steel")


@pytest.mark.parametrize("x_start", [0.0, 1.0])
def test_a_half_millimetre_shaft_is_refused_wherever_it_starts(x_start):
    with pytest.raises(ValidationError, match="shaft length"):
        _shaft(x_start, x_start + 0.0005)


def test_a_shaft_of_one_and_a_half_millimetres_away_from_the_origin_is_accepted():
    assert _shaft(1.0, 1.0015).length == pytest.approx(0.0015, rel=1e-9)
