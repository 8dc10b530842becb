"""The tail rotor's default aerodynamic damping, through the torsional resonance it limits.

A rotor at fixed pitch absorbs a torque Q_tr ∝ Ω_tr² (assumed in
:class:`flexshaft.design.drivetrain.TailRotor`), so dQ/dΩ_tr = 2 Q_tr/Ω_tr; with Q_tr = P n/Ω and
Ω_tr = Ω/n, reflected through the gear ratio by 1/n² (φ_shaft = n φ_rotor, the dissipated power
kept), the damper on the shaft's side is c = 2 P/Ω², whatever n. A rigid drive puts the rotor's
J_tr/n² and this c on the shaft's aft twist: with the forward twist held and a near-massless
shaft k = G J_p/L, the 1/rev torque oscillation tuned onto ω_n = √(k/J) is amplified by exactly
1/(2ζ), ζ = c/(2 J ω_n) (single-DOF resonance). The shaft's own inertia detunes the peak by
about 1e-8 (tests/test_torsional.py): 1e-6 asserted.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import K_SHAFT, shaft_text

from flexshaft.analyses.torsional import torsional_forced_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

POWER = 100.0e3  # W, the power of test_torsional's shaft text


def _design(rpm: float, J_tr: float, n: float) -> str:
    """tests/test_torsional.py's near-massless steel tube (ρ = 0.01 kg/m³) on two stiff bearings
    at ``rpm``, a tail rotor with no aerodynamic_damping key (the default applies)."""
    text = shaft_text(f"[tail_rotor]\nblades = 4\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n")
    assert "power = 100.0e3" in text and "speed_rpm = 3000.0" in text
    return text.replace("speed_rpm = 3000.0", f"speed_rpm = {rpm}")


def test_the_default_damping_2P_over_omega_squared_sets_the_resonance_peak():
    J_tr, n = 12.0, 3.4
    J = J_tr / n**2
    wn = np.sqrt(K_SHAFT / J)
    speed = wn * n  # the rotor's 1/rev, Ω/n, on ω_n
    response = torsional_forced_response(build_model(loads_design(_design(speed * 60 / (2 * np.pi), J_tr, n))))
    c = 2 * POWER / speed**2
    zeta = c / (2 * J * wn)
    assert response.harmonics[0].frequency == pytest.approx(wn / (2 * np.pi), rel=1e-12)
    assert response.harmonics[0].amplification == pytest.approx(1 / (2 * zeta), rel=1e-6)
