"""The forced torsional response finds a resonance inside the operating speed range.

tests/test_torsional.py's near-massless steel tube (k = G J_p/L), forward twist held, a rigid
tail-rotor drive: the rotor's J = J_tr/n² and damper c = c_tr/n² sit on the aft twist, a
single-DOF oscillator ω_n = √(k/J), ζ = c/(2 J ω_n) (derived here). The operating speed is set so
the tail rotor's 1/rev, Ω/n, equals ω_n, and ``speed_range = [0.9, 1.1]`` puts that speed in the
middle of the range (module docstring: the worst speed of the range). The 1/rev torque a T on
the rotor then drives the shaft torque |k φ| = a T/(2ζ) (amplification 1/(2ζ) = 25 at ζ = 0.02),
while at the range's ends, 10 % off tune, the amplification is
1/|1 − r² + 2iζr| = 5.2 (r = 0.9) and 4.7 (r = 1.1): a response taken at the ends alone reads a
fifth of the resonant torque. The 4/rev lies at 4 ω_n, far above resonance, and the steady torque
is the same at every speed, so the governing speed (largest peak stress) is the tuned one.
The default sweep (41 speeds, docstring of torsional_forced_response) holds the tuned speed to
round-off; the shaft's own inertia (ρ J_p L/J_r ≈ 7e-8 of the rotor's, tests/test_torsional.py)
moves the amplification by a measured 1.1e-8 (first order in the shaft's inertia): 1e-6
asserted on the amplification, 1e-9 on the governing speed (round-off of the evenly spaced
speeds, ~1e-16 relative).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import K_SHAFT, shaft_text

from flexshaft.analyses.torsional import torsional_forced_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

J_TR, RATIO, ZETA = 12.0, 3.4, 0.02


def test_default_sweep_finds_the_once_per_rev_resonance_mid_range():
    J = J_TR / RATIO**2
    wn = np.sqrt(K_SHAFT / J)
    c_tr = 2 * ZETA * J * wn * RATIO**2
    speed = wn * RATIO
    text = shaft_text(
        f"[tail_rotor]\nblades = 4\npolar_inertia = {J_TR}\ngearbox_ratio = {RATIO}\naerodynamic_damping = {c_tr}\n",
        rpm=speed * 60.0 / (2 * np.pi),
        operating="speed_range = [0.9, 1.1]",
    )
    response = torsional_forced_response(build_model(loads_design(text)))
    assert response.speed == pytest.approx(speed, rel=1e-9)
    once = response.harmonics[0]
    assert once.frequency == pytest.approx(wn / (2 * np.pi), rel=1e-9)
    assert once.amplification == pytest.approx(1 / (2 * ZETA), rel=1e-6)
