"""The spin-up curves, map and clustered speeds of a Jeffcott rotor on an ideal PD bearing, derived here.

The Jeffcott rotor of tests/jeffcott_bearing.py (a 20 kg disk on a near-massless pinned-pinned
tube, k = 48EI/L³) with an ideal magnetic bearing at the disk (k_s = 0, k_i = 1, no lag,
collocated): the law is G(iΩ) = k_p + iΩ k_d and, in complex coordinates, the disk obeys
m r̈ + k_d ṙ + (k + k_p) r = U Ω² e^{iΩt} for an imbalance U [kg m]: a forward circle of radius

    r(Ω) = U Ω² / |k + k_p − mΩ² + iΩ k_d|,

the bearing's relative orbit is r (it is at the disk) and its force |k_p + iΩ k_d| r. The tube
deflects as a midspan-loaded beam, whose largest deflection is at midspan: the shaft's peak orbit
is the disk's. With two load cases U and 3U the worst is 3U at every speed.

* :func:`spinup_curves`: orbit and force of the worst case (3U), the force with the law's
  derivative part.
* :func:`spinup_map` on a 2 × 2 grid of (k_p, k_d): each pair's peak over the speeds is the
  largest r(Ω) of the grid of speeds, at the speed where r is largest; the actuator force
  peak the largest |G| r.
* :func:`clustered_receptance`: the spin-up curve sampled on 21 speeds has its largest sample at
  index j (found here from r(Ω)); the added speeds are the n_fine speeds from Ω_{j−1} to
  Ω_{j+1} (docstring: "between the neighbours of each peak") less those of the grid.
* :meth:`SpinupMap.best`: on a hand-made map, the smallest shaft peak whose every actuator keeps
  within the force limit (one actuator over it disqualifies the pair).

Tolerance 1e-3 relative: the tube's mass (7e-6 of the disk's) and its mesh (4 elements; the
stiffness condenses exactly onto the disk at any mesh) change the disk's response by less than
1e-4 away from the resonance (tests/test_bearing_reactions_closed_form.py holds 1e-3 at the same
model); the map's speeds stay 5 % or more from the damped peak so that the relative error is not
amplified. Written for the h26a-spinup-* mutations of scripts/mutations.toml; under 0.05 s of CPU (one
tiny model, a few dozen banded solves).
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import U, imbalance_vector, model_with
from rotors import K_SHAFT, M_DISK

import flexshaft.analyses.receptance as receptance_module
from flexshaft.analyses.spinup import SpinupMap, actuator_receptance, clustered_receptance, spinup_curves, spinup_map

KP, KD = 5.0e3, 100.0  # N/m, N s/m (k_i = 1)
PD = f'kind = "active"\nkp = {KP}\nkd = {KD}'


@pytest.fixture(scope="module")
def model():
    return model_with(PD)


def orbit(speeds, kp=KP, kd=KD, scale=1.0):
    speeds = np.asarray(speeds, dtype=float)
    return scale * U * speeds**2 / np.abs(K_SHAFT + kp - M_DISK * speeds**2 + 1j * speeds * kd)


def test_curves_report_the_worst_case_and_the_full_law_force(model):
    speeds = np.array([100.0, 200.0, 400.0])
    cases = np.stack([imbalance_vector(model), imbalance_vector(model, 3.0)], axis=1)
    curves = spinup_curves(actuator_receptance(model, speeds, cases), (KP, KD))
    r = orbit(speeds, scale=3.0)
    node = model.dofs.node_at("shaft", 0.5)
    assert curves.shaft_orbit[node] == pytest.approx(r, rel=1e-3)
    assert curves.shaft_peak == pytest.approx(r, rel=1e-3)
    assert curves.actuator_displacement[0] == pytest.approx(r, rel=1e-3)
    assert curves.actuator_force[0] == pytest.approx(np.abs(KP + 1j * speeds * KD) * r, rel=1e-3)


def test_map_peaks_and_their_speeds(model):
    speeds = np.array([150.0, 220.0, 260.0, 285.0, 330.0, 380.0])  # 5 % or more from 302 and 314 rad/s
    kp, kd = np.array([2.0e3, 1.5e5]), np.array([60.0, 300.0])  # undamped 302, 314 rad/s
    smap = spinup_map(model, kp, kd, receptance=actuator_receptance(model, speeds, imbalance_vector(model)))
    for i, p in enumerate(kp):
        for j, d in enumerate(kd):
            r = orbit(speeds, p, d)
            k = int(np.argmax(r))
            assert smap.shaft_peak[i, j] == pytest.approx(r[k], rel=1e-3)
            assert smap.shaft_peak_speed[i, j] == speeds[k]
            assert smap.actuator_displacement_peak[i, j, 0] == pytest.approx(r[k], rel=1e-3)
            force = np.abs(p + 1j * speeds * d) * r
            assert smap.actuator_force_peak[i, j, 0] == pytest.approx(force.max(), rel=1e-3)


def test_clusters_span_both_neighbours_of_the_largest_sample(model, monkeypatch):
    q1 = imbalance_vector(model)
    monkeypatch.setattr(receptance_module, "imbalance_loads", lambda _model: q1)
    grid = np.linspace(100.0, 500.0, 21)  # 20 rad/s steps; the resonance near 303 rad/s
    n_fine = 9
    rec = clustered_receptance(model, (KP, KD), grid, n_peaks=3, n_fine=n_fine)
    j = int(np.argmax(orbit(grid)))
    assert 0 < j < grid.size - 1
    fine = np.linspace(grid[j - 1], grid[j + 1], n_fine)
    expected = np.union1d(grid, fine)
    assert rec.speeds == pytest.approx(expected, rel=1e-12)
    # the clustered curve's largest value is the largest of r on those speeds
    curve = spinup_curves(rec, (KP, KD)).shaft_peak
    assert curve.max() == pytest.approx(orbit(expected).max(), rel=1e-3)


def test_best_pair_keeps_every_actuator_within_the_force_limit():
    kp, kd = np.array([1.0e4, 2.0e4]), np.array([10.0, 20.0])
    shaft = np.array([[1.0, 2.0], [3.0, 4.0]]) * 1e-4
    force = np.array([[[50.0, 500.0], [60.0, 70.0]], [[80.0, 90.0], [10.0, 20.0]]])  # (kp, kd, actuator)
    smap = SpinupMap(
        kp=kp,
        kd=kd,
        speeds=np.array([100.0, 200.0]),
        shaft_peak=shaft,
        shaft_peak_speed=np.full((2, 2), 100.0),
        actuator_displacement_peak=np.full((2, 2, 2), 1e-5),
        actuator_force_peak=force,
        actuator_names=("a", "b"),
    )
    assert smap.best() == (1.0e4, 10.0, 1.0e-4)
    # the smallest peak's actuator b carries 500 N > 100 N: the next smallest within the limit
    assert smap.best(max_actuator_force=100.0) == (1.0e4, 20.0, 2.0e-4)
    assert smap.best(max_actuator_force=65.0) == (2.0e4, 20.0, 4.0e-4)
