"""The gain map's force through a magnet's current gain, and its limits inclusive, by hand.

* **Current gain.** The Jeffcott rotor of tests/jeffcott_bearing.py (a 20 kg disk at midspan of a
  near-massless pinned-pinned tube, k = 48EI/L³) with a collocated magnetic bearing at the disk
  whose current gain is k_i = 100 N/A (no negative stiffness, no amplifier lag). The map's gains
  are the controller's, C = K_p + iΩK_d [A/m, A s/m], and the bearing pushes with G = k_i C
  (module docstring of :mod:`flexshaft.analyses.spinup`, ``G = k_i A(s) C(s)``). In complex
  coordinates m r̈ + k_i K_d ṙ + (k + k_i K_p) r = UΩ² e^{iΩt}: the disk's (and the magnet's)
  forward circle r(Ω) = UΩ²/|k + k_i K_p − mΩ² + iΩ k_i K_d| and the force |k_i C| r; each
  gain pair's force peak is the largest |k_i C(iΩ)| r(Ω) over the speeds.
* **Inclusive limits.** :meth:`SpinupMap.best` keeps the gain pairs whose actuators stay
  "within the limits": a pair exactly at a limit is within it. On a hand-made map whose smallest
  shaft peak has its actuator displacement (force) exactly at the limit, that pair is the best.

Tolerance 1e-3 relative, as tests/test_spinup_pd_bearing_reference.py on the same rotor: the
tube's mass (3.5e-6 of the disk's) moves the response by less than 1e-4, the speeds kept 20 % or
more from the resonance (302 rad/s without the bearing). The limits are exact comparisons of
the same float64 numbers.

Written for the mutations h51d-spinup-map-force-without-plant and
h51d-spinup-best-displacement-limit-strict of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import U, imbalance_vector, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.spinup import SpinupMap, actuator_receptance, spinup_map

KI = 100.0  # N/A
SPEEDS = np.array([100.0, 200.0, 400.0])  # rad/s


def test_the_map_force_carries_the_current_gain():
    model = model_with(f'kind = "active"\nkp = 50.0\nkd = 0.5\nki = {KI}')
    kp, kd = np.array([20.0, 1.0e3]), np.array([0.3, 3.0])  # A/m, A s/m
    rec = actuator_receptance(model, SPEEDS, imbalance_vector(model)[:, None])
    smap = spinup_map(model, kp, kd, receptance=rec)
    for i, p in enumerate(kp):
        for j, d in enumerate(kd):
            G = KI * (p + 1j * SPEEDS * d)
            r = U * SPEEDS**2 / np.abs(K_SHAFT - M_DISK * SPEEDS**2 + G)
            assert smap.shaft_peak[i, j] == pytest.approx(r.max(), rel=1e-3)
            assert smap.actuator_force_peak[i, j, 0] == pytest.approx((np.abs(G) * r).max(), rel=1e-3)


def _map(disp, force):
    return SpinupMap(
        kp=np.array([1.0e4, 2.0e4]),
        kd=np.array([10.0, 20.0]),
        speeds=np.array([100.0, 200.0]),
        shaft_peak=np.array([[1.0, 2.0], [3.0, 4.0]]) * 1e-4,
        shaft_peak_speed=np.full((2, 2), 100.0),
        actuator_displacement_peak=np.asarray(disp, float)[..., None],
        actuator_force_peak=np.asarray(force, float)[..., None],
        actuator_names=("a",),
    )


def test_a_pair_exactly_at_the_limits_is_within_them():
    disp = [[2.5e-4, 1e-4], [1e-4, 1e-4]]
    force = [[120.0, 50.0], [50.0, 50.0]]
    smap = _map(disp, force)
    assert smap.best(max_actuator_displacement=2.5e-4) == (1.0e4, 10.0, 1.0e-4)
    assert smap.best(max_actuator_force=120.0) == (1.0e4, 10.0, 1.0e-4)
    assert smap.best(max_actuator_displacement=2.5e-4, max_actuator_force=120.0) == (1.0e4, 10.0, 1.0e-4)
    # just below either limit the pair is out: the next smallest peak
    assert smap.best(max_actuator_displacement=2.4e-4) == (1.0e4, 20.0, 2.0e-4)
    assert smap.best(max_actuator_force=119.0) == (1.0e4, 20.0, 2.0e-4)
