"""The exceedance line the terminal prints for a single exceeding sample.

Reference: the documented format (docs/transient.md, "Monte-Carlo imbalance": ``'12 of 1000
samples: P = 0.012, < 0.0194 (95 % upper bound)'``; the "How sure" bullet: the estimate is k/N
and the bound the exact one-sided Clopper-Pearson bound). With k = 1 exceedance the line must
say "1 of N samples", give the estimate 1/N and the bound; only k = 0 has the "P < bound" form
without an estimate (0 is no estimate). The bound for k = 1 is derived here, independently of
the code's beta quantile: it is the p_u at which one or no exceedance in N samples has
probability 1 − 0.95,

    (1 − p_u)^N + N p_u (1 − p_u)^(N−1) = 0.05,

solved by Brent's method to 1e-15; N = 20 gives p_u = 0.216106..., N = 1000 gives 0.0047350...
Both are far from a rounding edge of the three significant digits printed (0.2161 → "0.216",
0.004735 → "0.00473"), so the comparison of the text is exact on any machine.

CPU: microseconds.
"""

from __future__ import annotations

import pytest
from scipy.optimize import brentq

from flexshaft.montecarlo.confidence import Exceedance


def _one_event_bound(n: int) -> float:
    """p_u with P(at most 1 event in n | p_u) = 0.05 (binomial tail, solved by Brent)."""
    return brentq(lambda p: (1 - p) ** n + n * p * (1 - p) ** (n - 1) - 0.05, 1e-12, 1 - 1e-12, xtol=1e-15)


@pytest.mark.parametrize(("n", "estimate"), [(20, "0.05"), (1000, "0.001")])
def test_one_exceedance_is_reported_as_one_with_its_estimate(n, estimate):
    bound = _one_event_bound(n)
    assert Exceedance(1, n).upper_bound() == pytest.approx(bound, rel=1e-9)  # quantile vs tail root
    assert Exceedance(1, n).describe() == f"1 of {n} samples: P = {estimate}, < {bound:.3g} (95 % upper bound)"


def test_no_exceedance_keeps_the_bound_only_form():
    """k = 0: the closed form 1 − 0.05^(1/N) (the module docstring), no estimate printed."""
    assert Exceedance(0, 20).describe() == f"0 of 20 samples: P < {1 - 0.05 ** (1 / 20):.3g} (95 % upper bound)"
