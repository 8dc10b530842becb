"""The spin-up's worst load case on its every path, and the gain map's displacement limit, by hand.

The Jeffcott rotor of tests/jeffcott_bearing.py (a 20 kg disk at midspan of a near-massless
pinned-pinned tube, k = 48EI/L³, L = 1 m) with an ideal PD magnetic bearing at the disk (k_i = 1,
k_s = 0, no lag), G(iΩ) = k_p + iΩ k_d. Two imbalance cases at the disk, U and 3U (in this order,
so that the first is not the worst): every reported envelope is the worst case's, 3U.

* **Collocated map** (:func:`spinup_map`): the disk's forward circle r(Ω) = UΩ²/|k + k_p − mΩ²
  + iΩk_d| (tests/test_spinup_pd_bearing_reference.py), so each gain pair's shaft peak is
  3 max_Ω r(Ω).
* **Non-collocated sensor** (``sensor_offset = 0.25`` m: the sensor reads the shaft at x = 0.75
  m, a mesh node). The tube is massless and every force (the disk's inertia, the imbalance, the
  magnet's) acts at midspan, so the tube takes the static shape of a midspan-loaded simply
  supported beam, y(x)/y(L/2) = φ(x) = x(3L² − 4x²)/L³ for x ≤ L/2 (symmetric; the Hermite
  cubics hold it exactly): φ(0.25 m) = 0.6875. The sensor reads d_s = φ r and the magnet pushes
  −G d_s at the disk, so (k − mΩ² + φ G) r = UΩ²: the disk and the magnet's relative orbit are
  r = UΩ²/|k − mΩ² + φ(k_p + iΩk_d)|, the carried force |G| φ r (docstring: "carried force orbit
  G d_s − k_s d_a"), each of the 3U case.
* **The map's displacement limit** (:meth:`SpinupMap.best`): a gain pair whose any actuator
  exceeds ``max_actuator_displacement`` is out (a hand-made map, two actuators).

Tolerance 1e-3 relative, as tests/test_spinup_pd_bearing_reference.py on the same rotor: the
tube's mass (3.5e-6 of the disk's) moves the disk's response by less than 1e-4 with the speeds
kept 20 % or more from the resonance (302 rad/s without the bearing, 330 with φ k_p).

Written for the mutations h35b-spinup-noncollocated-worst-case-first,
h35b-spinup-noncollocated-act-min, h35b-spinup-map-first-case and
h35b-spinup-best-displacement-limit-min of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import U, imbalance_vector, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.spinup import SpinupMap, actuator_receptance, spinup_curves, spinup_map

KP, KD = 5.0e5, 2.0e3  # N/m, N s/m (k_i = 1): φG moves r by tens of % (a review: 5e3, 100 moved it 0.3 %)
PHI = 0.25 * (3.0 - 4.0 * 0.25**2)  # the midspan-loaded beam's shape at x = 0.25 (= 0.75) m
SPEEDS = np.array([100.0, 200.0, 400.0])  # rad/s, 20 % or more from the resonance


def _cases(model):
    return np.stack([imbalance_vector(model), imbalance_vector(model, 3.0)], axis=1)


def test_a_noncollocated_bearing_reports_the_worst_load_case():
    model = model_with(f'kind = "active"\nkp = {KP}\nkd = {KD}\nsensor_offset = 0.25')
    assert not model.actuators[0].collocated
    curves = spinup_curves(actuator_receptance(model, SPEEDS, _cases(model)), (KP, KD))
    G = KP + 1j * SPEEDS * KD
    r = 3.0 * U * SPEEDS**2 / np.abs(K_SHAFT - M_DISK * SPEEDS**2 + PHI * G)
    assert curves.shaft_peak == pytest.approx(r, rel=1e-3)
    assert curves.actuator_displacement[0] == pytest.approx(r, rel=1e-3)
    assert curves.actuator_force[0] == pytest.approx(np.abs(G) * PHI * r, rel=1e-3)


def test_the_gain_map_takes_the_worst_load_case():
    model = model_with(f'kind = "active"\nkp = {KP}\nkd = {KD}')
    kp, kd = np.array([2.0e3, 1.5e5]), np.array([60.0, 300.0])
    smap = spinup_map(model, kp, kd, receptance=actuator_receptance(model, SPEEDS, _cases(model)))
    for i, p in enumerate(kp):
        for j, d in enumerate(kd):
            r = 3.0 * U * SPEEDS**2 / np.abs(K_SHAFT + p - M_DISK * SPEEDS**2 + 1j * SPEEDS * d)
            assert smap.shaft_peak[i, j] == pytest.approx(r.max(), rel=1e-3)
            assert smap.actuator_displacement_peak[i, j, 0] == pytest.approx(r.max(), rel=1e-3)


def test_the_displacement_limit_holds_for_every_actuator():
    kp, kd = np.array([1.0e4, 2.0e4]), np.array([10.0, 20.0])
    shaft = np.array([[1.0, 2.0], [3.0, 4.0]]) * 1e-4
    disp = np.array([[[1e-5, 9e-4], [2e-5, 3e-5]], [[4e-5, 5e-5], [1e-5, 2e-5]]])  # (kp, kd, actuator)
    smap = SpinupMap(
        kp=kp,
        kd=kd,
        speeds=np.array([100.0, 200.0]),
        shaft_peak=shaft,
        shaft_peak_speed=np.full((2, 2), 100.0),
        actuator_displacement_peak=disp,
        actuator_force_peak=np.full((2, 2, 2), 10.0),
        actuator_names=("a", "b"),
    )
    # the smallest peak's actuator b moves 0.9 mm > 0.1 mm: the next smallest within the limit
    assert smap.best(max_actuator_displacement=1e-4) == (1.0e4, 20.0, 2.0e-4)
    assert smap.best(max_actuator_displacement=1e-3) == (1.0e4, 10.0, 1.0e-4)
