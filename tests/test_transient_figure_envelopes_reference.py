"""The run-up and Monte-Carlo figures draw the largest actuator, the limits and lengths in mm.

Hand-built results (plain namespaces and a small xarray Dataset, no analysis); references
derived here:

* the run-up's actuator panels show the largest over the actuators at each speed (their
  y labels: "largest over the actuators"): for forces [[1, 5, 2], [3, 2, 8]] N the curve is
  the element-wise maximum [3, 5, 8] N, the second actuator where it is the larger;
* each run-up panel's log range is ``decades`` below the largest value drawn in it, the curves'
  peaks AND the limits (runup_envelope_figure's docstring), up to twice that value: with the
  gap 1 mm above an orbit peaking at 0.05 mm the orbit panel spans [1e-3, 2] mm for 3
  decades, so the gap line is inside it; the same for a force limit of 400 N over forces up
  to 8 N: [0.4, 800] N;
* the Monte-Carlo histogram of the peak deflection is drawn in mm (its x label): a histogram
  outline spans the samples' range, so its x extent is [min, max] of the peaks × 1000.

Compared to rel 1e-12 (products of exact decimal factors, no discretisation). Agg, no file.
"""

from __future__ import annotations

from types import SimpleNamespace

import matplotlib
import numpy as np
import xarray as xr

matplotlib.use("Agg")

from flexshaft.plot.transient import montecarlo_figure, runup_envelope_figure  # noqa: E402

REL = 1e-12


def _run() -> SimpleNamespace:
    return SimpleNamespace(
        speed=np.array([100.0, 200.0, 300.0]),  # [rad/s]
        shaft_peak=np.array([1e-5, 4e-5, 2e-5]),  # [m]
        actuator_displacement=np.array([[1e-5, 5e-5, 2e-5], [2e-5, 1e-5, 4e-5]]),  # [m]
        actuator_force=np.array([[1.0, 5.0, 2.0], [3.0, 2.0, 8.0]]),  # [N]
    )


def test_runup_actuator_panels_show_the_largest_actuator():
    run = _run()
    steady = SimpleNamespace(
        speeds=run.speed,
        shaft_peak=run.shaft_peak,
        actuator_displacement=run.actuator_displacement,
        actuator_force=run.actuator_force,
    )
    fig = runup_envelope_figure({"run": run}, steady)
    _, orbit, force = fig.axes[:3]
    for label in ("run", "steady-state spin-up"):
        (o,) = [ln for ln in orbit.get_lines() if ln.get_label() == label]
        (f,) = [ln for ln in force.get_lines() if ln.get_label() == label]
        np.testing.assert_allclose(o.get_ydata(), [0.02, 0.05, 0.04], rtol=REL)  # [mm]
        np.testing.assert_allclose(f.get_ydata(), [3.0, 5.0, 8.0], rtol=REL)  # [N]


def test_runup_log_range_reaches_the_limit_lines():
    fig = runup_envelope_figure({"run": _run()}, gap=1e-3, force_limit=400.0, decades=3.0)
    _, orbit, force = fig.axes[:3]
    np.testing.assert_allclose(orbit.get_ylim(), (1e-3, 2.0), rtol=REL)  # gap 1 mm is the largest
    np.testing.assert_allclose(force.get_ylim(), (0.4, 800.0), rtol=REL)  # limit 400 N is the largest


def test_montecarlo_peak_histogram_in_mm():
    peak = np.array([0.12e-3, 0.30e-3, 0.18e-3, 0.25e-3])  # [m]
    ds = xr.Dataset(
        {
            "shaft_peak": ("sample", peak),
            "safety_factor": ("sample", np.full(4, 3.0)),
            "actuator_excursion_max": ("sample", peak),
            "actuator_load_max": ("sample", np.array([1.0, 2.0, 3.0, 4.0])),
        }
    )
    a = montecarlo_figure(ds).axes[0]
    assert "[mm]" in a.get_xlabel()
    (outline,) = a.patches
    x = outline.get_xy()[:, 0]
    np.testing.assert_allclose([x.min(), x.max()], [0.12, 0.30], rtol=REL)
