"""Monte-Carlo bearing outputs: loads per bearing, the gap events' sample count, and the peak
refinement below the largest sample.

Hand-made unit responses (the stand-ins of tests/test_montecarlo_outputs_reference.py), so the
outputs are arithmetic (derived, linearity of Σ_b U_b e^{iψ_b} × unit response):

* the load of each active bearing is its static reaction plus the peak (over the spin-up) of
  its dynamic force's major semi-axis; a forward circle ``v = X, w = −iX`` has radius |X|
  (:func:`~flexshaft.analyses.response.orbit_amplitude`). Bearing a: 2e5 N per kg m at its
  peak speed × 1e-3 kg m = 200 N, + 10 N static = 210 N; bearing b: 100 N + 150 N = 250 N.
* the golden-section refinement of a sampled peak: a Lorentzian proxy 1/((s − s₀)² + h²) with
  s₀ = 1.1655 between the grid points 1.1 and 1.2 (0.1 apart) samples largest at 1.2, *above*
  s₀; the refinement must bracket the peak on both sides of the largest sample and land
  within width × s₀ = 2e-6 s₀ of s₀ (its docstring's narrowing).

* the gap events count a sample only when every judged bearing has a finite value there (the
  docstring of ``_count_exceeding``): excursions a = [1, 3, nan, 2], b = [0, nan, 0, 5] [m]
  against gaps 2.5 and 4 m leave samples 0 and 3, of which 3 exceeds (b: 5 > 4): 1 event in 2.

Tolerances: the unit responses are complex64 (rel 1e-6 covers its 6e-8 round-off); the
refinement's bound is the search's own stopping width.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_montecarlo_outputs_reference import _forward, _units

from flexshaft.montecarlo.samples import ImbalanceDraws, _peak_refined_speeds, sample_outputs
from flexshaft.montecarlo.steady import MonteCarloResult
from flexshaft.verdict.gather import ActuatorLimits

xr = pytest.importorskip("xarray")


def test_each_bearings_load_is_its_static_reaction_plus_its_peak_force():
    shaft = np.zeros((3, 2, 2, 1))
    act = np.zeros((3, 2, 2, 1))
    # forces per kg m at the three speeds: a peaks mid-scan (2e5), b at the first speed (1e5)
    force = np.stack([_forward([[1e5], [1e5]]), _forward([[2e5], [0.5e5]]), _forward([[1e5], [0.2e5]])])
    units = _units(shaft, act, force, offset=[0.0, 0.0], force_static=[10.0, 150.0])
    draws = ImbalanceDraws(np.array([[1e-3]]), np.array([[1.3]]), np.array([[0.5]]))
    out = sample_outputs(None, units, draws, strength=False)
    assert out["actuator_force_a"][0] == pytest.approx(200.0, rel=1e-6)
    assert out["actuator_force_b"][0] == pytest.approx(100.0, rel=1e-6)
    assert out["actuator_load_a"][0] == pytest.approx(210.0, rel=1e-6)
    assert out["actuator_load_b"][0] == pytest.approx(250.0, rel=1e-6)
    assert out["actuator_load_max"][0] == pytest.approx(250.0, rel=1e-6)


def test_the_refinement_finds_a_peak_below_its_largest_sample():
    s0, h = 1.1655, 1e-5
    speeds = np.arange(1.0, 1.55, 0.1)
    proxy = lambda s: 1.0 / ((s - s0) ** 2 + h**2)  # noqa: E731
    assert np.argmax([proxy(s) for s in speeds]) == 2  # the largest sample is 1.2 > s0
    refined = _peak_refined_speeds(proxy, speeds)
    assert np.min(np.abs(refined - s0)) < 2e-6 * s0


def test_the_gap_events_count_only_samples_finite_at_every_bearing():
    ds = xr.Dataset(
        {
            "actuator_excursion_a": ("sample", [1.0, 3.0, np.nan, 2.0]),
            "actuator_excursion_b": ("sample", [0.0, np.nan, 0.0, 5.0]),
        }
    )
    result = MonteCarloResult(ds, {"a": ActuatorLimits(2.5, None), "b": ActuatorLimits(4.0, None)})
    events = result.gap_events
    assert (events.events, events.samples) == (1, 2)
