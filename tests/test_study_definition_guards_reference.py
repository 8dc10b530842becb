"""A study's definition is refused before any point when it cannot make a well-formed result.

docs/studies.md: the results hold "one data variable per output over the variables'
dimensions", and everything is validated "before anything runs". So an output cannot share a
variable's name (one name cannot be both a dimension and a data variable over it), and a swept
value must be a finite number: a special axis is handed to ``evaluate`` as it is, and the
analyses it feeds refuse non-finite speeds and frequencies (docs/limits.md §6: "speeds and
frequencies must be finite and ≥ 0"), so an infinite value would only fail at that point, after
the points before it had run.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.sweep import Study, SweepError, Variable


def constant(point):
    """A stand-in evaluation; these studies are refused before it is called."""
    return {"y": 1.0}


@pytest.mark.parametrize("bad", [math.inf, -math.inf, math.nan])
def test_a_non_finite_value_is_refused_by_the_variable(bad):
    """inf, −inf and NaN in a special axis's values are each refused, naming the variable."""
    with pytest.raises(SweepError, match="speed"):
        Variable(name="speed", values=[0.0, 100.0, bad])
    Variable(name="speed", values=[0.0, 100.0, 1.0e300])  # large but finite is a value


def test_an_output_named_like_a_variable_is_refused():
    """An output 'speed' next to a variable 'speed' is refused; renamed, the same study is built."""
    speed = Variable(name="speed", values=[0.0, 100.0])
    with pytest.raises(SweepError, match="output names"):
        Study(name="clash", variables=[speed], outputs=["speed"], evaluate=constant)
    study = Study(name="clash", variables=[speed], outputs=["y"], evaluate=constant)
    assert study.shape == (2,)
