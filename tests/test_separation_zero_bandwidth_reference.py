"""A resonance of zero half-power bandwidth is undamped: infinite AF, the capped API margin.

Reference (closed form): for one mode the half-power bandwidth is B = 2ζ N_c, so the
amplification factor AF = N_c / B = 1/(2ζ) grows without bound as ζ → 0; a peak whose
half-power points coincide with its speed (B = 0) is the limit ζ = 0, AF = ∞. API 617/684's
required margins then take their caps, worked by hand from
SM = min(16, 17 (1 − 1/(AF − 1.5))) % below and min(26, 10 + 17 (1 − 1/(AF − 1.5))) % above:
17 (1 − 0) = 17 > 16, so 16 % below; 10 + 17 = 27 > 26, so 26 % above. An AF of zero would
instead read as "critically damped" (AF < 2.5) and need no margin at all: the unsafe side.

Checked on :class:`~flexshaft.analyses.separation.ResonancePeak` built by hand (its
``bandwidth`` is N_2 − N_1 for a two-sided peak, 2 (N_c − N_1) or 2 (N_2 − N_c) for a one-sided
one, the limits' span for a bounded one): all four ways to a zero bandwidth. Exact arithmetic:
no tolerance. That AF = N_c/B equals Q = 1/(2ζ) on a physical peak is checked in
tests/test_separation.py::test_af_of_a_single_dof_unbalance_response_is_its_q (the single-DOF
unbalance response's peak resolved from samples, against the closed form).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.analyses.separation import ResonancePeak, required_separation_margin

N_C = 300.0  # rad/s


@pytest.mark.parametrize(
    ("lower", "upper", "lower_limit", "upper_limit"),
    [
        (N_C, N_C, N_C, N_C),  # two-sided, N_1 = N_2 = N_c
        (N_C, None, N_C, 310.0),  # one-sided from below, N_1 = N_c
        (None, N_C, 290.0, N_C),  # one-sided from above, N_2 = N_c
        (None, None, N_C, N_C),  # bounded, both limits at N_c
    ],
)
def test_a_zero_bandwidth_peak_is_undamped_and_takes_the_capped_margins(lower, upper, lower_limit, upper_limit):
    peak = ResonancePeak(N_C, 1.0, lower, upper, lower_limit, upper_limit)
    assert peak.bandwidth == 0.0
    assert peak.amplification_factor == math.inf
    assert required_separation_margin(peak.amplification_factor, "below") == 0.16
    assert required_separation_margin(peak.amplification_factor, "above") == 0.26
