"""The Monte-Carlo figure marks each limit's exceedance at the right probabilities.

montecarlo_figure's docstring (the code's API contract): the upper confidence bound of the
probability is "drawn at the limit as ▼ with the count and bound written beside it (with no
exceedance the estimate is 0, and the bound is the number to read)"; _mark_bound's docstring:
"▼ at the upper confidence bound, a bar down to the estimate k/N when k > 0".

References derived here, independent of flexshaft.montecarlo:

* with k = 0 of N the one-sided 95 % Clopper-Pearson bound solves (1 − p_u)^N = 0.05, so
  p_u = 1 − 0.05^(1/N) (Clopper & Pearson 1934; the closed form by hand);
* with k > 0 the estimate is k/N by definition and the bound is an input of the figure: a
  hand-chosen number (0.3 for 2 of 20), only its position is checked.

Exact up to float round-off (rel 1e-12, no discretisation). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import xarray as xr

matplotlib.use("Agg")

from flexshaft.plot.transient import montecarlo_figure  # noqa: E402

REL = 1e-12
N = 20


def _samples() -> xr.Dataset:
    excursion = np.linspace(0.05e-3, 0.30e-3, N)  # [m]; 2 samples at or above 0.28 mm
    load = np.linspace(10.0, 40.0, N)  # [N]; none above 100 N
    return xr.Dataset(
        {
            "shaft_peak": ("sample", excursion),
            "safety_factor": ("sample", np.full(N, 3.0)),
            "actuator_excursion_max": ("sample", excursion),
            "actuator_load_max": ("sample", load),
        }
    )


def test_the_down_triangle_sits_at_the_bound_and_the_dot_at_k_over_n():
    zero_bound = 1.0 - 0.05 ** (1.0 / N)  # k = 0: (1 - p)^N = 0.05
    events = {"gap": (2, N, 0.3), "force": (0, N, zero_bound)}
    fig = montecarlo_figure(_samples(), gap=0.28e-3, force_limit=100.0, exceedances=events)
    c, d = fig.axes[2], fig.axes[3]

    # gap panel (mm): ▼ at the bound 0.3, a dot at 2/20 = 0.1, a bar between them, at x = 0.28 mm
    (tri,) = [ln for ln in c.get_lines() if ln.get_marker() == "v"]
    np.testing.assert_allclose(tri.get_xdata(), [0.28], rtol=REL)
    np.testing.assert_allclose(tri.get_ydata(), [0.3], rtol=REL)
    (dot,) = [ln for ln in c.get_lines() if ln.get_marker() == "o"]
    np.testing.assert_allclose(dot.get_ydata(), [2 / N], rtol=REL)
    (bar,) = [ln for ln in c.get_lines() if ln.get_color() == "tab:red" and ln.get_linestyle() == "-"]
    np.testing.assert_allclose(bar.get_xdata(), [0.28, 0.28], rtol=REL)
    np.testing.assert_allclose(sorted(bar.get_ydata()), [2 / N, 0.3], rtol=REL)
    assert any("2 of 20 samples exceed" in t.get_text() and "P = 0.1," in t.get_text() for t in c.texts)

    # force panel: no exceedance, the ▼ at 1 - 0.05^(1/20) = 0.1391, no estimate dot
    (tri,) = [ln for ln in d.get_lines() if ln.get_marker() == "v"]
    np.testing.assert_allclose(tri.get_xdata(), [100.0], rtol=REL)
    np.testing.assert_allclose(tri.get_ydata(), [zero_bound], rtol=REL)
    assert abs(zero_bound - 0.1391) < 1e-4  # the closed form evaluated by hand: 1 - e^(ln 0.05/20)
    assert not [ln for ln in d.get_lines() if ln.get_marker() == "o"]
    assert any(t.get_text().startswith("0 of 20 samples exceed:\nP < 0.139") for t in d.texts)
