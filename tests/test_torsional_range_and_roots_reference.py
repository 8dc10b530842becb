"""Torsional checks over a speed range, a free rigid twist and the damped roots' matching,
against closed forms of lumped systems.

* **The forced response over the design's speed range.** tests/test_torsional.py's
  near-massless tube (k = G J_p/L, forward twist held) with a rigid drive: the rotor's
  J = J_tr/n² and c = c_tr/n² on the aft twist. Only the 1/rev oscillates (a₁ = 0.05,
  a_N = 0). The shaft carries |T₁| = a₁ T |k/(k − Jω² + icω)| at ω = Ω/n (T = P/Ω_op); with
  the top of the range at 0.8 ω_n this grows over the whole range, so the governing speed is
  the range's top, 1.25 Ω_op, and the torque factor 1 + |T₁|/T there.
* **A free rigid twist is no resonance** (module docstring of
  :mod:`flexshaft.analyses.torsional`): a mode list whose first frequency is 0 (a twist free
  at both ends) is judged from its first flexible mode on.
* **Each undamped mode takes its own damped root.** Two uncoupled oscillators (M = I,
  K = diag(ω_a², ω_b²), C = diag(2ζ_a ω_a, 2ζ_b ω_b)) have the roots
  s = −ζω ± iω√(1 − ζ²). With ω_a = 10, ζ_a = 0.01 and ω_b = 12, ζ_b = 0.8 the heavily damped
  upper mode's ω_d = 7.2 lies below the lower mode's 9.9995 rad/s: matching by distance to
  +iω_n still pairs each mode with its own root (and its damping ratio ζ = −Re s/|s|).

Tolerance: the lumped closed forms to rel 1e-6 (the shaft's own inertia moves them by ~5e-8,
tests/test_torsional.py); the 2×2 companion eigenvalues to 1e-12.

Written for the mutations h43d-torsion-speed-range-low-end-only,
h43d-torsion-rigid-twist-judged and h43d-torsion-root-match-conjugate of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import K_SHAFT, shaft_text

from flexshaft.analyses import torsional
from flexshaft.analyses.torsional import TorsionalModes, TorsionalSystem, torsional_forced_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

POWER = 100.0e3
J_TR, N_GEAR, C_TR, BLADES = 12.0, 3.4, 30.0, 4


def _rotor_text(rpm: float, speed_range: str = "[0.8, 1.25]") -> str:
    rotor = (
        f"[tail_rotor]\nblades = {BLADES}\npolar_inertia = {J_TR}\ngearbox_ratio = {N_GEAR}\n"
        f"aerodynamic_damping = {C_TR}\ntorque_oscillation_1p = 0.05\ntorque_oscillation_np = 0.0\n"
    )
    text = shaft_text(rotor).replace("speed_rpm = 3000.0", f"speed_rpm = {rpm!r}")
    return text.replace("power = 100.0e3", f"power = 100.0e3\nspeed_range = {speed_range}")


def test_the_forced_response_spans_the_design_speed_range():
    J, c = J_TR / N_GEAR**2, C_TR / N_GEAR**2
    wn = np.sqrt(K_SHAFT / J)
    top = 0.8 * wn * N_GEAR  # the 1/rev at 0.8 ω_n at the range's top
    op = top / 1.25
    model = build_model(loads_design(_rotor_text(float(op * 60 / (2 * np.pi)))))
    response = torsional_forced_response(model, n_speeds=5)
    assert response.speed == pytest.approx(top, rel=1e-12)
    w = top / N_GEAR
    T = POWER / op
    T1 = 0.05 * T * abs(K_SHAFT / (K_SHAFT - J * w * w + 1j * c * w))
    assert response.torque_factor == pytest.approx(1.0 + T1 / T, rel=1e-6)


def test_a_free_rigid_twist_is_not_judged():
    model = build_model(loads_design(_rotor_text(3000.0, "[0.98, 1.02]")))
    f1 = 30.0  # Hz, below twice the highest excitation (the 4/rev near 59 Hz)
    modes = TorsionalModes(np.array([0.0, f1]), np.array([0.0, 2j * np.pi * f1]), np.zeros((model.dofs.size, 2)))
    separations = torsional.torsional_separation(model, modes=modes)
    assert [(s.mode, s.natural_frequency) for s in separations] == [(1, f1)]


def test_each_undamped_mode_takes_its_own_damped_root(monkeypatch):
    model = build_model(loads_design(_rotor_text(3000.0, "[0.98, 1.02]")))
    (wa, za), (wb, zb) = (10.0, 0.01), (12.0, 0.8)
    system = TorsionalSystem(
        dofs=np.array([0, 1]),
        M=np.eye(2),
        K=np.diag([wa**2, wb**2]),
        K_loss=np.zeros((2, 2)),
        C=np.diag([2 * za * wa, 2 * zb * wb]),
    )
    monkeypatch.setattr(torsional, "torsional_system", lambda m: system)
    modes = torsional.torsional_modes(model)
    roots = [complex(-z * w, w * np.sqrt(1 - z * z)) for w, z in ((wa, za), (wb, zb))]
    assert roots[1].imag < roots[0].imag  # the damped order is not the undamped one
    assert modes.natural_frequencies == pytest.approx(np.array([wa, wb]) / (2 * np.pi), rel=1e-12)
    assert modes.eigenvalues == pytest.approx(np.array(roots), rel=1e-12)
    assert modes.damping_ratios == pytest.approx([za, zb], rel=1e-12)
