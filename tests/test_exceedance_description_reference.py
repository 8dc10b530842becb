"""The exceedance line the terminal prints for a single exceeding sample.

Reference: the documented format (docs/transient.md, "Monte-Carlo imbalance": ``'12 of 1000
samples: P = 0.012, < 0.0194 (95 % upper bound)'``; the "How sure" bullet: the estimate is k/N
and the bound the exact one-sided Clopper-Pearson bound). With k = 1 exceedance the line must
say "1 of N samples", give the estimate 1/N and the bound; only k = 0 has the "P < bound" form
without an estimate (0 is no estimate). The bound for k = 1 is derived here, independently of
the code's beta quantile: it is the p_u at which one or no exceedance in N samples has
probability 1 − 0.95,

    (1 − p_u)^N + N p_u (1 − p_u)^(N−1) = 0.05,

solved by Brent's method to 1e-15; N = 20 gives p_u = 0.2161062, N = 200 gives 0.0234985. The
expected lines are written out by hand with three significant digits: 0.2161062 → "0.216" (4.0e-4
from the nearest rounding edge, 0.2165) and 0.0234985 → "0.0235" (4.8e-5 from the edge 0.02345,
2e-3 of the value), both far beyond the bound's accuracy, so the comparison of the text is exact
on any machine; the estimates 1/20 = 0.05 and 1/200 = 0.005 print as they are.

CPU: microseconds.
"""

from __future__ import annotations

import pytest
from scipy.optimize import brentq

from flexshaft.montecarlo.confidence import Exceedance


def _one_event_bound(n: int) -> float:
    """p_u with P(at most 1 event in n | p_u) = 0.05 (binomial tail, solved by Brent)."""
    return brentq(lambda p: (1 - p) ** n + n * p * (1 - p) ** (n - 1) - 0.05, 1e-12, 1 - 1e-12, xtol=1e-15)


@pytest.mark.parametrize(
    ("n", "line"),
    [
        (20, "1 of 20 samples: P = 0.05, < 0.216 (95 % upper bound)"),
        (200, "1 of 200 samples: P = 0.005, < 0.0235 (95 % upper bound)"),
    ],
)
def test_one_exceedance_is_reported_as_one_with_its_estimate(n, line):
    """The bound against the tail root: both are accurate to about 1e-14 relative (the root is
    simple, the tail's slope N(N−1) p (1 − p)^(N−2) is about 8 at N = 200, so its 1e-16
    round-off moves the root by about 1e-17; the beta quantile is accurate to a few ulp);
    rel=1e-9 leaves room for differences between scipy versions' ``beta.ppf``. The text is
    compared exactly with the line worked by hand (module docstring)."""
    assert Exceedance(1, n).upper_bound() == pytest.approx(_one_event_bound(n), rel=1e-9)
    assert Exceedance(1, n).describe() == line


def test_no_exceedance_keeps_the_bound_only_form():
    """k = 0: docs/transient.md, "for k = 0 the closed form 1 − 0.05^(1/N)", no estimate printed.
    By hand for N = 20: 0.05^(1/20) = exp(ln 0.05 / 20) = exp(−0.1497866) = 0.8608917, so the
    bound is 0.1391083 → "0.139" (3.9e-4 from the edge 0.1395)."""
    assert Exceedance(0, 20).describe() == "0 of 20 samples: P < 0.139 (95 % upper bound)"
