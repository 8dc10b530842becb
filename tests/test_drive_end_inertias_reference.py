"""Torsional drive ends and an active bearing's required gain against closed forms derived here.

The shaft is tests/test_torsional.py's near-massless steel tube (k = G J_p/L; its own polar
inertia ρ J_p L = 6.8e-8 kg m² is 1e-7 of the end inertias and moves the lumped closed forms'
roots by about 5e-8, the same order as the dense eigen-solver's error on that conditioning):
the closed forms are asserted to 3e-7, as there.

docs/model.md, "Torsional ends": the tail rotor's inertia is ``J_r = J_tr/n²`` with "the gear
ratio n = shaft speed / rotor speed"; the main gearbox's "reflected inertia ``J_g`` sits on the
forward θ with its torsional stiffness ``k_g`` to ground". docs/magnetic-bearings.md, active
bearing keys: ``kp`` is "required unless ``controller``".
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import K_SHAFT, shaft_text

from flexshaft.analyses.torsional import torsional_modes
from flexshaft.assembly import build_model
from flexshaft.design import DesignError, loads_design


def test_an_elastic_gearbox_without_inertia_is_a_spring_in_series_with_the_shaft():
    """[main_gearbox] with only ``stiffness`` (no ``polar_inertia``, so J_g = 0) and a rigidly
    driven tail rotor J_r = J_tr/n² at the aft end: with no inertia at the forward twist the
    gearbox spring k_g and the massless shaft k are in series, one finite mode
    ω² = k_s/J_r, 1/k_s = 1/k_g + 1/k (derived here). Any inertia J_g left at the forward twist
    makes it the lower root of the two-DOF J_g J_r ω⁴ − (J_g k + J_r (k_g + k)) ω² + k_g k = 0:
    0.01 kg m² there lowers this mode by 3e-4 relative (k = 1.35e5, k_g = 5e5 N m/rad), a
    thousand times the 3e-7 asserted."""
    kg, J_tr, n = 5.0e5, 3.0, 2.0
    Jr = J_tr / n**2
    text = shaft_text(
        f"[main_gearbox]\nstiffness = {kg}\n[tail_rotor]\nblades = 4\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n",
        fixed_start='["u", "v", "w"]',
    )
    k_series = 1.0 / (1.0 / kg + 1.0 / K_SHAFT)
    tm = torsional_modes(build_model(loads_design(text)), 1)
    assert tm.natural_frequencies[0] == pytest.approx(np.sqrt(k_series / Jr) / (2 * np.pi), rel=3e-7)


def test_a_step_up_tail_drive_reflects_a_larger_inertia():
    """A step-up tail drive, n = 0.5 (the rotor at twice the shaft speed), rigid, and a disk J1
    at the free forward end: J2 = J_tr/n² = 4 J_tr and the free-free two-inertia closed form
    ω² = k (J1 + J2)/(J1 J2) (derived here; docs/model.md's reflection holds for any n)."""
    J1, J_tr, n = 0.3, 0.5, 0.5
    J2 = J_tr / n**2
    text = shaft_text(
        f'[[disks]]\nname = "hub"\nx = 0.0\nmass = 1.0\npolar_inertia = {J1}\n'
        f"[tail_rotor]\nblades = 3\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n",
        fixed_start='["u", "v", "w"]',
    )
    tm = torsional_modes(build_model(loads_design(text)), 2)
    expected = np.sqrt(K_SHAFT * (J1 + J2) / (J1 * J2)) / (2 * np.pi)
    assert tm.natural_frequencies[1] == pytest.approx(expected, rel=3e-7)


ACTIVE = """
name = "active bearing without kp"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800.0
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = 0.1
wall_thickness = 0.005
material = "steel"
[[bearings]]
name = "fore"
kind = "contact"
x = 0.0
stiffness = { v = 1e8, w = 1e8 }
[[bearings]]
name = "amb"
kind = "active"
x = 1.0
%s
[operating]
speed_rpm = 0.0
power = 0.0
"""


def test_an_active_bearing_without_kp_or_controller_is_refused_naming_kp():
    """docs/magnetic-bearings.md: ``kp`` is "required unless ``controller``"; a PD bearing
    given only ``kd`` (and one given nothing) is refused on load naming ``kp``, while the same
    bearing with ``kp`` loads (so the refusal is the missing gain, not the rest of the file)."""
    loads_design(ACTIVE % "kp = 1.0e6\nkd = 500.0")
    for keys in ("kd = 500.0", ""):
        with pytest.raises(DesignError, match="kp"):
            loads_design(ACTIVE % keys)
