"""The whirl-stability map over the actuator gains with a sensor offset from its magnet, against
the Jeffcott rotor's characteristic equation.

The rotor of tests/rotors.py (a 20 kg disk at mid-span of a near-massless pinned-pinned tube,
k = 48EI/L³, viscous internal damping c_i = ηk/ω_ref, no external dashpot) with two active
bearings at the disk, law C(s) = K_p + K_d s, current gain 1 N/A, each reading the shaft at
x_s = L/2 + δ (``sensor_offset`` δ). Every force acts at mid-span (the disk's inertia, the
magnets, and the stiffness-proportional internal damping of the Euler-Bernoulli tube), so the
massless tube keeps the static shape of a central load: y(x) = y_mid · x(3L² − 4x²)/L³ for
x <= L/2 (the textbook deflection of a simply supported beam under a central load, derived
from EI y'''' = 0 with y(0) = y''(0) = 0, y'(L/2) = 0). By symmetry the sensor reads
ρ r, ρ = a(3L² − 4a²)/L³ with a = L/2 − |δ|, and in r = v + iw the disk obeys

    m s² + (c_i + 2ρK_d) s + k + 2ρK_p − iΩ c_i = 0,

so the onset (s = iω on the line Re s = 0) is ω² = (k + 2ρK_p)/m, Ω_onset = ω(1 + 2ρK_d/c_i),
and the margin at the operating speed is the smallest −Re s/|s| of the quadratic's roots. A
sensor offset puts K_d in the non-collocated law (the sensed displacement, not the magnet's):
it damps by ρK_d, not K_d. Tolerance 2e-5 as in tests/test_gain_stability_map_reference.py
(the reference leaves out the tube's mass, 7e-6 of the disk's; measured 9e-7 here). The Hermite
cubic elements hold the cubic static shape exactly, so the 8-element mesh suffices.
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
DELTA = 0.15 * L  # sensor offset [m]


def test_offset_sensor_map_damps_by_the_sensed_share_of_kd():
    amb = "\n".join(
        f'[[bearings]]\nname = "amb_{k}"\nkind = "active"\nx = {L / 2}\nkp = 1.0\nsensor_offset = {DELTA}\n'
        for k in ("a", "b")
    )
    text = jeffcott_text(ETA, 0.0).replace("speed_rpm = 0.0", f"speed_rpm = {float(OPERATING * 30 / np.pi)!r}")
    a = L / 2 - DELTA
    rho = a * (3 * L**2 - 4 * a**2) / L**3
    speeds = np.linspace(0.5, 3.0, 26) * WN
    smap = gain_stability_map(
        loads_design(text + amb), [KP], [0.0, KD], speeds, damping_model="viscous", n_modes=2, reference_frequency=WN
    )
    for j, kd in enumerate((0.0, KD)):
        onset = np.sqrt((K_SHAFT + 2 * rho * KP) / M_DISK) * (1 + 2 * rho * kd / C_I)
        assert smap.onset_speed[0, j] == pytest.approx(onset, rel=2e-5)
        roots = np.roots([M_DISK, C_I + 2 * rho * kd, K_SHAFT + 2 * rho * KP - 1j * OPERATING * C_I])
        assert smap.margin_at_operating[0, j] == pytest.approx(np.min(-roots.real / np.abs(roots)), rel=2e-5)
