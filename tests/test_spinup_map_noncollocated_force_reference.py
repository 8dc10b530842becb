"""The gain map's bearing force behind a non-collocated sensor is its peak over the spin-up.

The Jeffcott rotor of tests/jeffcott_bearing.py (a 20 kg disk at midspan of a near-massless
pinned-pinned tube, k = 48EI/L³ = 1.826e6 N/m) with an ideal PD magnetic bearing at the disk
(k_i = 1, k_s = 0, no lag) whose sensor reads the shaft 0.25 m aft, at φ = 0.6875 of the disk's
deflection (the midspan-loaded beam's static shape, tests/test_spinup_cases_and_limits_reference.py,
where the massless tube makes it exact). The disk's forward circle and the carried force are

    r = UΩ²/|k − mΩ² + φ(k_p + iΩk_d)|,        F = |k_p + iΩk_d| φ r,

and :func:`spinup_map` reports, per gain pair, the largest F over the speeds (its docstring:
peaks over the spin-up). With k_p = 5e5 N/m and a light k_d = 100 N s/m the undamped resonance
√((k + φk_p)/m) = 329.4 rad/s lies between the samples 300 and 500 rad/s and F peaks at 300
rad/s (F = 8.37 N there, 3.05 N at 500, for U = 1e-4 kg m), not at the top speed.

Tolerance 1e-3 relative, as tests/test_spinup_cases_and_limits_reference.py on the same rotor:
the tube's mass (3.5e-6 of the disk's) shifts the resonance by ~1e-6 relative, which the 9 %
distance of 300 rad/s from it amplifies at most ~6-fold.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import U, imbalance_vector, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.spinup import actuator_receptance, spinup_map

KP, KD = 5.0e5, 100.0  # N/m, N s/m (k_i = 1)
PHI = 0.25 * (3.0 - 4.0 * 0.25**2)
SPEEDS = np.array([100.0, 300.0, 500.0])  # rad/s


def test_the_noncollocated_maps_force_is_its_peak_over_the_speeds():
    model = model_with(f'kind = "active"\nkp = {KP}\nkd = {KD}\nsensor_offset = 0.25')
    assert not model.actuators[0].collocated
    rec = actuator_receptance(model, SPEEDS, imbalance_vector(model)[:, None])
    G = KP + 1j * SPEEDS * KD
    r = U * SPEEDS**2 / np.abs(K_SHAFT - M_DISK * SPEEDS**2 + PHI * G)
    force = np.abs(G) * PHI * r
    assert np.argmax(force) == 1  # the peak is not at the top speed
    smap = spinup_map(model, np.array([KP]), np.array([KD]), receptance=rec)
    assert smap.actuator_force_peak[0, 0, 0] == pytest.approx(force.max(), rel=1e-3)
    assert smap.actuator_displacement_peak[0, 0, 0] == pytest.approx(r.max(), rel=1e-3)
