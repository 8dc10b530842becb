"""Test rotors with closed-form answers, shared by the damping, stability and response tests.

Jeffcott-like rotor: a heavy midspan disk (mass m) on a near-massless pinned-pinned steel tube
(3.5e-6 of the disk mass: 0.1 kg/m³ × π(D_o² − D_i²)/4 × L = 7.1e-5 kg; lighter makes the
first-order problem ill-conditioned), an optional external dashpot c_e at the disk and an
isotropic loss factor η of the shaft material. The shaft's loss stiffness is η K', which
condenses exactly onto the disk, so in complex coordinates r = v + i w the disk obeys m r̈ + c_e
ṙ + k r + (internal loss) = f with k = 48 E I / L³.
"""

from __future__ import annotations

import numpy as np

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

E, G = 210e9, 80e9
DO, DI, L, M_DISK = 0.05, 0.04, 1.0, 20.0
K_SHAFT = 48 * E * np.pi * (DO**4 - DI**4) / 64 / L**3
WN = np.sqrt(K_SHAFT / M_DISK)


def jeffcott_text(eta: float, c_e: float, internal_damping: str = "rotating", elements: int = 8) -> str:
    return f"""
name = "Jeffcott rotor with internal damping"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G}
density = 0.1
loss_factor = {eta}
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "external_damper"
kind = "contact"
x = {L / 2}
stiffness = {{}}
damping = {{ v = {c_e}, w = {c_e} }}
[[disks]]
name = "disk"
x = {L / 2}
mass = {M_DISK}
[operating]
speed_rpm = 0.0
power = 0.0
[analysis]
internal_damping = "{internal_damping}"
[mesh]
shaft_elements = {elements}
"""


def jeffcott(eta: float, c_e: float, internal_damping: str = "rotating"):
    """The assembled Jeffcott-like rotor."""
    return build_model(loads_design(jeffcott_text(eta, c_e, internal_damping)))


def disk_dofs(model):
    """Global indices (v, w) of the disk node."""
    node = model.dofs.node_at("shaft", L / 2)
    return model.dofs.shaft(node, "v"), model.dofs.shaft(node, "w")
