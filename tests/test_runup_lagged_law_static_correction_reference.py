"""A run's actuator force carries the law G(iΩ) on the static correction too (mutation hunt 19c).

A magnetic bearing whose law has states (a PD controller behind a first-order current amplifier,
G(s) = k_i (K_p + s K_d)/(1 + s/ω_a), with the magnet's negative stiffness k_s) carries the force
G d_s − k_s d_a (tests/test_runup_actuator_force_reference.py). At a constant speed Ω, started in
the steady state, every signal is harmonic at Ω and the carried force's complex envelope is, by
definition of the law,

    F = (G(iΩ) − k_s) D          (collocated sensor, D the envelope of the magnet's stroke),

with G written out here from the design's keys (k_i, K_p, K_d and f_a in Hz, ω_a = 2π f_a).
The run reports D and F as a modal part plus the quasi-static response of the modes left out
of its basis (its static correction): the check holds only if that part too is weighted by
G(iΩ), not by the static gain G(0) = k_i K_p, which differs from it by 7.8 % here (the
derivative's lead, ΩK_d = 2000 against K_p = 5000 A/m, partly undone by the lag, Ω/ω_a = 0.32).

The rotor: the Jeffcott rotor's tube made heavy (steel density), six elements, the magnet at
x = 0.25 m off the disk and the imbalance at the magnet, two basis modes, so that the static
correction is 16 % of the magnet's stroke (measured; with the law at s = 0 the force is then off
by about 0.078 |G(0)|/|G(iΩ) − k_s| × 16 % = 2 % of itself).

Tolerance 1e-9 of the largest force: the steady state is a fixed point of the run's envelope
equation at constant Ω, which its exponential integrator propagates exactly (every free
vibration exact whatever the step, flexshaft.analyses.envelope), so what remains is the
round-off of the steady solve and of the products (1e-15 measured).
CPU: one 2-mode run of three output samples, about 0.05 s.
"""

from __future__ import annotations

import numpy as np
from rotors import jeffcott_text

from flexshaft.analyses.transient import SpeedProfile, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KI, KP, KD, KS, FA = 100.0, 5.0e3, 50.0, 2.0e5, 20.0  # N/A, A/m, A s/m, N/m, Hz
U = 1e-4  # kg m
SPEED = 40.0  # rad/s


def test_static_correction_of_the_force_is_weighted_by_the_law_at_the_spin_frequency():
    text = jeffcott_text(0.0, 0.0, elements=6).replace("density = 0.1", "density = 7800.0")
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    keys = f'kind = "active"\nkp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}\namplifier_bandwidth = {FA}'
    model = build_model(loads_design(f'{head}[[bearings]]\nname = "b"\nx = 0.25\n{keys}\n{tail}'))
    dm = model.dofs
    q1 = np.zeros(dm.size, complex)
    node = dm.node_at("shaft", 0.25)
    q1[dm.shaft(node, "v")], q1[dm.shaft(node, "w")] = U, -1j * U
    run = transient_response(
        model, SpeedProfile.table([0.0, 0.02], [SPEED, SPEED]), loads_per_speed_squared=q1, basis_size=2, rtol=1e-7
    )
    assert run.residual is not None
    rows = model.actuators[0].lateral_rows.tocsr()[:, dm.free]
    stroke = run.actuator_envelope[0]  # (v, w) envelopes at the magnet, (2, n_t)
    assert np.abs(rows @ run.residual).max() * SPEED**2 > 0.1 * np.abs(stroke).max()  # the correction matters
    law = KI * (KP + 1j * SPEED * KD) / (1 + 1j * SPEED / (2 * np.pi * FA)) - KS
    force = run.actuator_force_envelope[0]
    assert np.abs(force - law * stroke).max() <= 1e-9 * np.abs(force).max()
