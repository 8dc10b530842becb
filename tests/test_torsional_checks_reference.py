"""The torsional checks' bookkeeping, against closed forms of lumped torsional systems.

Models: tests/test_torsional.py's near-massless steel tube (ρ = 0.01 kg/m³, k = G J_p/L over
L = 2 m), forward twist held, the tail rotor's reflected inertia J_tr/n² on the aft twist (a
rigid drive), P = 100 kW at 3000 rpm. The shaft's own polar inertia (1e-7 of the lumped ones)
moves the lumped closed forms by about 5e-8 (measured there); the two-inertia model of the first
test is meshed in two elements (the disk on the middle node): with tests/test_torsional.py's
eight near-massless elements and an interior disk the dense eigen-solve's round-off reached
2.7e-7 (7.2e-7 with OpenBLAS's Prescott kernels), in two elements -8e-9 on both. Frequencies
asserted to 3e-7; resonant amplitudes (a frequency error ε detunes them by about (ε/ζ)², at
ζ = 3.5e-3 and 1.8e-4 in the tests below: below 1e-7) to 1e-6.

* **Separation scope.** Every mode up to twice the highest excitation frequency is checked
  (:func:`~flexshaft.analyses.torsional.torsional_separation`). A disk J₁ at midspan and the
  rotor J₂ make two modes, the roots of J₁J₂ω⁴ − (J₁k₂ + J₂(k₁ + k₂))ω² + k₁k₂ = 0 with
  k₁ = k₂ = 2k (each half of the shaft); with J₁ = 2, J₂ = 1 kg m² they are 44.8 and 108.1 Hz.
  The excitations (n = 2, N = 3 blades): 25, 50 and 75 Hz, so the second mode lies between the
  highest excitation and twice it and is checked against the 3/rev: margin f₂/75 Hz − 1.
* **"At least" the required margin.** A margin equal to the requirement passes, one ulp short
  fails; 9/8 − 1 = 0.125 is exact in binary (the separation rule m = f_n/f_hi − 1 above a band).
* **The governing speed** of the forced response is the speed of the largest stress: with the
  rotor's 1/rev tuned onto ω_n = √(k/J) at one of two speeds, that speed; the shaft carries
  |T_k| = a_k T |k/(k − Jω² + icω)| at ω = kΩ/n (massless shaft: uniform torque), T = P/Ω_op, and
  the torque factor is 1 + Σ|T_k|/T.
* **The default aerodynamic damping is taken at the operating speed**, c = 2P/Ω_op²
  (tests/test_tail_rotor_damping_reference.py derives it), also when the design gives a speed
  range: the 1/rev tuned onto ω_n at Ω_op is amplified by 1/(2ζ), ζ = c/(2Jω_n).
* **The default torque oscillations** are 0.05 of the mean torque at 1/rev and 0.10 at N/rev
  (docs/design-reference.md, ``[tail_rotor]`` ``torque_oscillation_1p``/``_np``).

Written for the mutations h33a-torsional-ceiling-highest-excitation,
h33a-torsional-margin-on-limit-fails, h33a-torsional-governing-speed-least,
h33a-drive-damping-at-top-speed and h33a-drivetrain-default-oscillations-swapped of
scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import K_SHAFT, shaft_text

from flexshaft.analyses.torsional import (
    TorsionalSeparation,
    separation_margin,
    torsional_forced_response,
    torsional_separation,
)
from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.design.drivetrain import TailRotor

POWER, RPM = 100.0e3, 3000.0  # tests/test_torsional.py's operating point
OMEGA = RPM * 2 * np.pi / 60


def _rotor(J_tr: float, n: float, blades: int, extra: str = "") -> str:
    return f"[tail_rotor]\nblades = {blades}\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n{extra}"


def test_a_mode_between_the_highest_excitation_and_twice_it_is_checked():
    J1, J_tr, n, blades = 2.0, 4.0, 2.0, 3
    disk = '[[disks]]\nname = "disk"\nx = 1.0\nmass = 1.0\npolar_inertia = 2.0\ndiametral_inertia = 1.0\n'
    text = shaft_text(disk + _rotor(J_tr, n, blades), elements=2)  # the disk on the middle node
    assert f"speed_rpm = {RPM}" in text and "main_rotor" not in text
    separations = torsional_separation(build_model(loads_design(text)))
    J2, k = J_tr / n**2, 2 * K_SHAFT
    a, b, c = J1 * J2, J1 * k + J2 * 2 * k, k * k
    roots = np.sqrt([(b - np.sqrt(b * b - 4 * a * c)) / (2 * a), (b + np.sqrt(b * b - 4 * a * c)) / (2 * a)])
    f1, f2 = roots / (2 * np.pi)
    f_top = blades / n * OMEGA / (2 * np.pi)  # 75 Hz, the highest excitation
    assert f_top < f2 < 2 * f_top
    assert [s.natural_frequency for s in separations] == pytest.approx([f1, f2], rel=3e-7)
    second = separations[1]
    assert second.excitation == f"tail rotor {blades}/rev"
    assert second.margin == pytest.approx(f2 / f_top - 1.0, rel=3e-7)


def test_a_margin_exactly_at_the_requirement_passes():
    margin = separation_margin(9.0, 4.0, 8.0)
    assert margin == 0.125  # 9/8 − 1, exact in binary

    def judged(required: float) -> TorsionalSeparation:
        return TorsionalSeparation(0, 9.0, "shaft 1/rev", "shaft", 1, (4.0, 8.0), margin, required)

    assert judged(0.125).passed
    assert not judged(float(np.nextafter(0.125, 1.0))).passed


def test_the_forced_response_is_governed_by_the_speed_of_the_largest_stress():
    J_tr, n, c_tr, blades = 12.0, 3.4, 30.0, 4
    model = build_model(loads_design(shaft_text(_rotor(J_tr, n, blades, f"aerodynamic_damping = {c_tr}\n"))))
    J, c = J_tr / n**2, c_tr / n**2
    resonant = np.sqrt(K_SHAFT / J) * n  # the rotor's 1/rev on ω_n
    response = torsional_forced_response(model, speeds=[0.6 * resonant, resonant])
    assert response.speed == resonant
    T = POWER / OMEGA
    harmonics = [
        a * T * abs(K_SHAFT / (K_SHAFT - J * w * w + 1j * c * w))
        for a, w in ((0.05, resonant / n), (0.10, blades * resonant / n))
    ]
    assert response.torque_factor == pytest.approx(1.0 + sum(harmonics) / T, rel=1e-6)


def test_the_default_aerodynamic_damping_is_taken_at_the_operating_speed():
    J_tr, n = 12.0, 3.4
    J = J_tr / n**2
    wn = np.sqrt(K_SHAFT / J)
    speed = wn * n  # the operating speed puts the rotor's 1/rev on ω_n
    rpm = float(speed * 60 / (2 * np.pi))
    text = shaft_text(_rotor(J_tr, n, 4)).replace(f"speed_rpm = {RPM}", f"speed_rpm = {rpm!r}")
    text = text.replace("power = 100.0e3", "power = 100.0e3\nspeed_range = [0.8, 1.25]")
    model = build_model(loads_design(text))
    assert model.design.operating.speed_limits[1] == pytest.approx(1.25 * speed)
    c = 2 * POWER / speed**2
    assert model.drive.rotor_damping == pytest.approx(c, rel=1e-12)
    response = torsional_forced_response(model, speeds=[speed])
    assert response.harmonics[0].amplification == pytest.approx(J * wn / c, rel=1e-6)  # 1/(2ζ)


def test_the_default_torque_oscillations_are_five_and_ten_percent():
    rotor = TailRotor(blades=4, polar_inertia=12.0, gearbox_ratio=3.4)
    assert (rotor.torque_oscillation_1p, rotor.torque_oscillation_np) == (0.05, 0.10)
    model = build_model(loads_design(shaft_text(_rotor(12.0, 3.4, 4))))
    response = torsional_forced_response(model, speeds=[OMEGA])
    T = POWER / OMEGA
    assert [h.excitation for h in response.harmonics] == pytest.approx([0.05 * T, 0.10 * T], rel=1e-12)
