"""The tail rotor's drive on a driveline with a tailboom, against closed forms derived here.

* **Its twist DOF comes after the boom's DOFs.** The extra DOFs of a model follow the shaft's
  6 and the boom's 5 per node (docs of DofMap). The drive's physics checks it: the shaft's
  twist does not enter the contact bearings (they act on u, v, w, β, γ), so with the forward
  twist held, a near-massless shaft of torsional stiffness k = G J_p/L, the drive springs in
  series and the rotor's reflected inertia J_tr/n² make one torsional mode

      ω² = k_eff n²/J_tr,    1/k_eff = 1/k + 1/k_input + n²/k_hub

  whatever the boom does (kinetic and strain energy reflected through φ_shaft = n φ_rotor).
  The shaft's density (0.01 kg/m³, polar inertia 1e-7 of J_tr/n²) moves the root by about 1e-7
  (tests/test_torsional.py measured 5e-8 for the same tube); asserted to 3e-7.
* **The rotor turns at Ω/n** (n = shaft speed / rotor speed, the ratio's definition).

Written for the mutations h18a-dofs-extra-after-shaft and h18a-drivetrain-rotor-speed-times-ratio
of scripts/mutations.toml. Coarse mesh (4 shaft, 2 boom elements): a massless shaft's twist is
linear, exact at any mesh.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.torsional import torsional_modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.design.drivetrain import TailRotor

G_STEEL, DO, WALL, LENGTH = 80e9, 0.1, 0.005, 2.0
K_SHAFT = G_STEEL * math.pi * (DO**4 - (DO - 2 * WALL) ** 4) / 32 / LENGTH
J_TR, N, K_IN, K_HUB = 12.0, 3.4, 4.0e4, 2.5e5

TEXT = f"""
name = "tail rotor on a boomed driveline"
[materials.steel]
kind = "isotropic"
E = 210e9
G = {G_STEEL}
density = 0.01
[materials.al]
kind = "isotropic"
E = 70e9
G = 26e9
density = 2700.0
[shaft]
x_start = 0.0
x_end = {LENGTH}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
[tailboom]
length = {LENGTH}
root_semi_axes = [0.2, 0.2]
tip_semi_axes = [0.2, 0.2]
wall_thickness = 0.003
material = "al"
shaft_clearance = 0.05
[[bearings]]
name = "mid"
kind = "contact"
x = 1.0
stiffness = {{ v = 1e7, w = 1e7 }}
[[bearings]]
name = "aft"
kind = "contact"
x = {LENGTH}
stiffness = {{ v = 1e7, w = 1e7 }}
[tail_rotor]
blades = 4
polar_inertia = {J_TR}
gearbox_ratio = {N}
input_stiffness = {K_IN}
hub_stiffness = {K_HUB}
aerodynamic_damping = 0.0
[operating]
speed_rpm = 3000.0
power = 100.0e3
[mesh]
shaft_elements = 4
boom_elements = 2
"""


def test_the_rotor_mode_of_a_boomed_driveline_is_the_series_spring_closed_form():
    model = build_model(loads_design(TEXT))
    dm = model.dofs
    assert dm.n_boom_nodes > 0 and dm.extra == ("tail_rotor",)
    assert dm.extra_dof("tail_rotor") == 6 * dm.n_shaft_nodes + 5 * dm.n_boom_nodes  # after the boom
    k_eff = 1.0 / (1.0 / K_SHAFT + 1.0 / K_IN + N**2 / K_HUB)
    tm = torsional_modes(model, 1)
    assert tm.natural_frequencies[0] == pytest.approx(np.sqrt(k_eff * N**2 / J_TR) / (2 * np.pi), rel=3e-7)


def test_the_tail_rotor_turns_at_the_shaft_speed_over_the_ratio():
    rotor = TailRotor(blades=4, polar_inertia=J_TR, gearbox_ratio=N)
    omega = 2 * math.pi * 5000.0 / 60.0
    assert rotor.speed(omega) == pytest.approx(omega / N, rel=1e-15)
