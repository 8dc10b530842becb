"""A run's non-collocated magnet under a PD law (no controller states): its force reads the
static correction at the sensor, its stroke at the magnet.

The rotor and bearing of tests/test_runup_noncollocated_static_correction_reference.py (the
Jeffcott tube made heavy, six elements, magnet at x = 0.25 m, sensor at x = 0.5 m, imbalance at
the magnet, two basis modes), with a PD law and no amplifier: G(s) = k_i (K_p + K_d s), a law
without states, whose quasi-static part the run adds channel by channel (the magnet's −k_s on
its own displacement, the sensor's G on the sensor's). At a constant speed Ω, started in the
steady state, every signal is harmonic at Ω and the envelopes obey, by the docs' definition of
the carried force G d_s − k_s d_a,

    D_a = V(x_a),    F = k_i (K_p + iΩK_d) V(x_s) − k_s V(x_a),

V the run's shaft envelope (static correction included). The correction is 17 % of the magnet's
stroke and 0.3 % of the sensor's reading (measured): taken at the magnet, the law's share
moves the force by 22 % (measured), far beyond the 1e-9 asserted.

Tolerance: the identities to 1e-9 of the largest value (the steady state is a fixed point of
the run's exponential integrator; round-off only).

Written for the mutation h37a-maps-residual-on-magnet of scripts/mutations.toml. CPU: one
2-mode run of three samples, under 0.1 s.
"""

from __future__ import annotations

import numpy as np
from test_runup_noncollocated_static_correction_reference import MAGNET, SENSOR, one_magnet_model

from flexshaft.analyses.transient import SpeedProfile, transient_response

KI, KP, KD, KS = 100.0, 5.0e3, 2.0, 2.0e5  # N/A, A/m, A s/m, N/m
U = 1e-4  # kg m
SPEED = 40.0  # rad/s


def test_a_pd_laws_force_reads_the_static_correction_at_its_sensor():
    keys = f'kind = "active"\nkp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}\nsensor_offset = {SENSOR - MAGNET}'
    model = one_magnet_model(keys)
    act = model.actuators[0]
    assert not act.collocated and act.amplifier_bandwidth is None
    dm = model.dofs
    magnet, sensor = dm.node_at("shaft", MAGNET), dm.node_at("shaft", SENSOR)
    assert dm.shaft_x[magnet] == MAGNET and dm.shaft_x[sensor] == SENSOR
    q1 = np.zeros(dm.size, complex)
    q1[dm.shaft(magnet, "v")], q1[dm.shaft(magnet, "w")] = U, -1j * U
    run = transient_response(
        model, SpeedProfile.table([0.0, 0.02], [SPEED, SPEED]), loads_per_speed_squared=q1, basis_size=2, rtol=1e-7
    )
    assert run.residual is not None
    rows = act.lateral_rows.tocsr()[:, dm.free]
    V = run.shaft_envelope  # (v, w) of every node, (2, n_nodes, n_t)
    stroke = run.actuator_envelope[0]
    assert np.abs(rows @ run.residual).max() * SPEED**2 > 0.1 * np.abs(stroke).max()  # the correction matters
    assert np.abs(stroke - V[:, magnet]).max() <= 1e-9 * np.abs(stroke).max()
    force = run.actuator_force_envelope[0]
    expected = KI * (KP + 1j * SPEED * KD) * V[:, sensor] - KS * V[:, magnet]
    assert np.abs(force - expected).max() <= 1e-9 * np.abs(expected).max()
