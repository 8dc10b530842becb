"""A run's non-collocated magnet: its stroke and its law's reading carry the static correction
of their own stations.

A magnetic bearing at x = 0.25 m whose sensor reads the shaft at x = 0.5 m (``sensor_offset =
0.25``), a proportional law behind a first-order current amplifier, G(s) = k_i K_p/(1 + s/ω_a)
(a law with a state), with the magnet's negative stiffness k_s: the bearing is referenced to
the ground, so its stroke is the shaft's deflection at the magnet, d_a, and it carries
G d_s − k_s d_a with d_s the shaft's deflection at the sensor (docs: "carried force G d_s −
k_s d_a"). At a constant speed Ω, started in the steady state, every signal is harmonic at Ω
and the envelopes obey, by these definitions,

    D_a = V(x_a),    F = G(iΩ) V(x_s) − k_s V(x_a),

V the run's shaft envelope (static correction included, :class:`TransientResult`), G written
out here from the design's keys (ω_a = 2π f_a). The rotor of
tests/test_runup_lagged_law_static_correction_reference.py (the Jeffcott tube made heavy,
steel's density, six elements, the imbalance at the magnet, two basis modes), where the static
correction is 17 % of the magnet's stroke and 0.4 % of the sensor's reading (measured): read at
the wrong station, the stroke moves by 16 % and the force by 20 %.

Tolerances: the identities to 1e-9 of the largest value (the steady state is a fixed point of
the run's exponential integrator; round-off only, 6e-15 measured). Against the full model's
steady response (banded solve of every DOF, :func:`steady_state_envelope`) to 5 %: the two-mode
run's actuator feedback on the static correction is quasi-static and output-only (module
docstring), which leaves it 1.7 % (stroke) and 2.8 % (force) off (measured), well inside the
mutations' 16-20 %.

Written for the mutations h35b-transient-residual-at-sensor and
h35b-transient-residual-sensed-at-magnet of scripts/mutations.toml. CPU: one 2-mode run of three
samples and one banded solve, under 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import jeffcott_text

from flexshaft.analyses.transient import SpeedProfile, steady_state_envelope, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KI, KP, KS, FA = 100.0, 5.0e3, 2.0e5, 20.0  # N/A, A/m, N/m, Hz
U = 1e-4  # kg m
SPEED = 40.0  # rad/s
MAGNET, SENSOR = 0.25, 0.5  # m


def one_magnet_model(keys: str):
    """The steel Jeffcott rotor (6 elements) with its bearings replaced by one magnet "b" at
    MAGNET with the bearing keys ``keys`` (its law, sensor offset, ...)."""
    text = jeffcott_text(0.0, 0.0, elements=6).replace("density = 0.1", "density = 7800.0")
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    return build_model(loads_design(f'{head}[[bearings]]\nname = "b"\nx = {MAGNET}\n{keys}\n{tail}'))


def test_the_stroke_and_the_law_read_the_static_correction_at_their_own_stations():
    keys = (
        f'kind = "active"\nkp = {KP}\nkd = 0.0\nks = {KS}\nki = {KI}\namplifier_bandwidth = {FA}\n'
        f"sensor_offset = {SENSOR - MAGNET}"
    )
    model = one_magnet_model(keys)
    assert not model.actuators[0].collocated
    dm = model.dofs
    magnet, sensor = dm.node_at("shaft", MAGNET), dm.node_at("shaft", SENSOR)
    assert dm.shaft_x[magnet] == MAGNET and dm.shaft_x[sensor] == SENSOR
    q1 = np.zeros(dm.size, complex)
    q1[dm.shaft(magnet, "v")], q1[dm.shaft(magnet, "w")] = U, -1j * U
    run = transient_response(
        model, SpeedProfile.table([0.0, 0.02], [SPEED, SPEED]), loads_per_speed_squared=q1, basis_size=2, rtol=1e-7
    )
    assert run.residual is not None
    rows = model.actuators[0].lateral_rows.tocsr()[:, dm.free]
    stroke = run.actuator_envelope[0]  # (v, w) at the magnet, (2, n_t)
    assert np.abs(rows @ run.residual).max() * SPEED**2 > 0.1 * np.abs(stroke).max()  # the correction matters
    V = run.shaft_envelope  # (v, w) of every node, (2, n_nodes, n_t)
    assert np.abs(stroke - V[:, magnet]).max() <= 1e-9 * np.abs(stroke).max()
    law = KI * KP / (1 + 1j * SPEED / (2 * np.pi * FA))
    force = run.actuator_force_envelope[0]
    expected = law * V[:, sensor] - KS * V[:, magnet]
    assert np.abs(force - expected).max() <= 1e-9 * np.abs(expected).max()
    full = steady_state_envelope(model, [SPEED], q1)
    assert run.actuator_displacement[0] == pytest.approx(np.full(3, full.actuator_displacement[0, 0]), rel=0.05)
    assert run.actuator_force[0] == pytest.approx(np.full(3, full.actuator_force[0, 0]), rel=0.05)
