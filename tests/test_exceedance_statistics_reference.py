"""An exceedance's statistics at a confidence other than the default, and its standard error
with events, worked by hand.

References:

* the binomial proportion k/N has variance p(1 − p)/N (k binomial, variance N p (1 − p)): 3
  events of 4 give √(3/4 · 1/4 / 4) = √3/8, 1 of 10 gives √(0.09/10) = 0.3/√10;
* the one-sided Clopper–Pearson bound p_u at confidence c solves the binomial tail equation
  Σ_{i≤k} C(N, i) p_uⁱ (1 − p_u)^(N−i) = 1 − c (Clopper & Pearson 1934), summed here in exact
  rational arithmetic at the returned bound; with no event p_u = 1 − (1 − c)^(1/N) in closed
  form. At c = 0.99 the tail is 0.01, not the default's 0.05.

Tolerances: the standard errors are a few float operations (1e-14 relative); the float bound
carries 1e-16 relative error and the tail's slope is below 100 there, so 1e-10 absolute.
"""

from __future__ import annotations

import math
from fractions import Fraction
from math import comb

import pytest

from flexshaft.montecarlo import Exceedance


def _tail(k: int, n: int, p: float) -> float:
    q = Fraction(p)
    return float(sum(comb(n, i) * q**i * (1 - q) ** (n - i) for i in range(k + 1)))


def test_standard_error_of_a_proportion_with_events():
    assert Exceedance(3, 4).standard_error == pytest.approx(math.sqrt(3.0) / 8.0, rel=1e-14)
    assert Exceedance(1, 10).standard_error == pytest.approx(0.3 / math.sqrt(10.0), rel=1e-14)
    assert Exceedance(4, 4).standard_error == 0.0


@pytest.mark.parametrize(("k", "n"), [(3, 200), (1, 10)])
def test_bound_at_99_percent_leaves_one_percent_in_the_tail(k, n):
    ex = Exceedance(k, n)
    assert _tail(k, n, ex.upper_bound(0.99)) == pytest.approx(0.01, abs=1e-10)
    data = ex.to_dict(0.99)
    assert data["confidence"] == 0.99
    assert _tail(k, n, data["upper_bound"]) == pytest.approx(0.01, abs=1e-10)


def test_bound_without_events_at_99_percent_is_the_closed_form():
    assert Exceedance(0, 50).upper_bound(0.99) == pytest.approx(1.0 - 0.01 ** (1.0 / 50), rel=1e-12)
    assert Exceedance(0, 50).describe(0.99).endswith("(99 % upper bound)")
    assert f"{1.0 - 0.01 ** (1.0 / 50):.3g}" in Exceedance(0, 50).describe(0.99)
