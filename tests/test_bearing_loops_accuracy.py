"""The bearing loops as the assessment computes them against the all-full reference (issue 30).

:func:`~flexshaft.analyses.bearing_loops.bearing_loops` refines its peaks and crossovers on
projected models checked by full solves, and keeps a crossover's first checked point when the
release rule shows it cannot set a margin. The reference is the same function with
``projected=False``: a full banded solve at every refinement step, every crossover refined to
the end. Both run on the same grid (the assessment's: the every-root check's closed-loop poles
at the point's speed), at the screening's one point per lightly damped pole or the report's
three, on:

* the embedded designs with magnetic bearings (tuned: zone A; baseline: K_d = 0, zone D) at
  every point of their envelopes, the screening's and the report's grid taking turns over the
  points (each design sees both, each point one: the points run the same code on the same
  driveline at other temperatures; CPU budget, issue 23);
* two poor loops of the tuned driveline: K_d 250 N s/m (tests/test_envelope_verdict.py's) and
  the non-collocated PID magnet with amplifier and filter lags (tests/test_loop_robustness.py's).

Tolerances (relative): the peak |S| and the gain and phase margins 1e-7 (both are full-model
values at frequencies that agree to the refinements' own tolerances: 1e-8 ω for the
crossovers, 1e-6 in ln ω for a peak, whose value then differs by about (1e-6/ζ)²/2, below 1e-7
for ζ >= 0.003; the verdict holds its values to 1e-6); the peak frequency 2e-6 and the phase
margin's frequency 1e-7 (the same tolerances on the argument).
"""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft.analyses.loop_margins as lm
from flexshaft.analyses.bearing_loops import bearing_loops
from flexshaft.analyses.root_stability import root_stability
from flexshaft.assembly import build_model
from flexshaft.design import tuned_design, with_overrides
from flexshaft.design.io import embedded_design
from flexshaft.design.points import design_at_point
from flexshaft.thermal.envelope import point_conditions

PID = {"ks": 8.47e5, "ki": 177.0, "kp": 7610.0, "kd": 3.16, "integral_gain": 4.8e4, "derivative_cutoff": 500.0}
PID.update(amplifier_bandwidth=1000.0, sensor_offset=0.04)


def _envelope_models(name: str):
    design = embedded_design(name)
    for point in design.envelope.points:
        yield point.name, build_model(design_at_point(design, point, point_conditions(design, point)))


def _poles(model):
    """The every-root check's closed-loop roots at the operating speed, as the assessment's grid
    reads them, computed at that speed alone: each root is converged on the full model at its
    speed, so they do not depend on the other speeds of the check (rest and the onset margin's;
    measured bitwise equal on the embedded designs and the PID magnet, at a third of the CPU)."""
    return root_stability(model, [model.speed]).roots_at(model.speed)


def _assert_margins_equal(fast, full) -> None:
    assert len(fast) == len(full)
    for a, b in zip(fast, full):
        m, r = a.margins, b.margins
        assert m.peak_sensitivity == pytest.approx(r.peak_sensitivity, rel=1e-7)
        assert m.peak_frequency == pytest.approx(r.peak_frequency, rel=2e-6)
        for x, y in (
            (m.gain_margin_upper_db, r.gain_margin_upper_db),
            (m.gain_margin_lower_db, r.gain_margin_lower_db),
            (m.phase_margin_deg, r.phase_margin_deg),
        ):
            assert x == y if not np.isfinite(y) else x == pytest.approx(y, rel=1e-7)
        for x, y in (
            (m.phase_margin_frequency, r.phase_margin_frequency),
            (m.gain_margin_frequency, r.gain_margin_frequency),
        ):
            assert x == y if y is None else x == pytest.approx(y, rel=1e-7)
        assert len(m.gain_crossovers) == len(r.gain_crossovers)
        assert len(m.phase_crossovers) == len(r.phase_crossovers)
        np.testing.assert_array_equal(a.sensitivity, b.sensitivity)  # the grid's values are full solves in both


@pytest.mark.parametrize("name, first", [("tuned", 1), ("baseline", 3)], ids=["tuned", "baseline"])
def test_margins_equal_the_all_full_reference_at_every_envelope_point(name, first):
    """Every envelope point against the all-full reference, at the screening's (1) and the
    report's (3) grid in turn from ``first``: tuned cold_day 1, standard_day 3, hot_day 1,
    hot_soak_start 3; baseline cold_day 3, standard_day 1, hot_soak_start 3."""
    models = list(_envelope_models(name))
    assert len(models) >= 3 and all(model.actuators for _, model in models)
    turns = [first, 4 - first] * len(models)
    for (_, model), samples in zip(models, turns):
        poles = _poles(model)
        fast = bearing_loops(model, poles=poles, peak_samples=samples)
        _assert_margins_equal(fast, bearing_loops(model, poles=poles, peak_samples=samples, projected=False))


@pytest.mark.parametrize("overrides", [{"kd": 250.0}, PID], ids=["K_d 250", "PID magnet"])
def test_margins_of_poor_loops_equal_the_all_full_reference(overrides):
    design = with_overrides(tuned_design(), {f"bearings[{i}].{k}": v for i in (1, 2) for k, v in overrides.items()})
    model = build_model(design.model_copy(update={"envelope": None}))
    poles = _poles(model)
    fast = bearing_loops(model, poles=poles, peak_samples=1)
    assert {loop.margins.zone for loop in fast} == {"D"}
    _assert_margins_equal(fast, bearing_loops(model, poles=poles, peak_samples=1, projected=False))


def test_released_crossovers_keep_their_first_checked_point(monkeypatch):
    """On the tuned design at its operating point some crossovers are released (their phase
    margins lie far above the smallest): their frequencies are those of the first full check,
    one Newton step from the crossover, within 1e-3 relative of the reference's (a twentieth of
    the grid's 5 % step: a sanity bound, the margins do not read them). With the release
    rule's safety factor infinite none is released and every crossover is the reference's to
    its refinement tolerance (1e-8 ω; asserted 1e-7)."""
    model = build_model(tuned_design().model_copy(update={"envelope": None}))
    poles = _poles(model)
    full = bearing_loops(model, poles=poles, peak_samples=1, projected=False)
    fast = bearing_loops(model, poles=poles, peak_samples=1)
    released = 0
    for a, b in zip(fast, full):
        got, expected = np.array(a.margins.gain_crossovers), np.array(b.margins.gain_crossovers)
        assert np.all(np.abs(got - expected) <= 1e-3 * expected)
        released += int(np.sum(np.abs(got - expected) > 1e-7 * expected))
        assert got[np.argmin(np.abs(got - b.margins.phase_margin_frequency))] == pytest.approx(
            b.margins.phase_margin_frequency, rel=1e-7
        )  # the crossover of the smallest margin is refined
    assert released > 0
    monkeypatch.setattr(lm, "RELEASE_SAFETY", np.inf)
    for a, b in zip(bearing_loops(model, poles=poles, peak_samples=1), full):
        np.testing.assert_allclose(a.margins.gain_crossovers, b.margins.gain_crossovers, rtol=1e-7)
        np.testing.assert_allclose(a.margins.phase_crossovers, b.margins.phase_crossovers, rtol=1e-7)
