"""Self-heating's Picard iteration rules worked by hand: the runaway boundary, the iteration
history and the onset's bisection count (hunt h46c).

* Runaway is "an iterate EXCEEDS the allowable temperature" (:class:`FixedPoint`'s docstring,
  module docstring: no fixed point below it). An update whose value is exactly the allowable
  has its fixed point AT the allowable: T₁ = T_a (not above), T₂ = T_a, |ΔT| = 0 → converged
  after two iterations, not a runaway.
* ``history`` holds the peak of each NEW iterate. The affine contraction T ← T/2 + 100 K from
  T₀ = 0 K gives T_k = 200 (1 − 2⁻ᵏ): 100, 150, 175, … (exact binary fractions); the start
  temperature itself is no iterate.
* ``runaway_onset`` bisects ``refine`` times between the last stable and the first runaway
  scale. A stand-in self-heating that runs away above 3.7 with the scales (1, 2, 4): bracket
  [2, 4], mids 3 (stable), 3.5 (stable), 3.75 (runaway) for refine = 3, so the onset is 3.75
  exactly; with one step fewer it would stay at 4. 3 + refine self-heating runs are returned.
* The iteration starts at the shaft's air (the module docstring: from below, so that it cannot
  jump over a lower fixed point). An unloaded shaft (both load scales 0) dissipates exactly
  0 W (tests/test_selfheating_load_scales_reference.py), so by the maximum principle its
  temperature is the air at the Dirichlet ends and everywhere: the first iterate equals the
  start, and the iteration converges at once (1 iteration, history [T_air]); a start anywhere
  else needs a second iterate.

Exact arithmetic (binary fractions), compared exactly; the unloaded shaft to 1e-9 K (a
sourceless tridiagonal solve, round-off). Microseconds, and ~0.1 s for the coarse baseline.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

import flexshaft as fs
import flexshaft.thermal.selfheating as selfheating
from flexshaft.design import with_overrides
from flexshaft.thermal.analysis import shaft_air_temperature
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.selfheating import fixed_point


def test_an_equilibrium_exactly_at_the_allowable_is_not_a_runaway():
    allowable = 350.0
    fp = fixed_point(lambda T: np.full_like(T, allowable), np.array([300.0, 310.0]), allowable, tol=1e-3)
    assert fp.status == "converged"
    assert fp.iterations == 2
    np.testing.assert_array_equal(fp.temperature, [allowable, allowable])
    # a hair above it is a runaway at the first iterate
    above = fixed_point(lambda T: np.full_like(T, allowable + 1e-9), np.array([300.0]), allowable)
    assert above.status == "runaway" and above.iterations == 1


def test_history_holds_each_new_iterates_peak():
    fp = fixed_point(lambda T: 0.5 * T + 100.0, np.array([0.0, 0.0]), allowable=1e4, tol=1.0)
    # T_k = 200 (1 - 2^-k): |T_k - T_{k-1}| = 100 / 2^(k-1) < 1 first at k = 8
    expected = [200.0 * (1.0 - 2.0**-k) for k in range(1, 9)]
    assert fp.status == "converged" and fp.iterations == 8
    np.testing.assert_array_equal(fp.history, expected)
    np.testing.assert_array_equal(fp.temperature, [expected[-1], expected[-1]])


def test_onset_bisection_takes_exactly_refine_steps(monkeypatch):
    threshold = 3.7
    asked = []

    def stand_in(model, options, loss_model, imbalance_scale, static_scale, **kw):
        asked.append(imbalance_scale)
        return SimpleNamespace(status="runaway" if imbalance_scale > threshold else "converged")

    monkeypatch.setattr(selfheating, "self_heating", stand_in)
    onset, results = selfheating.runaway_onset(None, [1.0, 2.0, 4.0], refine=3)
    assert onset == 3.75
    assert asked == [1.0, 2.0, 4.0, 3.0, 3.5, 3.75]
    assert len(results) == 6


def test_the_iteration_starts_at_the_shafts_air():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    air = shaft_air_temperature(design.tailboom, thermal_options(design.thermal))
    result = selfheating.self_heating(fs.build_model(design), imbalance_scale=0.0, static_scale=0.0)
    assert result.status == "converged"
    assert result.iterations == 1
    np.testing.assert_allclose(result.history, [air], rtol=0.0, atol=1e-9)
    np.testing.assert_allclose(result.element_temperature, air, rtol=0.0, atol=1e-9)
