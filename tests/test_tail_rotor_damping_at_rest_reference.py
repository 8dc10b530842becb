"""The tail rotor's default aerodynamic damping vanishes at rest.

A rotor at fixed pitch absorbs a torque Q_tr = a Ω_tr² (assumed in
:class:`flexshaft.design.drivetrain.TailRotor`; docs/model.md, "Torsional ends": default
``2P/Ω²``, the reflection of ``2 Q/Ω_tr``), so its damping is dQ/dΩ_tr = 2 a Ω_tr: 0 at
Ω_tr = 0 (derived here). A design at rest (``speed_rpm = 0`` and ``power = 0``, which the schema
requires at rest) with a
``[tail_rotor]`` and no ``aerodynamic_damping`` key therefore builds a model whose rotor has no
damper. With a rigid drive, the forward twist held and tests/test_torsional.py's near-massless
tube (k = G J_p/L, loss factor 0), the rotor's J = J_tr/n² on the aft twist is an undamped
single-DOF oscillator: f = √(k/J)/2π and ζ = 0. The shaft's own inertia moves f by about 5e-8
(tests/test_torsional.py): 3e-7 asserted. Without any damping the damped root is s = iω_n, its real part
only round-off of the companion eigenproblem (ζ of 2e-12 and -7e-13 measured with the Prescott
and Haswell kernels): |ζ| < 1e-9 asserted, still 2.7e6 times below the ζ = 0.0027 the 2P/Ω²
damping gives this rotor at the test shaft's 3000 rev/min (measured, and c/(2Jω_n) by hand).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import K_SHAFT, shaft_text

from flexshaft.analyses.torsional import torsional_modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

J_TR, RATIO = 12.0, 3.4


def test_a_tail_rotor_at_rest_has_no_default_aerodynamic_damping():
    text = shaft_text(f"[tail_rotor]\nblades = 4\npolar_inertia = {J_TR}\ngearbox_ratio = {RATIO}\n", rpm=0.0)
    assert "power = 100.0e3" in text
    text = text.replace("power = 100.0e3", "power = 0.0")  # a design at rest transmits no power
    design = loads_design(text)
    assert design.tail_rotor.aerodynamic_damping is None  # the default applies
    assert design.tail_rotor.reflected_damping(0.0, 0.0) == 0.0
    model = build_model(design)
    assert model.drive.rotor_damping == 0.0
    modes = torsional_modes(model, n_modes=1)
    J = J_TR / RATIO**2
    assert modes.natural_frequencies[0] == pytest.approx(np.sqrt(K_SHAFT / J) / (2 * np.pi), rel=3e-7)
    assert abs(modes.damping_ratios[0]) < 1e-9
