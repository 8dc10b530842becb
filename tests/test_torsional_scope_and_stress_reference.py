"""The torsional separation's lowest mode and the forced response's governing stress, by hand.

* **The lowest flexible mode is always judged.** :func:`torsional_separation` checks every mode
  up to twice the highest excitation frequency "(at least the lowest flexible mode)". A tail
  rotor of J_tr = 0.1 kg m² behind a rigid drive of ratio n = 2 on tests/test_torsional.py's
  near-massless steel tube (k = G J_p/L, forward twist held) is one inertia J = J_tr/n² on one
  spring: f = √(k/J)/2π = 370 Hz, with the tube's own polar inertia J_s = ρ J_p L (ρ = 0.01
  kg/m³, 2.7e-6 of J) by Rayleigh's quotient on the linear twist, ω² = k/(J + J_s/3) (a shift
  of 4.5e-7; what is left is of order (J_s/J)² ~ 1e-11 and the solver's round-off, 1e-13
  measured; asserted to 3e-7 as tests/test_torsional.py), above twice the highest excitation
  (the 3/rev of the rotor, 3Ω/(2πn) = 75 Hz at 3000 rpm, so 150 Hz). That mode is still
  reported, against the 3/rev, with the margin f/75 Hz − 1 (the rule above a band,
  m = f_n/f_hi − 1).
* **The governing element is the one of the largest stress, not of the largest torque.** The
  two-tube shaft of tests/test_segment_joint_elements_reference.py (a: D 60 mm, wall 3 mm, 0 to
  1 m; b: D 40 mm, wall 2 mm, 1 to 2 m; aluminium G = 26 GPa, near-massless), held in twist
  forward, a disk of polar inertia J_d = 2 kg m² at the joint and the tail rotor (J_tr = 12 kg m²,
  n = 3.4, c_tr = 30 N m s, 4 blades, rigid drive: J = J_tr/n², c = c_tr/n² on the aft twist).
  Two lumped DOFs (θ_d, θ_r), k_a = G J_a/1 m, k_b = G J_b/1 m, the harmonic torque a_k T on the
  rotor (T = P/Ω, a₁ = 0.05, a₄ = 0.10, ω = kΩ/n):

      [k_a + k_b − J_d ω²      −k_b         ] [θ_d]   [  0  ]
      [    −k_b          k_b − Jω² + icω ] [θ_r] = [a_k T],

  the torque k_a θ_d in a and k_b (θ_r − θ_d) in b (the disk's inertia makes them differ: a
  carries 3 % more). The peak torque T + Σ_k |T_k| is largest in a, the stress (T + Σ|T_k|) r/J
  in b (r/J 3.4 times a's): the response reports b's stress at an element of b, and the
  torque factor from a's torque (docstring: "largest (T + Σ|T_k|)/T over the elements").
  The shaft's own inertia (density 1e-2 kg/m³) perturbs the lumped forms by ~1e-9: rel 1e-7.

Written for the mutations h35b-torsional-no-lowest-mode-kept and
h35b-torsional-governing-element-by-torque of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_segment_joint_elements_reference import G_MOD, JOINT, TUBES, _design, _polar
from test_torsional import J_POLAR, K_SHAFT, LENGTH, shaft_text

from flexshaft.analyses.torsional import torsional_forced_response, torsional_separation
from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict, loads_design


def test_the_lowest_flexible_mode_is_judged_above_twice_the_highest_excitation():
    J_tr, n, blades = 0.1, 2.0, 3
    text = shaft_text(f"[tail_rotor]\nblades = {blades}\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n")
    separations = torsional_separation(build_model(loads_design(text)))
    J_s = 1e-2 * J_POLAR * LENGTH  # the tube's polar inertia (density 1e-2 kg/m³)
    f = np.sqrt(K_SHAFT / (J_tr / n**2 + J_s / 3)) / (2 * np.pi)
    f_top = blades / n * (3000.0 * 2 * np.pi / 60) / (2 * np.pi)  # 75 Hz
    assert f > 2 * f_top
    assert len(separations) == 1
    only = separations[0]
    assert only.mode == 0 and only.natural_frequency == pytest.approx(f, rel=3e-7)
    assert only.excitation == f"tail rotor {blades}/rev"
    assert only.margin == pytest.approx(f / f_top - 1.0, rel=3e-7)


def test_the_forced_response_is_governed_by_the_largest_stress_not_the_largest_torque():
    J_tr, n, c_tr, blades, J_d = 12.0, 3.4, 30.0, 4, 2.0
    rotor = {"blades": blades, "polar_inertia": J_tr, "gearbox_ratio": n, "aerodynamic_damping": c_tr}
    disk = {"name": "d", "x": JOINT, "mass": 1.0, "polar_inertia": J_d, "diametral_inertia": 0.5}
    model = build_model(design_from_dict(_design(1e-2, {"tail_rotor": rotor, "disks": [disk]})))
    speed = model.speed
    response = torsional_forced_response(model, speeds=[speed])
    k_a, k_b = G_MOD * _polar("a") / JOINT, G_MOD * _polar("b") / JOINT
    J, c, T = J_tr / n**2, c_tr / n**2, 100.0e3 / speed
    peak_a = peak_b = T
    for order, a in ((1, 0.05), (blades, 0.10)):
        w = order * speed / n
        Z = np.array([[k_a + k_b - J_d * w * w, -k_b], [-k_b, k_b - J * w * w + 1j * c * w]])
        theta_d, theta_r = np.linalg.solve(Z, [0.0, a * T])
        peak_a += abs(k_a * theta_d)
        peak_b += abs(k_b * (theta_r - theta_d))
    stress_a = peak_a * (TUBES["a"][0] / 2) / _polar("a")
    stress_b = peak_b * (TUBES["b"][0] / 2) / _polar("b")
    assert peak_a > 1.02 * peak_b and stress_b > 3 * stress_a  # the two rules point at different tubes
    assert JOINT < response.x < 2 * JOINT
    assert response.peak_shear_stress == pytest.approx(stress_b, rel=1e-7)
    assert response.torque_factor == pytest.approx(peak_a / T, rel=1e-7)
