"""The gain map's actuator force for a bearing of unit plant with a negative stiffness, its
progress reports, and a spin-up grid held at one speed fraction.

Reference (closed form, derived here as in tests/test_spinup_mixed_negative_stiffness_reference.py):
the Jeffcott rotor of tests/rotors.py (disk m = 20 kg on a near-massless tube of k = 48 E I/L³)
with one collocated active bearing at the disk of current gain k_i = 1 and no amplifier lag (so
its plant k_i A(s) is 1) and a negative stiffness k_s = 2e5 N/m. The module docstring of
:mod:`flexshaft.analyses.spinup` writes the collocated feedback as ``G − k_s``; the disk then obeys,
in complex coordinates, ``(k − mΩ² + L) r = U Ω²`` with ``L = K_p + iΩK_d − k_s`` under the
forward imbalance U (1, −i) per Ω², a circle of radius |r|, and the bearing carries |L| |r|. k_s
is two thirds of K_p here, so a force |K_p + iΩK_d| |r| (k_s dropped) is off by a factor 1.6-1.75
(peak 3.709 against 2.117 N at K_p = 3e5 N/m, 5.688 against 3.572 N at 4.5e5 N/m).

Tolerance: the tube's mass and rotary inertia (3.5e-6 of the disk's) move the answers by 5e-6
at most: rtol 1e-4, as the test cited above. The speeds 0.3, 0.6 and 1.4 ω_n stay off the
resonance. CPU: a few milliseconds.

``spinup_map``'s docstring: ``progress`` is "Called with (done, total) gain pairs" (done never
exceeds total); ``spinup_speeds`` refuses only a start that exceeds the stop ("start must not
exceed stop"), so start = stop is the grid of n copies of that fraction of the operating speed.
"""

from __future__ import annotations

import numpy as np
from jeffcott_bearing import KS, U, imbalance_vector, model_with
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.spinup import actuator_receptance, spinup_map, spinup_speeds
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KP, KD = 3.0e5, 400.0  # N/m, N s/m (k_i = 1: the law is in N/m directly)
UNIT = f'kind = "active"\nkp = {KP}\nkd = {KD}\nks = {KS}\nki = 1.0'


def test_map_force_of_a_unit_plant_bearing_keeps_its_negative_stiffness():
    model = model_with(UNIT)
    speeds = np.array([0.3, 0.6, 1.4]) * WN
    rec = actuator_receptance(model, speeds, imbalance_vector(model)[:, None])
    assert rec.plant is not None and np.all(rec.plant == 1.0)  # the premise: unit plant
    assert np.all(rec.negative_stiffness == KS)  # and k_s ≠ 0
    kp, kd = np.array([KP, 1.5 * KP]), np.array([KD])
    smap = spinup_map(model, kp, kd, receptance=rec)
    for i, p in enumerate(kp):
        law = p + 1j * speeds * KD - KS
        r = np.abs(U * speeds**2 / (K_SHAFT - M_DISK * speeds**2 + law))
        np.testing.assert_allclose(smap.shaft_peak[i, 0], r.max(), rtol=1e-4)
        np.testing.assert_allclose(smap.actuator_displacement_peak[i, 0, 0], r.max(), rtol=1e-4)
        np.testing.assert_allclose(smap.actuator_force_peak[i, 0, 0], (np.abs(law) * r).max(), rtol=1e-4)


def test_map_progress_never_reports_more_pairs_than_the_total():
    model = model_with(UNIT)
    rec = actuator_receptance(model, np.array([0.3, 0.6]) * WN, imbalance_vector(model)[:, None])
    calls = []
    spinup_map(model, [KP, 1.5 * KP, 2 * KP], [KD], receptance=rec, block=2, progress=lambda d, t: calls.append((d, t)))
    assert calls == [(2, 3), (3, 3)]  # 3 pairs in blocks of 2


def test_spinup_grid_with_start_equal_to_stop_holds_one_speed():
    text = jeffcott_text(0.0, 0.0, elements=4).replace("speed_rpm = 0.0", "speed_rpm = 3000.0")
    model = build_model(loads_design(text))
    omega = 3000.0 * 2 * np.pi / 60  # rad/s
    speeds = spinup_speeds(model, 4, start=0.5, stop=0.5)
    np.testing.assert_allclose(speeds, np.full(4, 0.5 * omega), rtol=1e-12)  # one product, round-off
