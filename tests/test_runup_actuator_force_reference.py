"""The run-up's actuator force is the bearing's whole law, k_i (K_p + s K_d) − k_s, not the
controller's current demand C(s) alone (fixed here: with k_i ≠ 1 or k_s ≠ 0 it was off by
the factor |G − k_s| / |C|, 60x for the magnet below).

References (derived here):

* steady start: the Jeffcott rotor with a PD magnet at its disk (tests/jeffcott_bearing.py) at
  constant Ω has the disk orbit U Ω² / |k + Z_b − mΩ²| with Z_b = k_i (K_p + iΩK_d) − k_s, and
  the magnet carries |Z_b| times it; a run started in that steady state reports it at t = 0,
  and so does the steady envelope. Tolerance 1e-4: the tube's mass (7e-6 of the disk's) and the
  run's steady start on a 4-mode basis with its static correction (no truncation at the disk);
* a sensor 0.1 m from the magnet (at x = 0.6 m): every force on the near-massless tube acts at
  its middle, so it keeps the static shape of a central load on a pinned-pinned beam,
  y(x) ∝ x (3L² − 4x²) for x ≤ L/2 (Euler-Bernoulli; symmetric), and the sensor reads
  ρ = y(0.4)/y(0.5) = 0.944 of the magnet's stroke. The bearing carries G ρ d − k_s d, so the
  disk's orbit is U Ω² / |k + ρG − k_s − mΩ²| and the force |ρG − k_s| times it; the sensor's
  channel must be counted (without it the force was k_s d alone). Tolerance 1e-4 as above;
* during a fast run-up from rest: the carried force of a PD magnet is by definition
  (k_i K_p − k_s) d(t) + k_i K_d ḋ(t) for the displacement d(t) the run reports at the magnet
  (here off the disk, on a heavy tube with a 2-mode basis, so that the static correction of the
  truncated modes, whose rate ``2ΩΩ̇`` carries the tangential load, matters: 2.7 % of the
  force); ḋ by central differences of the reported signal, error (hω)²/6 ≈ 4e-6 relative for
  h = 1e-5 s and the basis's ω < 600 rad/s; 1e-4 asserted.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, KD, KI, KP, KS, U, active_law, disk, imbalance_vector, model_with
from rotors import K_SHAFT, M_DISK, jeffcott_text

from flexshaft.analyses.transient import SpeedProfile, steady_state_envelope, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def test_steady_start_force_is_the_magnet_law_times_the_orbit():
    model = model_with(ACTIVE)
    speed = 150.0  # rad/s, below the resonance near 326 rad/s
    q1 = imbalance_vector(model)
    run = transient_response(
        model, SpeedProfile.constant_acceleration(speed, speed + 1.0, 10.0), loads_per_speed_squared=q1, basis_size=4
    )
    orbit = U * speed**2 / abs(K_SHAFT - M_DISK * speed**2 + active_law(speed))
    assert run.actuator_displacement[0, 0] == pytest.approx(orbit, rel=1e-4)
    assert run.actuator_force[0, 0] == pytest.approx(abs(active_law(speed)) * orbit, rel=1e-4)
    steady = steady_state_envelope(model, [speed], q1)
    assert steady.actuator_force[0, 0] == pytest.approx(abs(active_law(speed)) * orbit, rel=1e-4)


def test_steady_start_force_of_a_non_collocated_sensor():
    model = model_with(ACTIVE + "\nsensor_offset = 0.1")
    speed = 150.0
    q1 = imbalance_vector(model)
    run = transient_response(
        model, SpeedProfile.constant_acceleration(speed, speed + 1.0, 10.0), loads_per_speed_squared=q1, basis_size=4
    )
    ratio = 0.4 * (3.0 - 4 * 0.4**2) / (0.5 * (3.0 - 4 * 0.5**2))  # y(0.6)/y(0.5), L = 1
    law = ratio * (active_law(speed) + KS) - KS  # ρ G − k_s
    orbit = U * speed**2 / abs(K_SHAFT - M_DISK * speed**2 + law)
    assert run.actuator_displacement[0, 0] == pytest.approx(orbit, rel=1e-4)
    assert run.actuator_force[0, 0] == pytest.approx(abs(law) * orbit, rel=1e-4)
    steady = steady_state_envelope(model, [speed], q1)
    assert steady.actuator_force[0, 0] == pytest.approx(abs(law) * orbit, rel=1e-4)


KD_RUN = 50.0  # A s/m: k_i K_d = 5000 N s/m, so that the derivative force matters


def test_force_during_a_fast_run_up_is_the_pd_law_of_the_reported_displacement():
    text = jeffcott_text(0.0, 0.0, elements=6).replace("density = 0.1", "density = 7800.0")
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    keys = f'kind = "active"\nkp = {KP}\nkd = {KD_RUN}\nks = {KS}\nki = {KI}'
    model = build_model(loads_design(f'{head}[[bearings]]\nname = "b"\nx = 0.25\n{keys}\n{tail}'))
    dm = model.dofs
    q1 = np.zeros(dm.size, complex)
    node = dm.node_at("shaft", 0.25)
    q1[dm.shaft(node, "v")], q1[dm.shaft(node, "w")] = U, -1j * U
    h = 1e-5
    run = transient_response(
        model,
        SpeedProfile.constant_acceleration(0.0, 40.0, 2000.0),
        loads_per_speed_squared=q1,
        basis_size=2,
        output_step=h,
        rtol=1e-7,
    )
    assert run.residual is not None
    e = np.exp(1j * run.phase)
    d = np.real(run.actuator_envelope[0] * e)  # (v, w) at the magnet [m]
    f = np.real(run.actuator_force_envelope[0] * e)
    d_dot = (d[:, 2:] - d[:, :-2]) / (2 * h)
    law = (KI * KP - KS) * d[:, 1:-1] + KI * KD_RUN * d_dot
    assert np.abs(f[:, 1:-1] - law).max() <= 1e-4 * np.abs(f).max()
    assert KD != KD_RUN  # the shared rotor's bearing is not this one


def test_disk_orbit_of_the_steady_start_is_unchanged_by_the_law():
    """The fix changed what is reported, not the dynamics: the disk's orbit is the closed form."""
    model = model_with(ACTIVE)
    speed = 250.0
    v, w = disk(model)
    run = transient_response(
        model,
        SpeedProfile.constant_acceleration(speed, speed + 1.0, 10.0),
        loads_per_speed_squared=imbalance_vector(model),
        basis_size=4,
    )
    orbit = U * speed**2 / abs(K_SHAFT - M_DISK * speed**2 + active_law(speed))
    node = model.dofs.node_at("shaft", 0.5)
    assert run.shaft_orbit[node, 0] == pytest.approx(orbit, rel=1e-4)
