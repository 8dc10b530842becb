"""A free-free shaft's rigid-body twist is reported at exactly 0 Hz, whatever its mesh (derived here).

With no twist held, every shaft element's torsional stiffness acts on twist differences only,
so the uniform twist θ = 1 has K θ = 0: ω² = 0 exactly, a rigid-body mode. The generalized
eigen-solver returns it as round-off of either sign, measured here between 4e-11 and 5e-8
(rad/s)² on steel shafts of 2 to 12 elements whose largest ω² is 8e7 to 4e9 (rad/s)², i.e. a few
ε times the largest. :class:`~flexshaft.analyses.torsional.TorsionalModes` documents "0 for a free
rigid-body twist": the module judges ω² against 1e3 ε of the largest eigenvalue, so the reported
frequency, damped eigenvalue and damping ratio are the exact 0 it assigns (an assertion on the
sentinel, not on a solver's digits: the round-off lies 5 orders below that threshold, on any
BLAS). A threshold on ω² alone (not relative) would report the positive round-off as a
frequency of ~1e-5 Hz; the mesh sweep makes a positive round-off on some mesh near certain
(about half of them, measured).

The first flexible mode is checked against the two-inertia closed form of a near-massless
spring (k = G J_p/L between a disk J₁ and the tail rotor's reflected J_tr/n²): ω² = k (J₁ + J₂)/(J₁ J₂),
as in tests/test_torsional.py (tolerance 3e-7 there, from the shaft's residual mass 1e-7 of the
inertias and the mass matrix's conditioning).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.torsional import torsional_modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

G_STEEL = 80e9
DO, WALL, LENGTH = 0.1, 0.005, 2.0
J_POLAR = np.pi * (DO**4 - (DO - 2 * WALL) ** 4) / 32
K_SHAFT = G_STEEL * J_POLAR / LENGTH


def _free_free(elements: int, disk: float, density: float, rotor: str = ""):
    """A steel tube on two contact bearings, twist free at both ends, a disk on the forward end."""
    text = f"""
name = "free twist"
[materials.steel]
kind = "isotropic"
E = 210e9
G = {G_STEEL}
density = {density}
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = {LENGTH}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "v", "w"]
[[bearings]]
name = "fore"
kind = "contact"
x = 0.0
stiffness = {{ v = 1e8, w = 1e8 }}
[[bearings]]
name = "aft"
kind = "contact"
x = {LENGTH}
stiffness = {{ v = 1e8, w = 1e8 }}
[operating]
speed_rpm = 3000.0
power = 100.0e3
[mesh]
shaft_elements = {elements}
[[disks]]
name = "hub"
x = 0.0
mass = 1.0
polar_inertia = {disk}
{rotor}
"""
    return build_model(loads_design(text))


@pytest.mark.parametrize("disk", [0.3, 1.0])
def test_the_rigid_twist_of_a_free_free_shaft_is_zero_on_every_mesh(disk):
    """Steel density, 2 to 12 elements: mode 0 is the rigid twist, reported at 0 exactly."""
    for elements in (2, 3, 4, 5, 6, 8, 12):
        tm = torsional_modes(_free_free(elements, disk, 7800.0), 2)
        assert tm.natural_frequencies[0] == 0.0, elements
        assert tm.eigenvalues[0] == 0.0 and tm.damping_ratios[0] == 0.0, elements
        assert tm.natural_frequencies[1] > 0.0


def test_the_flexible_mode_beside_the_rigid_twist_is_the_two_inertia_closed_form():
    """Near-massless tube between J₁ = 0.3 and J₂ = J_tr/n² = 4/2.5²: ω² = k(J₁+J₂)/(J₁J₂)."""
    J1, J_tr, n = 0.3, 4.0, 2.5
    J2 = J_tr / n**2
    rotor = f"[tail_rotor]\nblades = 3\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n"
    for elements in (3, 5, 6):
        tm = torsional_modes(_free_free(elements, J1, 1e-2, rotor), 2)
        assert tm.natural_frequencies[0] == 0.0, elements
        expected = np.sqrt(K_SHAFT * (J1 + J2) / (J1 * J2)) / (2 * np.pi)
        assert tm.natural_frequencies[1] == pytest.approx(expected, rel=3e-7)
