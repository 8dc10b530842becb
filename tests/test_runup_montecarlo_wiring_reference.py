"""The run-up Monte-Carlo's bookkeeping worked by hand: which draws a sample uses, how the bays'
unit envelopes combine, the peaks it reports and the exceedance counted against a limit.

:func:`~flexshaft.montecarlo.runup.runup_montecarlo` is linear in the bays' unbalances: sample
k's envelopes are Σ_b U_b h_b(t) with U_b = e_b m_b e^{iψ_b} (its docstring). Here the
transient of each bay is a stand-in whose envelopes are written down, so every output follows
by hand (no transient is integrated; milliseconds):

* two bays of rotating mass m = (2, 3) kg, a fixed eccentricity e = 1e-4 m (the ``"fixed"``
  distribution: |U_b| = e m_b, the phase ψ_b drawn);
* both bays move shaft node 0, so its envelope Σ_b e m_b e^{iψ_b} h_b(t) depends on the drawn
  angles and each sample's peak differs; bay 1 alone also moves node 1;
* shaft nodes whirl on in-phase straight lines (w = v): the orbit's major semi-axis is √2 |v|
  (not |v|);
* bearing b is moved by bay b alone, on the in-phase line v = 0.6 c_b(t), w = 0.8 c_b(t): major
  semi-axis |c_b| (not max(|v|, |w|) = 0.8 |c_b|, nor the v amplitude 0.6 |c_b|);
* bearing forces are circles of radius |f_b(t)|; the largest force is the largest bearing's,
  not a sum over bearings;
* static offsets (1e-4, 2e-4) m and static forces (30, 5) N are added per bearing before the
  largest is taken (the class docstring): excursion = max_b(orbit_b + offset_b).

The draws: sample k uses ``default_rng([seed, k])`` (docstring of the function and of
:func:`~flexshaft.montecarlo.samples.draw_imbalance`): for a fixed distribution the angles are
the generator's first ``uniform(0, 2π, n_bays)``. The default output step is π/(2 Ω_max),
four samples per period of the fastest envelope content (the docstring).

Exceedance: P(output > limit), a strict inequality (a sample at the limit does not exceed
it), with the binomial standard error √(P(1 − P)/N).

Tolerance: the envelopes travel in complex64 (the module's documented storage), so 1e-6
relative; the draws and the step are compared to 1e-15.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

import flexshaft.montecarlo.runup as runup
from flexshaft.montecarlo.runup import RunupSamples
from flexshaft.montecarlo.samples import EccentricityDistribution

MASS = np.array([2.0, 3.0])  # kg
ECC = 1e-4  # m
SPEEDS = np.array([10.0, 20.0, 30.0])  # rad/s, the run's speed at each output time
OFFSET = np.array([1e-4, 2e-4])  # m
STATIC = np.array([30.0, 5.0])  # N
# unit envelopes per bay over the three times [m/(kg m)], [N/(kg m)]
SHAFT0 = (np.array([1.0, 4.0, 2.0]), np.array([3.0, 1.0, 0.5]) * np.exp(0.3j))  # node 0, bay b
SHAFT1 = np.array([0.5, 0.2, 0.1])  # node 1, bay 1 only
ORBIT = (np.array([0.5, 1.0, 0.25]), np.array([0.2, 0.1, 0.6]))  # c_b(t), bearing b, bay b
FORCE = (np.array([100.0, 50.0, 20.0]), np.array([10.0, 300.0, 40.0]))


def _fake_run(bay: int) -> SimpleNamespace:
    n_t = SPEEDS.size
    shaft = np.zeros((2, 2, n_t), complex)  # (v/w, node, time)
    shaft[0, 0] = SHAFT0[bay]
    if bay == 1:
        shaft[0, 1] = SHAFT1
    shaft[1] = shaft[0]  # w = v: a straight line at 45 deg
    act = np.zeros((2, 2, n_t), complex)  # (bearing, v/w, time)
    act[bay, 0] = 0.6 * ORBIT[bay]
    act[bay, 1] = 0.8 * ORBIT[bay]
    force = np.zeros((2, 2, n_t), complex)
    force[bay, 0] = FORCE[bay]
    force[bay, 1] = -1j * FORCE[bay]
    return SimpleNamespace(shaft_envelope=shaft, actuator_envelope=act, actuator_force_envelope=force, speed=SPEEDS)


@pytest.fixture
def run(monkeypatch):
    steps = []

    def transient(model, profile, **kw):
        steps.append(kw["output_step"])
        return _fake_run(int(np.flatnonzero(kw["loads_per_speed_squared"])[0]))

    monkeypatch.setattr(runup, "imbalance_bays", lambda model: [(0.0, 1.0), (1.0, 2.0)])
    monkeypatch.setattr(runup, "bay_rotating_masses", lambda model: MASS)
    monkeypatch.setattr(runup, "reduce", lambda model, n: None)
    monkeypatch.setattr(runup, "default_basis_size", lambda model, speed: 4)
    monkeypatch.setattr(runup, "per_bay_imbalance_loads", lambda model, unit: np.array(unit, float))
    monkeypatch.setattr(runup, "transient_response", transient)
    monkeypatch.setattr(runup, "actuator_static_state", lambda model: (None, OFFSET, STATIC))
    profile = SimpleNamespace(max_speed=float(SPEEDS[-1]))
    out = runup.runup_montecarlo(object(), profile, 3, seed=7, distribution=EccentricityDistribution("fixed", ECC))
    return out, steps


def _angles(k: int) -> np.ndarray:
    return np.random.default_rng([7, k]).uniform(0.0, 2 * np.pi, 2)


def test_each_sample_uses_its_own_stream_of_the_steady_study(run):
    out, _ = run
    for k in range(3):
        np.testing.assert_allclose(out.draws.angle[k], _angles(k), rtol=1e-15)
    np.testing.assert_array_equal(out.draws.eccentricity, np.full((3, 2), ECC))


def test_default_output_step_is_a_quarter_period_of_the_top_speed(run):
    _, steps = run
    assert steps == [pytest.approx(math.pi / (2 * 30.0), rel=1e-15)] * 2


def test_shaft_peak_of_each_sample_sums_the_bays_with_their_drawn_phases(run):
    out, _ = run
    peaks = []
    for k in range(3):
        u = ECC * MASS * np.exp(1j * _angles(k))  # U_b = e m_b e^{iψ_b} [kg m]
        node0 = math.sqrt(2) * np.abs(u[0] * SHAFT0[0] + u[1] * SHAFT0[1])  # w = v: √2 |v|
        node1 = math.sqrt(2) * np.abs(u[1] * SHAFT1)
        per_time = np.maximum(node0, node1)
        np.testing.assert_allclose(out.shaft_peak[k], per_time.max(), rtol=1e-6)
        assert out.shaft_peak_speed[k] == SPEEDS[int(np.argmax(per_time))]
        peaks.append(per_time.max())
    assert np.ptp(peaks) > 1e-2 * max(peaks)  # the phases matter: the samples differ


def test_bearing_peaks_are_the_largest_bearing_of_the_bays_sum(run):
    out, _ = run
    u = ECC * MASS  # |U_b| [kg m]; bearing b sees bay b alone, so the phase drops out
    # major semi-axis of v = 0.6 c, w = 0.8 c is |c|: 1.0 * 2e-4 = 2e-4, 0.6 * 3e-4 = 1.8e-4
    orbit = np.array([u[0] * ORBIT[0].max(), u[1] * ORBIT[1].max()])
    load = np.array([u[0] * FORCE[0].max(), u[1] * FORCE[1].max()])  # 0.02, 0.09 N
    np.testing.assert_allclose(out.actuator_orbit_max, orbit.max(), rtol=1e-6)
    np.testing.assert_allclose(out.actuator_force_max, load.max(), rtol=1e-6)
    # static + dynamic per bearing, then the largest: 3e-4 vs 3.8e-4 m; 30.02 vs 5.09 N
    np.testing.assert_allclose(out.actuator_excursion_max, (orbit + OFFSET).max(), rtol=1e-6)
    np.testing.assert_allclose(out.actuator_load_max, (load + STATIC).max(), rtol=1e-6)


def _samples(peaks: np.ndarray) -> RunupSamples:
    zeros = np.zeros_like(peaks)
    return RunupSamples(peaks, zeros, zeros, zeros, None, zeros, zeros)  # type: ignore[arg-type]


def test_a_sample_at_the_limit_does_not_exceed_it():
    """1, 2, 3, 4 mm against 2 mm: two exceed (3 and 4), P = 1/2, √(1/4/4) = 1/4."""
    p, error = _samples(np.array([1.0, 2.0, 3.0, 4.0]) * 1e-3).exceedance("shaft_peak", 2e-3)
    assert p == 0.5
    assert error == pytest.approx(0.25, rel=1e-14)
