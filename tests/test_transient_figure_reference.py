"""The run-up and Monte-Carlo figures draw speeds, limits and probabilities as labelled.

Hand-built results (plain namespaces and a small xarray Dataset, no analysis); references
derived here:

* a speed ω [rad/s] is n = 60·ω/(2π) [rpm] on the axis labelled rpm;
* the actuator gap [m] is drawn in mm (×1000), the force limit in N as given;
* the exceedance curve of N samples x_(1) ≤ … ≤ x_(N) is P(X ≥ x_(k)) = (N − k + 1)/N, from 1 at
  the smallest sample down to 1/N at the largest (decreasing: a probability of exceedance).

Compared to rel 1e-12 (no discretisation). Agg, no file.
"""

from __future__ import annotations

from types import SimpleNamespace

import matplotlib
import numpy as np
import xarray as xr

matplotlib.use("Agg")

from flexshaft.plot.transient import montecarlo_figure, runup_envelope_figure  # noqa: E402

REL = 1e-12


def test_runup_envelope_speed_in_rpm_and_the_limits_in_their_units():
    omega = np.array([10.0, 200.0, 500.0])  # [rad/s]
    run = SimpleNamespace(
        speed=omega,
        shaft_peak=np.array([1e-5, 2e-4, 1e-4]),
        actuator_displacement=np.array([[1e-6, 5e-5, 3e-5]]),
        actuator_force=np.array([[1.0, 40.0, 25.0]]),
    )
    fig = runup_envelope_figure({"10 s": run}, gap=0.25e-3, force_limit=150.0)
    shaft, orbit, force = fig.axes[:3]
    (line,) = [ln for ln in shaft.get_lines() if ln.get_label() == "10 s"]
    np.testing.assert_allclose(line.get_xdata(), omega * 60.0 / (2.0 * np.pi), rtol=REL)
    np.testing.assert_allclose(line.get_ydata(), [1e-2, 0.2, 0.1], rtol=REL)  # mm
    (gap,) = [ln for ln in orbit.get_lines() if str(ln.get_label()).startswith("gap")]
    np.testing.assert_allclose(gap.get_ydata(), [0.25, 0.25], rtol=REL)
    (limit,) = [ln for ln in force.get_lines() if str(ln.get_label()).startswith("force limit")]
    np.testing.assert_allclose(limit.get_ydata(), [150.0, 150.0], rtol=REL)


def test_montecarlo_exceedance_curves_are_p_of_x_at_least():
    excursion = np.array([0.3e-3, 0.1e-3, 0.2e-3, 0.4e-3])  # [m], N = 4
    load = np.array([30.0, 10.0, 40.0, 20.0])  # [N]
    ds = xr.Dataset(
        {
            "shaft_peak": ("sample", excursion),
            "safety_factor": ("sample", np.full(4, 3.0)),
            "actuator_excursion_max": ("sample", excursion),
            "actuator_load_max": ("sample", load),
        }
    )
    fig = montecarlo_figure(ds, gap=0.25e-3, force_limit=35.0)
    c, d = fig.axes[2], fig.axes[3]
    for ax, values, scale in ((c, excursion, 1e3), (d, load, 1.0)):
        (curve,) = [ln for ln in ax.get_lines() if ln.get_label() == "samples"]
        np.testing.assert_allclose(curve.get_xdata(), np.sort(values) * scale, rtol=REL)
        np.testing.assert_allclose(curve.get_ydata(), [4 / 4, 3 / 4, 2 / 4, 1 / 4], rtol=REL)
    (gap,) = [ln for ln in c.get_lines() if str(ln.get_label()).startswith("gap")]
    np.testing.assert_allclose(gap.get_xdata(), [0.25, 0.25], rtol=REL)
