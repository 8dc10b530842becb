"""What a bearing carries, against the Jeffcott rotor's closed forms (derived here).

The rotor of tests/rotors.py: a 20 kg disk at the middle of a near-massless pinned-pinned tube
(bending stiffness at the disk k = 48EI/L³), with ONE bearing at the disk. Everything there is
a single mass on springs in parallel, each plane (v, w) on its own (no polar inertia, no
internal loss: nothing couples them):

* static: a load P at the disk deflects it by P / (k + k_b); the bearing carries k_b P/(k + k_b)
  in the load's direction; a bearing that integrates (PID) holds the disk at 0, so the tube is
  undeformed, its ends carry nothing and the bearing carries all of P (statics);
* imbalance U Ω² e^{iΩt} (load Q_v = U, Q_w = −iU): the disk's amplitude in a plane with
  bearing law Z_b(Ω) (contact: k_b + iΩc_b; active, collocated: k_i(K_p + iΩK_d) − k_s) is
  A = U Ω² / (k + Z_b − mΩ²) and the bearing carries Z_b A. With different damping in v and w
  the force orbit is an ellipse; its major semi-axis is found by brute force over the phase;
* the spin-up of the active bearing: the disk's orbit U Ω²/|k + Z_b − mΩ²| and the bearing's
  force |Z_b| times it; with two load cases U and 3U at the disk, the second is the worst at
  every speed and the bearing's orbit and force are 3 times the first's.

Tolerances: the tube's mass is 7e-6 of the disk's (tests/rotors.py): relative errors ~1e-5,
amplified by at most 1/(2ζ) ≈ 30 near a resonance; 1e-3 is asserted where the speeds are away
from the resonance, 1e-9 for pure statics and algebra on the solution itself.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import (
    ACTIVE,
    CONTACT,
    CV,
    CW,
    KB,
    KD,
    KP,
    PID,
    U,
    active_law,
    disk,
    imbalance_vector,
    major_semi_axis,
    model_with,
)
from rotors import K_SHAFT, M_DISK

import flexshaft.analyses.spinup_response as spinup_response_module
from flexshaft.analyses.reactions import actuator_response, bearing_forces, bearing_reactions
from flexshaft.analyses.response import imbalance_response, static_actuator_forces, static_response
from flexshaft.analyses.spinup import actuator_receptance, spinup_curves
from flexshaft.analyses.spinup_response import spinup_response


def test_contact_bearing_static_share_and_elliptical_imbalance_force():
    model = model_with(CONTACT)
    v, w = disk(model)
    load = np.zeros(model.dofs.size)
    load[v], load[w] = 300.0, 400.0
    speed = 0.6 * np.sqrt((K_SHAFT + KB) / M_DISK)  # below the resonance
    q_static = static_response(model, load, speed=0.0)
    q_dyn = np.asarray(imbalance_response(model, [speed], imbalance_vector(model)))[:, 0]
    r = bearing_reactions(model, q_static, q_dyn, speed=speed, loads=load)["b"]

    share = KB / (K_SHAFT + KB)  # springs in parallel
    assert r.static_force[1:3] == pytest.approx([300.0 * share, 400.0 * share], rel=1e-9)
    assert r.static_lateral == pytest.approx(500.0 * share, rel=1e-9)
    assert r.static_axial == pytest.approx(0.0, abs=1e-9)

    z = K_SHAFT - M_DISK * speed**2
    a_v = U * speed**2 / (z + KB + 1j * speed * CV)
    a_w = -1j * U * speed**2 / (z + KB + 1j * speed * CW)
    f_v, f_w = (KB + 1j * speed * CV) * a_v, (KB + 1j * speed * CW) * a_w
    assert r.imbalance_motion[1:3, 0] == pytest.approx([a_v, a_w], rel=1e-3)
    assert r.imbalance_force[1:3, 0] == pytest.approx([f_v, f_w], rel=1e-3)
    assert abs(f_w) > 1.01 * abs(f_v)  # an ellipse: the check below sees both planes
    assert r.imbalance_lateral_amplitude == pytest.approx(major_semi_axis(f_v, f_w), rel=1e-3)


def test_integrating_bearing_carries_the_whole_static_load():
    model = model_with(PID)
    v, w = disk(model)
    load = np.zeros(model.dofs.size)
    load[v], load[w] = 300.0, -400.0
    forces = static_actuator_forces(model, load)["b"]
    # the bearing holds the disk at 0: the tube is undeformed, the bearing carries P itself
    assert forces == pytest.approx([300.0, -400.0], rel=1e-9)
    assert np.abs(static_response(model, load)[[v, w]]).max() < 1e-12


def test_active_bearing_force_is_its_law_at_i_omega_times_its_stroke():
    model = model_with(ACTIVE)
    v, w = disk(model)
    speeds = np.array([150.0, 250.0])  # rad/s
    q = np.asarray(imbalance_response(model, speeds, imbalance_vector(model)))
    z = K_SHAFT - M_DISK * speeds**2 + active_law(speeds)
    amplitude = U * speeds**2 / z
    assert q[v] == pytest.approx(amplitude, rel=1e-3)
    for k, omega in enumerate(speeds):
        force = bearing_forces(model, q[:, k], omega)["b"]
        assert force[1:3] == pytest.approx(active_law(omega) * q[[v, w], k], rel=1e-9)
    disp, force = actuator_response(model, q, speeds)
    assert disp["b"] == pytest.approx(np.abs(amplitude), rel=1e-3)  # a forward circle
    assert force["b"] == pytest.approx(np.abs(active_law(speeds) * amplitude), rel=1e-3)


def test_spinup_curves_with_a_negative_stiffness_magnet():
    model = model_with(ACTIVE)
    speeds = np.array([100.0, 200.0, 400.0])
    curves = spinup_curves(actuator_receptance(model, speeds, imbalance_vector(model)), (KP, KD))
    orbit = U * speeds**2 / np.abs(K_SHAFT - M_DISK * speeds**2 + active_law(speeds))
    node = model.dofs.node_at("shaft", 0.5)
    assert curves.shaft_orbit[node] == pytest.approx(orbit, rel=1e-3)
    assert curves.actuator_displacement[0] == pytest.approx(orbit, rel=1e-3)
    assert curves.actuator_force[0] == pytest.approx(np.abs(active_law(speeds)) * orbit, rel=1e-3)


def test_spinup_response_reports_the_worst_case_at_the_actuator(monkeypatch):
    model = model_with(ACTIVE)
    # two load cases: U and 3U at the disk; the second is the worst at every speed
    cases = np.stack([imbalance_vector(model), imbalance_vector(model, 3.0)], axis=1)
    monkeypatch.setattr(spinup_response_module, "imbalance_loads", lambda _model: cases)
    speeds = np.array([100.0, 200.0, 400.0])
    result = spinup_response(model, speeds, projected=False)
    orbit = 3.0 * U * speeds**2 / np.abs(K_SHAFT - M_DISK * speeds**2 + active_law(speeds))
    assert list(result.worst_case) == [1, 1, 1]
    assert result.actuator_displacement["b"] == pytest.approx(orbit, rel=1e-3)
    assert result.actuator_force["b"] == pytest.approx(np.abs(active_law(speeds)) * orbit, rel=1e-3)
    # the spin-up proper: the speeds up to and including the operating speed
    assert list(result.up_to(200.0)) == [0, 1]
