"""The Monte-Carlo result's figure marks each limit's exact 95 % upper confidence bound, also
when no sample exceeded it.

References:

* docs/transient.md "How sure": with k exceedances in N samples the estimate is k/N; with none
  it is 0, "which says nothing"; the figure gives at each limit (▼) the exact one-sided 95 %
  upper confidence bound (Clopper & Pearson 1934), for k = 0 the closed form 1 − 0.05^(1/N).
* For k > 0 the bound p_u is defined by the binomial tail Σ_{i≤k} C(N, i) p_uⁱ (1 − p_u)^(N−i)
  = 0.05, summed here in exact rational arithmetic at the marker's height (as
  tests/test_montecarlo_bounds.py does for the bound function itself).

Twenty hand-made samples at one active bearing: 3 excursions over its 0.5 mm gap, no force
over its 1500 N capacity, so the gap's ▼ solves the tail equation for k = 3, N = 20 (p_u =
0.3437, against the estimate 0.15) and the force's ▼ is at 1 − 0.05^(1/20) = 0.1391. Float
round-off of the beta quantile: 1e-10 absolute on the tail, 1e-12 relative on the closed form.
"""

from __future__ import annotations

from fractions import Fraction
from math import comb

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from flexshaft.montecarlo.steady import MonteCarloResult  # noqa: E402
from flexshaft.verdict.gather import ActuatorLimits  # noqa: E402

xr = pytest.importorskip("xarray")

N = 20
GAP, CAPACITY = 0.5e-3, 1500.0


def _result() -> MonteCarloResult:
    excursion = np.r_[np.full(N - 3, 0.2e-3), 0.6e-3, 0.7e-3, 0.9e-3]  # 3 over the gap
    load = np.linspace(100.0, 1400.0, N)  # none over the capacity
    data = {
        "shaft_peak": ("sample", np.linspace(1e-4, 2e-4, N)),
        "safety_factor": ("sample", np.full(N, np.nan)),
        "actuator_excursion_a": ("sample", excursion),
        "actuator_load_a": ("sample", load),
        "actuator_excursion_max": ("sample", excursion),
        "actuator_load_max": ("sample", load),
    }
    limits = {"a": ActuatorLimits(gap=GAP, force_capacity=CAPACITY)}
    return MonteCarloResult(xr.Dataset(data, coords={"sample": np.arange(N)}), limits)


def _bound_marker(panel) -> tuple[float, float]:
    """(limit, bound) of the panel's one ▼, the 95 % upper bound drawn at the limit."""
    marks = [ln for ln in panel.get_lines() if ln.get_marker() == "v"]
    assert len(marks) == 1, "no ▼ (95 % upper bound) at the limit"
    return float(marks[0].get_xdata()[0]), float(marks[0].get_ydata()[0])


def test_each_limit_carries_its_exact_upper_bound():
    import matplotlib.pyplot as plt

    fig = _result().plot()
    try:
        _, _, gap_panel, force_panel = fig.axes
        x, upper = _bound_marker(gap_panel)
        assert x == pytest.approx(GAP * 1e3, rel=1e-12)  # drawn in mm
        p = Fraction(upper)
        tail = sum(comb(N, i) * p**i * (1 - p) ** (N - i) for i in range(3 + 1))
        assert float(tail) == pytest.approx(0.05, abs=1e-10)

        # no exceedance: the estimate is 0, the bound is the number to read
        x, upper = _bound_marker(force_panel)
        assert x == pytest.approx(CAPACITY, rel=1e-12)
        assert upper == pytest.approx(1.0 - 0.05 ** (1.0 / N), rel=1e-12)
        (text,) = [t.get_text() for t in force_panel.texts]
        assert text.startswith(f"0 of {N} samples exceed")
    finally:
        plt.close(fig)
