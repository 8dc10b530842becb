"""The whirl-stability map over the actuator gains (thesis chapter 4,
:func:`flexshaft.thesis.whirl.gain_stability_map`) against the Jeffcott rotor's closed form.

The rotor of tests/rotors.py (a 20 kg disk at mid-span of a near-massless pinned-pinned tube,
shaft stiffness k = 48EI/L³, viscous internal damping c_i = ηk/ω_ref, no external dashpot)
with two active PD bearings at the disk: each adds K_p to the stiffness and K_d to the
external damping, so in r = v + iw the disk obeys

    m s² + (2K_d + c_i) s + (k + 2K_p) − iΩ c_i = 0.

At the onset Re s = 0, s = iω: ω² = (k + 2K_p)/m and Ω_onset = ω (1 + 2K_d/c_i) (the
classical threshold of internal damping, tests/test_stability.py). The map's margin at the
operating speed is the smallest damping ratio −Re s/|s| of the two roots there.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, L, jeffcott_text

from flexshaft.design import loads_design
from flexshaft.thesis.whirl import gain_stability_map

ETA, KP, KD = 0.02, 2e5, 40.0
C_I = ETA * K_SHAFT / WN  # ω_ref = ω_n of the shaft alone
OPERATING = 0.8 * WN  # [rad/s], on the map's speed grid below


def _rotor_with_two_ambs():
    amb = "\n".join(f'[[bearings]]\nname = "amb_{k}"\nkind = "active"\nx = {L / 2}\nkp = 1.0\n' for k in ("a", "b"))
    text = jeffcott_text(ETA, 0.0).replace("speed_rpm = 0.0", f"speed_rpm = {float(OPERATING * 30 / np.pi)!r}")
    return loads_design(text + amb)


def _roots(speed, c_e):
    return np.roots([M_DISK, c_e + C_I, K_SHAFT + 2 * KP - 1j * speed * C_I])


def test_onset_and_margin_over_kd_follow_the_jeffcott_closed_form():
    """Onset ω(1 + 2K_d/c_i) for K_d = 0 and 40 N s/m on both bearings (it moves from 334 to
    554 rad/s): Re s is linear in Ω for this rotor, so the linear interpolation on the grid of
    26 speeds adds no error. The margin at the operating speed (a grid speed) is the closed-form
    roots' smallest damping ratio. Both to 2e-5: the closed form leaves out the tube's mass,
    7e-6 of the disk's (measured 9e-7 on the onset, 3e-6 on the margin)."""
    speeds = np.linspace(0.5, 3.0, 26) * WN
    assert np.min(np.abs(speeds - OPERATING)) < 1e-9 * WN
    smap = gain_stability_map(
        _rotor_with_two_ambs(), [KP], [0.0, KD], speeds, damping_model="viscous", n_modes=2, reference_frequency=WN
    )
    omega = np.sqrt((K_SHAFT + 2 * KP) / M_DISK)
    for j, kd in enumerate((0.0, KD)):
        assert smap.onset_speed[0, j] == pytest.approx(omega * (1 + 2 * kd / C_I), rel=2e-5)
        roots = _roots(OPERATING, 2 * kd)
        assert smap.margin_at_operating[0, j] == pytest.approx(np.min(-roots.real / np.abs(roots)), rel=2e-5)
    assert smap.max_speed == speeds[-1]
