"""Two ``[requirements]`` limits against the rules docs/requirements.md writes down.

* ``min_onset_margin``: no whirl onset below (1 + margin) × the operating speed. A stricter
  designer may ask for no onset below 2.5 × the operating speed (margin 1.5, e.g. to clear a
  run-up overshoot); nothing in the rule caps the margin at 100 %, so 1.5 is accepted.
* ``max_sensitivity_peak``: the sensitivity S = 1/(1 + L) of every loop tends to 1 where the
  loop gain L falls off at high frequency, so its peak |S|max is at least 1 and a limit of 1
  can never be met; the docs' bound of the gain margin by the peak, GM ≥ M/(M − 1), is
  infinite at M = 1. The schema refuses 1 and accepts any value above it (1.5 here, zone A).

Exact values (a stored input) and refusals: no arithmetic. CPU: milliseconds.
"""

from __future__ import annotations

import pytest
from pydantic import ValidationError

from flexshaft.design.requirements import Requirements


def test_an_onset_margin_above_one_is_a_valid_requirement():
    assert Requirements(min_onset_margin=1.5).min_onset_margin == 1.5


def test_a_sensitivity_peak_limit_of_one_is_refused():
    with pytest.raises(ValidationError, match="max_sensitivity_peak"):
        Requirements(max_sensitivity_peak=1.0)
    assert Requirements(max_sensitivity_peak=1.5).max_sensitivity_peak == 1.5
