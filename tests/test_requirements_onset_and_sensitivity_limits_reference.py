"""Two ``[requirements]`` limits against the rules docs/requirements.md writes down.

* ``min_onset_margin``: no whirl onset below (1 + margin) × the operating speed
  (docs/requirements.md, the `min_onset_margin` and `whirl_onset` rows). A stricter designer
  may ask for no onset below 2.5 × the operating speed (margin 1.5, e.g. to clear a run-up
  overshoot); nothing in the rule caps the margin at 100 %, so 1.5 is accepted. The schema's
  upper bound of 10 is a code choice this test does not pin down.
* ``max_sensitivity_peak``: the sensitivity S = 1/(1 + L) of every loop tends to 1 where the
  loop gain L falls off at high frequency (derived here): sup |S| ≥ 1 for every strictly
  proper loop, and |S| > 1 at a finite frequency for relative degree ≥ 2 (Bode's sensitivity
  integral), so 1 is the degenerate limit (an unfiltered PD loop of relative degree 1 can stay
  just below 1 on a finite grid). The schema refuses 1 and accepts any value above it (1.5
  here, zone A).

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
