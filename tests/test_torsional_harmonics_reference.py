"""The torsional forced response's harmonics and steady stress, and a damped torsional mode, by hand.

* **Each torque harmonic as reported.** The two-tube shaft of
  tests/test_segment_joint_elements_reference.py (a: D 60 mm, wall 3 mm, 0 to 1 m; b: D 40 mm,
  wall 2 mm, 1 to 2 m; aluminium G = 26 GPa, near-massless, density 1e-2 kg/m³), held in twist
  forward, a disk of polar inertia J_d = 2 kg m² at the joint and the tail rotor (J_tr = 12 kg m²,
  n = 3.4, c_tr = 30 N m s, 4 blades, rigid drive: J = J_tr/n², c = c_tr/n² on the aft twist).
  The harmonic k of the rotor's torque oscillation is a_k T on the rotor (T = P/Ω, a₁ = 0.05,
  a₄ = 0.10, the design-reference defaults) at ω = kΩ/n, i.e. the frequency kΩ/(2πn) Hz. With
  the two lumped twists (θ_d, θ_r), k_a = G J_a/1 m, k_b = G J_b/1 m:

      [k_a + k_b − J_d ω²      −k_b         ] [θ_d]   [  0  ]
      [    −k_b          k_b − Jω² + icω ] [θ_r] = [a_k T],

  tube a carries k_a θ_d, tube b k_b (θ_r − θ_d). The module's docstring: a harmonic's
  ``excitation`` is a_k T, its ``torque`` the largest element torque, its ``shear_stress`` that
  torque × r_o/J of its element, its ``amplification`` the ratio torque/excitation. The steady
  shear stress is T r_o/J of the most stressed tube (b: r/J 3.4 times a's), and an element's
  station is its midpoint (element ends from the model's mesh). The shaft's own inertia perturbs
  the lumped forms by ~1e-9: rel 1e-7, as tests/test_torsional_scope_and_stress_reference.py.
* **The damping ratio of a torsional mode is −Re s/|s|.** A tail rotor J_tr = 0.1 kg m² behind
  n = 2 on tests/test_torsional.py's near-massless steel tube (k = G J_p/L, forward twist held),
  with aerodynamic damping c_tr: one inertia J = J_tr/n² (+ J_s/3 of the tube, Rayleigh) and one
  dashpot c = c_tr/n², J s² + c s + k = 0, ζ = c/(2√(kJ)) chosen 0.3 (−Re s/Im s would read
  ζ/√(1 − ζ²) = 0.3145, 4.8 % high). The tube's inertia left over (J_s/J)² ~ 1e-11: asserted to
  1e-6 (the dense eigen-solver's round-off on this conditioning, tests/test_torsional.py).

Written for the mutations h37c-torsion-* of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_segment_joint_elements_reference import G_MOD, JOINT, TUBES, _design, _polar
from test_torsional import J_POLAR, K_SHAFT, LENGTH, shaft_text

from flexshaft.analyses.torsional import torsional_forced_response, torsional_modes
from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict, loads_design

J_TR, RATIO, C_TR, BLADES, J_DISK = 12.0, 3.4, 30.0, 4, 2.0


def _two_tube_response():
    rotor = {"blades": BLADES, "polar_inertia": J_TR, "gearbox_ratio": RATIO, "aerodynamic_damping": C_TR}
    disk = {"name": "d", "x": JOINT, "mass": 1.0, "polar_inertia": J_DISK, "diametral_inertia": 0.5}
    model = build_model(design_from_dict(_design(1e-2, {"tail_rotor": rotor, "disks": [disk]})))
    return model, torsional_forced_response(model, speeds=[model.speed])


def test_each_torque_harmonic_reports_its_frequency_excitation_torque_and_stress():
    model, response = _two_tube_response()
    speed = model.speed
    k_a, k_b = G_MOD * _polar("a") / JOINT, G_MOD * _polar("b") / JOINT
    J, c, T = J_TR / RATIO**2, C_TR / RATIO**2, 100.0e3 / speed
    r_over_j = {"a": TUBES["a"][0] / 2 / _polar("a"), "b": TUBES["b"][0] / 2 / _polar("b")}
    assert [h.order for h in response.harmonics] == [1, BLADES]
    for harmonic, (order, a) in zip(response.harmonics, ((1, 0.05), (BLADES, 0.10))):
        w = order * speed / RATIO
        Z = np.array([[k_a + k_b - J_DISK * w * w, -k_b], [-k_b, k_b - J * w * w + 1j * c * w]])
        theta_d, theta_r = np.linalg.solve(Z, [0.0, a * T])
        torques = {"a": abs(k_a * theta_d), "b": abs(k_b * (theta_r - theta_d))}
        tube = max(torques, key=lambda name: torques[name])
        assert harmonic.fraction == a
        assert harmonic.frequency == pytest.approx(order * speed / RATIO / (2 * np.pi), rel=1e-12)
        assert harmonic.excitation == pytest.approx(a * T, rel=1e-12)
        assert harmonic.torque == pytest.approx(torques[tube], rel=1e-7)
        assert harmonic.amplification == pytest.approx(torques[tube] / (a * T), rel=1e-7)
        assert harmonic.shear_stress == pytest.approx(torques[tube] * r_over_j[tube], rel=1e-7)
        assert (harmonic.x < JOINT) == (tube == "a")


def test_the_steady_stress_is_the_most_stressed_tubes_and_stations_are_element_midpoints():
    model, response = _two_tube_response()
    T = 100.0e3 / model.speed
    assert response.steady_torque == pytest.approx(T, rel=1e-12)
    assert response.steady_shear_stress == pytest.approx(T * TUBES["b"][0] / 2 / _polar("b"), rel=1e-12)
    ends = model.dofs.shaft_element_x
    midpoints = 0.5 * (ends[:, 0] + ends[:, 1])
    for x in [response.x, *(h.x for h in response.harmonics)]:
        assert np.min(np.abs(midpoints - x)) <= 1e-12
        assert np.min(np.abs(model.dofs.shaft_x - x)) >= 0.1 * np.min(ends[:, 1] - ends[:, 0])


def test_a_damped_torsional_mode_has_zeta_minus_re_s_over_abs_s():
    J_tr, n, zeta = 0.1, 2.0, 0.3
    J_s = 1e-2 * J_POLAR * LENGTH  # the tube's polar inertia (density 1e-2 kg/m³)
    J = J_tr / n**2 + J_s / 3
    c = 2 * zeta * np.sqrt(K_SHAFT * J)
    rotor = f"[tail_rotor]\nblades = 3\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n"
    text = shaft_text(rotor + f"aerodynamic_damping = {float(c * n**2)!r}\n")
    modes = torsional_modes(build_model(loads_design(text)), n_modes=1)
    assert modes.damping_ratios[0] == pytest.approx(zeta, rel=1e-6)
    omega_n = np.sqrt(K_SHAFT / J)
    assert modes.frequencies[0] == pytest.approx(omega_n * np.sqrt(1 - zeta**2) / (2 * np.pi), rel=1e-6)
