"""The before/after-tuning comparison of the spin-up study (thesis figure 3.17,
:func:`flexshaft.thesis.spinup_maps.spinup_studies`) and its refined peak: on the baseline
(Table 3.1 driveline) with a 20-speed, 2 × 2 gain map (about 0.1 s of CPU, run once for the
file), and the refinement rule on a hand-written resonance (no receptance solved).

References:

* **The actuator force is the PD law times the orbit.** The SpinupCurves docstring
  (:class:`flexshaft.analyses.spinup.SpinupCurves`, ``actuator_force``) documents the force as
  "``|C(iΩ)|`` × relative orbit for the thesis's PD bearing": the baseline's bearings are
  collocated, without amplifier lag or negative stiffness, so for a PD law C(iΩ) = K_p + iΩK_d
  of each case (coords ``kp``, ``kd``) the dataset's ``actuator_force`` [N] is
  hypot(K_p, ΩK_d) times the same case's ``actuator_displacement`` [m], element by element
  (one modulus and one product, no solve between: 1e-12 relative, a few ulp measured). The two
  cases are the design's gains (K_p 1e7 N/m, K_d 0) and the map's quietest pair, which on this
  map is another one (1e6 N/m, 1000 N s/m), so a tuned case computed with the design's law
  misses its own modulus by a factor near 10.
* **The refined peak is a deflection at its speed.** ``refined_peak`` has units m and long name
  "peak on a refined speed grid": each entry is the largest shaft orbit of its case's law at
  the headline's ``peak_speed_before`` / ``peak_speed_after``, checked against the public
  receptance solved at that one speed (the same per-speed banded solve, alone instead of in
  the fine grid: equal when measured; 1e-9 relative leaves room for round-off amplified by a
  lightly damped resonance on another BLAS kernel), and equals the headline's
  ``peak_before`` / ``peak_after``. docs/studies.md
  (lines 216-217): "Refining never lowers a peak", so it is at least the sampled
  ``shaft_peak`` of its case.
* **The map spans the run-up.** docs/thesis-reproduction.md (the tuned design, the thesis's
  procedure §3.3): "map the spin-up peak (2-100 % of the operating speed)". The public speed
  coordinate of the ``tuned`` dataset runs from exactly 0.02 to exactly 1.0 times the
  baseline's operating speed (4800 rpm = 502.65 rad/s): numpy's linspace returns its start
  (start + 0·step) and its stop (set, not summed) exactly, each scaled once by the operating
  speed, and the clustered speeds added around the resonances lie between neighbouring grid
  speeds (exact equality with the same products).
* **The refined peak is never below the sampled one** (docs/studies.md, lines 216-217:
  "Refining never lowers a peak"; the docstring of ``_refined_peak``): a damped oscillator
  A(Ω) = 1/√((1 − r²)² + (2ζr)²), r = Ω/ω0, ζ = 1e-3, sampled exactly at its maximum
  Ω* = ω0√(1 − 2ζ²) with uneven neighbours 90 and 100.7 rad/s: the 81 fine speeds between them
  are 0.13375 rad/s apart and the nearest, 100.03125 rad/s, lies 0.3135 half-widths
  (ζω0 = 0.1 rad/s) from the top, where A is 4.6 % lower (derived here, the Lorentzian near
  resonance: A/A_max ≈ 1/√(1 + 0.3135²) = 0.9542); so the sampled (Ω*, A(Ω*)) is returned as
  it is (no arithmetic on it: exact equality).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.analyses.receptance import actuator_receptance
from flexshaft.analyses.spinup import spinup_curves
from flexshaft.assembly import build_model
from flexshaft.assembly.model import Controller
from flexshaft.design import baseline_design
from flexshaft.thesis import spinup_maps


@pytest.fixture(scope="module")
def baseline():
    """The baseline model and its spin-up studies on a 20-speed, 2 × 2 gain map."""
    model = build_model(baseline_design())
    grid = {"map_speeds": 20, "map_kp": [1e6, 1e7], "map_kd": [0.0, 1000.0]}
    return model, spinup_maps.spinup_studies(model, grid, None)


def test_each_case_carries_its_own_pd_force(baseline):
    model, out = baseline
    assert all(a.controller == Controller.pd(1e7, 0.0) for a in model.actuators)  # Table 3.1's law
    assert out["gains_before"] == (1e7, 0.0)
    assert out["gains_after"] != out["gains_before"]  # the map's quietest pair is another one
    tuned = out["tuned"]
    kp, kd = tuned.coords["kp"].values, tuned.coords["kd"].values
    assert (kp[0], kd[0]) == out["gains_before"] and (kp[1], kd[1]) == out["gains_after"]
    speed = tuned.coords["speed"].values
    for c in range(2):
        d = tuned["actuator_displacement"].values[c]
        assert d.shape == (2, speed.size) and np.all(d > 0)
        force = tuned["actuator_force"].values[c]
        np.testing.assert_allclose(force / (np.hypot(kp[c], speed * kd[c]) * d) - 1, 0.0, atol=1e-12)


def test_the_refined_peaks_are_deflections_at_their_speeds(baseline):
    model, out = baseline
    tuned = out["tuned"]
    refined = np.asarray(tuned["refined_peak"].values)
    assert tuned["refined_peak"].attrs["units"] == "m"
    for c, key in enumerate(("before", "after")):
        law = [Controller.pd(*out[f"gains_{key}"])] * len(model.actuators)
        at = spinup_curves(actuator_receptance(model, [out[f"peak_speed_{key}"]]), law).shaft_peak[0]
        assert refined[c] == pytest.approx(at, rel=1e-9)
        assert refined[c] == out[f"peak_{key}"]
        assert refined[c] >= tuned["shaft_peak"].values[c].max()  # refining never lowers a peak


def test_the_map_spans_the_run_up_to_the_operating_speed(baseline):
    model, out = baseline
    assert model.speed == pytest.approx(4800 * np.pi / 30, rel=1e-12)
    speed = out["tuned"].coords["speed"].values
    assert speed.min() == 0.02 * model.speed
    assert speed.max() == model.speed


OMEGA0, ZETA = 100.0, 1e-3  # [rad/s], [-]


def _amplification(speeds):
    r = np.asarray(speeds, dtype=float) / OMEGA0
    return 1.0 / np.sqrt((1 - r**2) ** 2 + (2 * ZETA * r) ** 2)


def test_a_refinement_that_misses_the_sampled_top_keeps_it(monkeypatch):
    monkeypatch.setattr(spinup_maps, "_receptance", lambda model, speeds: np.frombuffer(speeds))
    monkeypatch.setattr(spinup_maps, "spinup_curves", lambda rec, law: SimpleNamespace(shaft_peak=_amplification(rec)))
    top = OMEGA0 * np.sqrt(1 - 2 * ZETA**2)
    speeds = np.array([80.0, 90.0, top, 100.7, 110.0])
    curve = _amplification(speeds)
    fine = np.linspace(90.0, 100.7, 81)
    assert _amplification(fine).max() < 0.96 * curve[2]  # the fine grid misses the top
    value, speed = spinup_maps._refined_peak(None, None, speeds, curve)
    assert value == float(curve[2]) and speed == float(top)
