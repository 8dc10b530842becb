"""An axial mode is scaled, like every mode, to a unit maximum translation (the
:class:`~flexshaft.analyses.modal.Modes` docstring): its largest translation is the shaft's
axial u, not its (round-off) lateral v, w.

Reference (closed form): a 2 m steel tube, pinned laterally at both ends, held axially by one
soft spring k_u = 1e4 N/m at x = 0 and carrying a 5 kg disk. Its lowest mode is the whole
rotor sliding on the spring, ω² = k_u / m with m the tube's ρ π (D² − d²)/4 L plus the disk's
mass; the bar's own axial flexibility lowers ω² by the factor (1 − k_u/(3 EA/L)) ≈ 1 − 5e-5
(Rayleigh, linear axial shape), so rtol 1e-3 bounds the closed form's own error. The first
lateral mode (pinned tube, tens of Hz) is far above ω ≈ 25 rad/s, so the lowest mode is the
axial one. Its shape has u = 1 (real) exactly after the normalisation and no lateral motion
(round-off only).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

K_U, DISK = 1.0e4, 5.0
TUBE = f"""
name = "tube on a soft axial spring"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.05
wall_thickness = 0.005
material = "steel"
fixed_start = ["v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "axial spring"
kind = "contact"
x = 0.0
stiffness = {{ u = {K_U} }}
[[disks]]
name = "disk"
x = 1.2
mass = {DISK}
diametral_inertia = 0.05
polar_inertia = 0.1
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 8
"""


def test_the_axial_mode_has_a_unit_axial_translation():
    model = build_model(loads_design(TUBE))
    m = modes(model, 0.0, n_modes=2, damped=False)
    tube = 7800 * math.pi * (0.05**2 - 0.04**2) / 4 * 2.0
    assert m.kind[0] == "axial"
    assert 2 * math.pi * m.frequencies[0] == pytest.approx(math.sqrt(K_U / (tube + DISK)), rel=1e-3)
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    u = m.shapes[dm.shaft(nodes, "u"), 0]
    lateral = m.shapes[np.concatenate([dm.shaft(nodes, f) for f in ("v", "w")]), 0]
    assert np.abs(lateral).max() < 1e-6
    np.testing.assert_allclose(u, 1.0, rtol=0, atol=1e-3)  # rigid sliding: u = 1 all along
    assert np.abs(u).max() == pytest.approx(1.0, rel=1e-12)
