"""A free-free shaft's rigid-body twist is reported at exactly 0 Hz, whatever its mesh (derived here).

With no twist held, every shaft element's torsional stiffness acts on twist differences only,
so the uniform twist θ = 1 has K θ = 0: ω² = 0 exactly, a rigid-body mode. The generalized
eigen-solver returns it as round-off of either sign, measured here on the 14 steel meshes below
(2 to 12 elements, largest ω² 8e7 to 4e9 (rad/s)²): |ω²| = 1.9e-10 to 3.0e-7 (rad/s)², i.e.
5e-19 to 6.9e-17 of the largest ω² (0.002 to 0.3 ε), on OpenBLAS's Prescott, Haswell and
SkylakeX kernels. :class:`~flexshaft.analyses.torsional.TorsionalModes` documents "0 for a free
rigid-body twist": the module judges ω² against 1e3 ε of the largest eigenvalue, so the reported
frequency, damped eigenvalue and damping ratio are the exact 0 it assigns (an assertion on the
sentinel, not on a solver's digits: the round-off lies 3.5 to 5.6 orders below that threshold).
A threshold on ω² alone (not relative) would report a positive round-off as a frequency of
~1e-5 Hz; which meshes give a positive round-off depends on the kernel (measured: Prescott 7 of
the 14, Haswell 8, SkylakeX 10), so this sweep catches it only by that sign. The slow
two-inertia model of the last test catches it deterministically: its flexible ω² = 2k/J =
5.8e-21 (rad/s)² is itself below the absolute threshold 1e3 ε = 2.2e-13 (rad/s)², so such a
threshold reports 0 Hz where the closed form gives 1.21169e-11 Hz.

With no damping (loss factor 0, no damper: C = 0, K'' = 0) the damped roots are s = ±iω, so the
damped frequency equals the undamped one; the companion (quadratic) eigen-solve agrees with the
symmetric one to 2e-13 measured, asserted to 1e-9 (margin for the quadratic's conditioning on
other kernels, still far below any physical damping shift).

The first flexible mode is checked against the two-inertia closed form of a near-massless
spring (k = G J_p/L between a disk J₁ and the tail rotor's reflected J_tr/n²): ω² = k (J₁ + J₂)/(J₁ J₂),
as in tests/test_torsional.py (tolerance 3e-7 there, from the shaft's residual mass 1e-7 of the
inertias and the mass matrix's conditioning).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import K_SHAFT, shaft_text

from flexshaft.analyses.torsional import torsional_modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def _free_free(elements: int, disk: float, density: float, rotor: str = ""):
    """A steel tube on two contact bearings, twist free at both ends, a disk on the forward end."""
    disk_table = f'[[disks]]\nname = "hub"\nx = 0.0\nmass = 1.0\npolar_inertia = {disk}\n'
    text = shaft_text(disk_table + rotor, '["u", "v", "w"]', density=density, elements=elements)
    return build_model(loads_design(text))


@pytest.mark.parametrize("disk", [0.3, 1.0])
def test_the_rigid_twist_of_a_free_free_shaft_is_zero_on_every_mesh(disk):
    """Steel density, 2 to 12 elements: mode 0 is the rigid twist, reported at 0 exactly."""
    for elements in (2, 3, 4, 5, 6, 8, 12):
        tm = torsional_modes(_free_free(elements, disk, 7800.0), 2)
        assert tm.natural_frequencies[0] == 0.0, elements
        assert tm.eigenvalues[0] == 0.0 and tm.damping_ratios[0] == 0.0, elements
        assert tm.natural_frequencies[1] > 0.0
        assert tm.frequencies[1] == pytest.approx(tm.natural_frequencies[1], rel=1e-9), elements


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


SLOW = """
name = "slow twist"
[materials.foam]
kind = "isotropic"
E = 2.6e3
G = 1e3
density = 1e-6
loss_factor = 0.0
[shaft]
x_start = -1000.0
x_end = 1000.0
outer_diameter = 0.001
wall_thickness = 1e-4
material = "foam"
fixed_start = ["u", "v", "w"]
fixed_end = ["v", "w"]
[[bearings]]
name = "fore"
kind = "contact"
x = -1000.0
stiffness = { v = 1e-13, w = 1e-13 }
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 1
[[disks]]
name = "a"
x = -1000.0
mass = 1.0
polar_inertia = 1e7
[[disks]]
name = "b"
x = 1000.0
mass = 1.0
polar_inertia = 1e7
"""


def test_a_very_slow_twist_mode_is_not_taken_for_the_rigid_one():
    """Two disks J = 1e7 kg m² on a 2000 m foam tube (G = 1 kPa, D = 1 mm, wall 0.1 mm), all
    within docs/limits.md: ω² = 2k/J, k = G J_p/L (two equal inertias on a spring, derived here),
    f = 1.21169e-11 Hz. The tube's own polar inertia ρ J_p L ≈ 1.2e-16 kg m² is 1e-23 of J, so the
    closed form is exact to round-off; ω² is the largest eigenvalue, relative accuracy a few ε:
    tolerance 1e-12 (``abs=0``: pytest's default absolute 1e-12 would swamp a 1e-11 Hz value).
    The rigid twist beside it is the exact 0 the module assigns."""
    do, wall, length, g, j = 0.001, 1e-4, 2000.0, 1e3, 1e7
    j_polar = np.pi * (do**4 - (do - 2 * wall) ** 4) / 32
    expected = np.sqrt(2 * g * j_polar / length / j) / (2 * np.pi)
    assert expected == pytest.approx(1.21169e-11, rel=1e-5, abs=0.0)
    tm = torsional_modes(build_model(loads_design(SLOW)), 2)
    assert tm.natural_frequencies[0] == 0.0
    assert tm.natural_frequencies[1] == pytest.approx(expected, rel=1e-12, abs=0.0)
