"""A speed argument that is not a number at all is refused, never read as rest.

Reference: docs/limits.md §6 (hand-written): "Every public analysis refuses non-finite or
impossible arguments with a ``ValueError`` naming the argument and what is allowed: speeds and
frequencies must be finite and ≥ 0". ``None``, an arbitrary object or a two-element list is not
a finite number, so it is refused. Reading it as 0 rad/s instead would silently analyse the
shaft at rest (no imbalance, no gyroscopic coupling), a different physical state than asked.

The checks are a few Python comparisons: the file runs in milliseconds, no model is built.
"""

from __future__ import annotations

import pytest

from flexshaft.analyses.guards import RefusedInputError, check_speed, check_spin_speed

NOT_NUMBERS = [None, object(), [1.0, 2.0]]


@pytest.mark.parametrize("value", NOT_NUMBERS, ids=["None", "object", "list"])
def test_a_speed_that_is_not_a_number_is_refused(value):
    """check_speed and check_spin_speed refuse a non-number with a RefusedInputError (a
    ValueError) naming the argument, instead of returning a speed (0 rad/s)."""
    with pytest.raises(RefusedInputError, match="omega"):
        check_speed(value, "omega")
    with pytest.raises(RefusedInputError, match="operating speed"):
        check_spin_speed(value, "operating speed")


def test_rest_itself_is_still_a_speed():
    """The documented bound is inclusive (≥ 0): 0 and 0.0 are accepted as exactly 0 rad/s, so
    the refusal above is of the non-number, not of rest (exact: float(0) is 0.0)."""
    assert check_speed(0, "omega") == 0.0
    assert check_spin_speed(0.0) == 0.0
