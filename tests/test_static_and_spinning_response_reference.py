"""Static response with a PD and with an integrating magnetic bearing, and the harmonic
response's default spin speed, against closed forms (mutation hunt 23c).

The rotors: tests/rotors.py's Jeffcott-like rotor (20 kg disk at midspan of a near-massless
pinned-pinned tube, k = 48 EI/L³) and tests/jeffcott_bearing.py's, with one magnetic bearing
at the disk (k_i = 100 N/A, k_s = 2e5 N/m).

1. PD law i = −(k_p + k_d s) d, sensor at the magnet. Statically s = 0, so the magnet adds
   k_i k_p − k_s to the disk's stiffness: a force F at the disk deflects it by
   F/(k + k_i k_p − k_s) (derived; the tube's stiffness condenses exactly onto the disk). The
   Euler-Bernoulli beam element (the default) is exact for point loads (cubic shape
   functions), so the only error is round-off, κ ε ≈ 1e-13: tolerance 1e-10.

2. PID law, sensor 0.125 m beside the magnet. In static equilibrium the integrator holds the
   sensed displacement at zero. With F at the disk, both the load and the magnet's force act at
   the disk, so the tube's deflection is that of one point load F + f_magnet, and it is zero at
   the sensor (not a node of zero deflection of that shape) only if F + f_magnet = 0: the shaft
   stays undeformed (q = 0) and the bearing carries F. Tolerance: round-off of a 36-DOF solve
   (1e-12 of the disk's compliance F/k, 5e-5 m, so 1e-16 m absolute; 1e-9 N relative on the force).

3. The harmonic response at the model's operating speed when ``speed`` is not given. With the
   rotating-frame hysteretic loss η and the dashpot c_e, a forward load (F_w = −i F_v) at
   frequency ω drives the disk, r = v + iw, with (tests/test_damping.py derives it)

       [k − m ω² + iω c_e + iη k sgn(ω − Ω)] r = F,

   so below the spin (ω < Ω) the loss term changes sign. The operating speed is Ω = 2ω_n;
   checked at ω = 0.8 ω_n (below) and 2.5 ω_n (above), where the two signs differ by 28 % and
   2 %. Tolerance 5e-5 relative: the tube's 3.5e-6 share of the disk's mass, amplified by at
   most 1/|1 − ω²/ω_n²| ≈ 3 here (measured 3e-6).

CPU: three 4- to 8-element models, about 0.05 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, KI, KP, KS, PID, disk, model_with
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott_text

from flexshaft.analyses.response import frequency_response, static_actuator_forces, static_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

F = 100.0  # N


def _load_at_disk(model) -> np.ndarray:
    q = np.zeros(model.dofs.size)
    q[disk(model)[0]] = F
    return q


def test_a_pd_bearing_adds_its_static_stiffness_to_the_disk():
    model = model_with(ACTIVE)
    q = static_response(model, _load_at_disk(model))
    v, w = disk(model)
    assert q[v] == pytest.approx(F / (K_SHAFT + KI * KP - KS), rel=1e-10)
    assert q[w] == 0.0


def test_an_integrating_bearing_holds_its_sensor_at_zero_and_carries_the_load():
    model = model_with(PID + "\nsensor_offset = 0.125")
    a = model.actuators[0]
    assert np.abs(a.lateral_rows - a.sensing_rows).max() > 0  # the sensor is not at the magnet
    Q = _load_at_disk(model)
    q = static_response(model, Q)
    assert np.abs(q).max() <= 1e-12 * F / K_SHAFT
    forces = static_actuator_forces(model, Q)[a.name]
    assert forces == pytest.approx([F, 0.0], rel=1e-9, abs=1e-9 * F)


@pytest.mark.parametrize("ratio", [0.8, 2.5])
def test_the_harmonic_response_spins_at_the_operating_speed_by_default(ratio):
    eta, c_e = 0.05, 2 * 0.01 * M_DISK * WN
    rpm = float(2 * WN * 60 / (2 * np.pi))
    model = build_model(loads_design(jeffcott_text(eta, c_e).replace("speed_rpm = 0.0", f"speed_rpm = {rpm!r}")))
    assert model.speed == pytest.approx(2 * WN, rel=1e-12)
    v, w = disk_dofs(model)
    load = np.zeros(model.dofs.size, complex)
    load[v], load[w] = 1.0, -1j
    omega = ratio * WN
    sign = np.sign(omega - model.speed)
    r = 1.0 / (K_SHAFT - M_DISK * omega**2 + 1j * omega * c_e + 1j * sign * eta * K_SHAFT)
    q = np.asarray(frequency_response(model, load, omega))
    assert q[v] == pytest.approx(r, rel=5e-5)
    assert q[w] == pytest.approx(-1j * r, rel=5e-5)
