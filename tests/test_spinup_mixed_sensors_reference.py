"""The spin-up map of a rotor whose two magnetic bearings differ: one senses at its magnet, the
other 0.25 m away (mutation hunt h43b: a model of mixed sensors is not all collocated).

The Jeffcott rotor of tests/jeffcott_bearing.py (a 20 kg disk at midspan of a near-massless
pinned-pinned tube, k = 48EI/L³) with two ideal PD magnets at the disk (k_i = 1, k_s = 0, no
lag): "a" senses at the magnet, "b" reads the shaft 0.25 m aft, at φ = 0.6875 of the disk's
deflection (the midspan-loaded beam's static shape, exact on the massless tube:
tests/test_spinup_map_noncollocated_force_reference.py). :func:`spinup_map` applies one gain
pair G = k_p + iΩk_d to every actuator, so the disk's forward circle and the carried forces are

    r = UΩ²/|k − mΩ² + (1 + φ) G|,      F_a = |G| r,      F_b = |G| φ r

(derived: each magnet pushes on the disk with G times what it senses). Treating "b" as
collocated would give (1 + 1) G in the denominator and F_b = |G| r. Tolerance 1e-3 relative, as
the single-sensor test on this rotor (the tube's 3.5e-6 mass share, amplified near resonance).
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import U, imbalance_vector
from rotors import K_SHAFT, M_DISK, jeffcott_text

from flexshaft.analyses.spinup import actuator_receptance, spinup_map
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KP, KD = 5.0e5, 100.0  # N/m, N s/m (k_i = 1)
PHI = 0.25 * (3.0 - 4.0 * 0.25**2)
SPEEDS = np.array([100.0, 300.0, 500.0])  # rad/s


def _model():
    text = jeffcott_text(0.0, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    bearings = (
        f'[[bearings]]\nname = "a"\nx = 0.5\nkind = "active"\nkp = {KP}\nkd = {KD}\n\n'
        f'[[bearings]]\nname = "b"\nx = 0.5\nkind = "active"\nkp = {KP}\nkd = {KD}\nsensor_offset = 0.25\n\n'
    )
    return build_model(loads_design(head + bearings + tail))


def test_a_collocated_and_an_offset_sensor_on_one_map():
    model = _model()
    assert [a.collocated for a in model.actuators] == [True, False]
    rec = actuator_receptance(model, SPEEDS, imbalance_vector(model)[:, None])
    G = KP + 1j * SPEEDS * KD
    r = U * SPEEDS**2 / np.abs(K_SHAFT - M_DISK * SPEEDS**2 + (1 + PHI) * G)
    smap = spinup_map(model, np.array([KP]), np.array([KD]), receptance=rec)
    assert smap.actuator_force_peak[0, 0, 0] == pytest.approx((np.abs(G) * r).max(), rel=1e-3)
    assert smap.actuator_force_peak[0, 0, 1] == pytest.approx((np.abs(G) * PHI * r).max(), rel=1e-3)
    assert smap.actuator_displacement_peak[0, 0, 1] == pytest.approx(r.max(), rel=1e-3)
