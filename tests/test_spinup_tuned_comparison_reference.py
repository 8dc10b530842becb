"""The before/after-tuning comparison of the spin-up study (thesis figure 3.17,
:func:`flexshaft.thesis.spinup_maps.spinup_studies`) and its refined peak, on stand-ins whose
answers are written down by hand: no receptance is solved (milliseconds).

References:

* **Each case is its own gains' spin-up.** The two cases of the ``tuned`` dataset are named by
  their gains (coords ``kp``, ``kd``): the design's (K_p 1e7 N/m, K_d 0) and the tuned pair,
  the quietest of the map. The stand-in spin-up of a PD law (K_p, K_d) has a shaft peak
  P(K_p, K_d) from a hand table, an actuator orbit d(Ω) = P·(1, 2, 1)/2 at both actuators and
  an actuator force that a PD bearing transmits, |K_p + iΩK_d|·d (the law evaluated at
  s = iΩ, the docstring of :func:`~flexshaft.analyses.spinup.spinup_curves`): the dataset's
  ``shaft_peak``, ``actuator_displacement`` and ``actuator_force`` [N] of each case must be
  those of the case's gains.
* **The refined peak is a deflection.** ``refined_peak`` has units m and long name "peak on a
  refined speed grid": with a stand-in refinement that returns (1.25 × the sampled peak,
  a speed of several hundred rad/s), the two entries are 1.25 P of each case and equal the
  headline's ``peak_before`` / ``peak_after``.
* **The refined peak is never below the sampled one** (the docstring of ``_refined_peak``):
  a damped oscillator A(Ω) = 1/√((1 − r²)² + (2ζr)²), r = Ω/ω0, ζ = 1e-3, sampled exactly at
  its maximum Ω* = ω0√(1 − 2ζ²) with uneven neighbours 90 and 100.7 rad/s: the 81 fine speeds
  between them are 0.13375 rad/s apart and the nearest, 100.03125 rad/s, lies 0.3 half-widths
  (ζω0 = 0.1 rad/s) from the top, where A is 4.6 % lower (derived here, the Lorentzian near
  resonance: A/A_max ≈ 1/√(1 + 0.31²) = 0.954); so the sampled (Ω*, A(Ω*)) is returned as it
  is (no arithmetic on it: exact equality).

Tolerances: exact or 1e-12 relative (products of binary fractions and one modulus).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.assembly.model import Controller
from flexshaft.thesis import spinup_maps

KP = np.array([1e6, 1e7])  # [N/m]
KD = np.array([0.0, 1000.0])  # [N s/m]
PEAK = np.array([[8.0, 1.0], [38.0, 6.0]]) * 1e-3  # [m], P(K_p, K_d); (1e7, 0) is the design's
SPEEDS = np.array([100.0, 200.0, 300.0])  # [rad/s]
SHAPE = np.array([0.5, 1.0, 0.5])  # shaft peak over the speeds, as a fraction of P


def _peak(kp, kd):
    return float(PEAK[np.flatnonzero(KP == kp)[0], np.flatnonzero(KD == kd)[0]])


def _curves(rec, law):
    if isinstance(law, tuple):  # a surface's (kp, kd) pair: not under test here
        kp, kd, p = law[0], law[1], 0.0
    else:
        kp, kd = law[0].kp, law[0].kd
        p = _peak(kp, kd)
    d = np.tile(p * SHAPE, (2, 1))  # both actuators' orbit [m]
    return SimpleNamespace(
        shaft_peak=p * SHAPE,
        shaft_orbit=np.array([p * SHAPE]),
        actuator_displacement=d,
        actuator_force=np.abs(kp + 1j * SPEEDS * kd) * d,
    )


def _studies(monkeypatch):
    rec = SimpleNamespace(n_actuators=2, speeds=SPEEDS, shaft_x=np.array([0.0]), actuator_names=("amb_1", "amb_2"))
    smap = SimpleNamespace(
        kp=KP,
        kd=KD,
        shaft_peak=PEAK,
        actuator_displacement_peak=np.zeros((2, 2, 2)),
        to_arrays=lambda: SimpleNamespace(attrs={}),
    )
    monkeypatch.setattr(spinup_maps, "spinup_speeds", lambda model, n, **range_: None)  # any range
    monkeypatch.setattr(spinup_maps, "clustered_receptance", lambda model, laws, speeds: rec)
    monkeypatch.setattr(spinup_maps, "spinup_map", lambda model, kp, kd, receptance: smap)
    monkeypatch.setattr(spinup_maps, "spinup_curves", _curves)
    monkeypatch.setattr(
        spinup_maps,
        "_refined_peak",
        lambda model, law, speeds, curve: (1.25 * float(curve.max()), float(speeds[np.argmax(curve)]) + 7.0),
    )
    model = SimpleNamespace(actuators=[SimpleNamespace(controller=Controller.pd(1e7, 0.0))] * 2)
    grid = {"map_speeds": 3, "map_kp": KP, "map_kd": KD}
    return spinup_maps.spinup_studies(model, grid, None)


def test_each_case_is_the_spin_up_of_its_own_gains(monkeypatch):
    out = _studies(monkeypatch)
    assert out["gains_before"] == (1e7, 0.0) and out["gains_after"] == (1e6, 1000.0)
    tuned = out["tuned"]
    kp, kd = tuned.coords["kp"].values, tuned.coords["kd"].values
    for c in range(2):
        p = _peak(kp[c], kd[c])
        np.testing.assert_allclose(tuned["shaft_peak"].values[c], p * SHAPE, rtol=1e-12)
        d = tuned["actuator_displacement"].values[c]
        np.testing.assert_allclose(d, np.tile(p * SHAPE, (2, 1)), rtol=1e-12)
        force = tuned["actuator_force"].values[c]
        np.testing.assert_allclose(force, np.hypot(kp[c], SPEEDS * kd[c]) * d, rtol=1e-12)
    # the tuned case's force is the damped law's: 1e6 N/m and 1000 N s/m at 200 rad/s on 1 mm
    assert tuned["actuator_force"].values[1, 0, 1] == pytest.approx(np.hypot(1e6, 2e5) * 1e-3, rel=1e-12)


def test_the_refined_peaks_are_deflections(monkeypatch):
    out = _studies(monkeypatch)
    refined = np.asarray(out["tuned"]["refined_peak"].values)
    np.testing.assert_allclose(refined, [1.25 * 38e-3, 1.25 * 1e-3], rtol=1e-12)
    assert out["peak_before"] == refined[0] and out["peak_after"] == refined[1]
    assert out["peak_speed_before"] == out["peak_speed_after"] == 207.0


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


class _Stop(Exception):
    pass


def test_the_map_spans_the_run_up_to_the_operating_speed(monkeypatch):
    """docs/thesis-reproduction.md (the tuned design, the thesis's procedure §3.3): "map the
    spin-up peak (2-100 % of the operating speed)". On the baseline (Table 3.1 driveline,
    4800 rpm = 502.65 rad/s) the map's speeds run from 2 % to 100 % of it, the last one exactly
    the operating speed (the end point of a linspace scaled once: 1e-12 relative for the rest)."""
    from flexshaft.assembly import build_model
    from flexshaft.design import baseline_design

    seen = {}

    def capture(model, laws, speeds):
        seen["speeds"] = np.asarray(speeds)
        raise _Stop

    monkeypatch.setattr(spinup_maps, "clustered_receptance", capture)
    model = build_model(baseline_design())
    with pytest.raises(_Stop):
        spinup_maps.spinup_studies(model, {"map_speeds": 50, "map_kp": KP, "map_kd": KD}, None)
    speeds = seen["speeds"]
    assert speeds.size == 50
    assert speeds[-1] == pytest.approx(model.speed, rel=1e-12)
    assert speeds[0] == pytest.approx(0.02 * model.speed, rel=1e-12)
    assert model.speed == pytest.approx(4800 * np.pi / 30, rel=1e-12)
