"""The Monte-Carlo figure's exceedance curves are the samples' P(X ≥ x) between the samples too.

Reference, derived here: for N samples x_(1) < ... < x_(N) the empirical exceedance
P(X ≥ x) = #{k : x_(k) ≥ x}/N is (N − k + 1)/N at x = x_(k) and keeps that value on
(x_(k−1), x_(k)]: it drops just after each sample (left-continuous). Four force samples
[3, 1, 4, 2] N give 1 on (−, 1], 3/4 on (1, 2], 1/2 on (2, 3] and 1/4 on (3, 4]: each level,
the last, 1/N, included, is drawn over the interval that ends at its sample. The curve is read
back as the drawn line's path (matplotlib's ``Line2D.get_path``, after its step style) and
evaluated at the interval midpoints 1.5, 2.5 and 3.5; the values are exact quarters.
(The curve was drawn with ``where="post"`` before: 1/N too high between samples, 1 at 1.5.)

Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import xarray as xr

matplotlib.use("Agg")

from flexshaft.plot.transient import montecarlo_figure  # noqa: E402


def _value_at(line, x: float) -> float:
    """The drawn curve's value at x strictly inside one of its horizontal segments."""
    xy = line.get_path().vertices
    for (x0, y0), (x1, y1) in zip(xy[:-1], xy[1:], strict=True):
        if y0 == y1 and min(x0, x1) < x < max(x0, x1):
            return float(y0)
    raise AssertionError(f"no horizontal segment of the curve spans x = {x}")


def test_exceedance_is_the_share_of_samples_at_or_above_x() -> None:
    force = np.array([3.0, 1.0, 4.0, 2.0])  # [N]
    ds = xr.Dataset(
        {
            "shaft_peak": ("sample", np.full(4, 1e-4)),
            "safety_factor": ("sample", np.full(4, 3.0)),
            "actuator_excursion_max": ("sample", np.full(4, 1e-4)),
            "actuator_load_max": ("sample", force),
        }
    )
    d = montecarlo_figure(ds).axes[3]
    (curve,) = [ln for ln in d.get_lines() if ln.get_label() == "samples"]
    for x in (1.5, 2.5, 3.5):
        expected = np.count_nonzero(force >= x) / force.size
        assert _value_at(curve, x) == expected, x
    assert _value_at(curve, 3.5) == 0.25  # the last level, 1/N, drawn over (3, 4]
