"""The design schema checks its own defaults as it checks the values a file gives.

A key left out of a design file takes the schema's default; every model of the schema derives
from :class:`flexshaft.design.fields.FrozenModel`, whose configuration validates defaults
(``validate_default``), so a default that broke its own field's bound (a developer's slip: a
negative default stiffness under ``ge=0``, a NaN where floats must be finite) is refused when
the first design omitting that key is read, not carried silently into the analyses. Every
embedded design reads under that rule (tests/test_design.py), so today's defaults obey their
bounds; this test holds the rule itself on a model with one bad default. Exact: no numerics.
"""

from __future__ import annotations

import pydantic
import pytest
from pydantic import Field

from flexshaft.design.fields import FrozenModel


class _Part(FrozenModel):
    stiffness: float = Field(-1.0e5, ge=0.0, description="[N/m]")  # the slip: a negative default


def test_a_default_outside_its_own_bound_is_refused_when_it_is_used():
    assert _Part(stiffness=2.0e5).stiffness == 2.0e5  # a value given in the file is checked as usual
    with pytest.raises(pydantic.ValidationError, match="greater than or equal to 0"):
        _Part()
