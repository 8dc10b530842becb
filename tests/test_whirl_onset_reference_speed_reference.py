"""The whirl-onset requirement is measured from the operating speed, also with a speed range.

docs/requirements.md states the requirement as "no whirl onset below 1.15 x the operating speed"
(``min_onset_margin = 0.15``) and its table gives the limit of ``whirl_onset`` as
"(1 + ``min_onset_margin``) × operating speed": unlike API 684's separation margin, which is
measured from the ends of ``[operating] speed_range``, the onset limit does not move with the
range. The evidence below is built by hand with numbers exact in binary floating point
(Ω_op = 400 rad/s, margin 0.25: the limit is 1.25 × 400 = 500 rad/s exactly; range 384-448 rad/s,
so 1.25 × 448 = 560 rad/s would be the limit if it were measured from the top of the range),
so the margins compared are exact and the tolerance is zero.
"""

from __future__ import annotations

from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.evidence import Evidence

OP = 400.0  # operating speed [rad/s]
RANGE = (384.0, 448.0)  # [operating] speed_range [rad/s], OP inside
REQ = Requirements(min_onset_margin=0.25)
REQUIRED = 500.0  # (1 + 0.25) × 400, exact in binary


def _onset_check(**changes):
    values = {"operating_speed": OP, "operating_range": RANGE, "stability_max_speed": 2 * OP, **changes}
    ev = Evidence(**values)
    (check,) = [c for c in evaluate(ev, REQ).checks if c.key == "whirl_onset"]
    return check


def test_onset_limit_is_the_operating_speed_times_one_plus_margin_with_a_range():
    """An onset at 520 rad/s: 20 rad/s above (1 + 0.25) × Ω_op = 500 rad/s, so the check passes
    with margin 520 − 500 = 20 rad/s and limit 500 rad/s; measured from the top of the range
    (1.25 × 448 = 560 rad/s) it would fail by 40 rad/s."""
    check = _onset_check(onset_speed=520.0)
    assert check.status == "pass"
    assert check.limit == REQUIRED
    assert check.margin == 520.0 - REQUIRED


def test_stable_to_exactly_the_required_speed_passes_as_a_lower_bound_with_a_range():
    """No onset up to a scan that stops at exactly (1 + margin) × Ω_op = 500 rad/s: the rule's
    "with no onset up to the highest speed analysed, that speed as a lower bound" gives a margin
    of exactly 0 (a pass, lower bound), not "not evaluated" (which the docs reserve for "a
    stability analysis that stops below the required onset speed")."""
    check = _onset_check(stability_max_speed=REQUIRED)
    assert check.status == "pass"
    assert check.lower_bound
    assert check.margin == 0.0
