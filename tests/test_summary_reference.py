"""The model summary's numbers (``results.json``'s ``summary``, the ``run`` command's printed
line) against closed forms on a Jeffcott rotor with a small tail boom.

References (derived): torque T = P/Ω with Ω = N·2π/60 [rad/s] for N [rpm]; the operating speed
in rpm is the design file's own ``speed_rpm``; the total mass is the sum of the design file's
masses: the disk, the thin-walled circular boom tube ρ·2πrt·L (the section is a circle of
radius r at both ends, so the tube's area is exactly 2πrt for the code's mid-wall ellipse,
and a consistent-mass beam carries its full mass in a rigid translation), the end mass and
the steel tube (7e-6 of the disk, below the tolerance).
"""

from __future__ import annotations

import math

import pytest
from conftest import RUN_DESIGN
from rotors import DI, DO, M_DISK, jeffcott_text

from flexshaft.analyses.summary import model_summary
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

SPEED_RPM, POWER = 3000.0, 50.0e3
BOOM_RHO, BOOM_R, BOOM_T, BOOM_L, END_MASS = 2700.0, 0.3, 0.004, 1.5, 30.0

BOOM = f"""
[materials.boom]
kind = "isotropic"
E = 71.0e9
G = 27.0e9
density = {BOOM_RHO}
loss_factor = 0.0
[tailboom]
length = {BOOM_L}
root_semi_axes = [{BOOM_R}, {BOOM_R}]
tip_semi_axes = [{BOOM_R}, {BOOM_R}]
wall_thickness = {BOOM_T}
material = "boom"
shaft_clearance = 0.05
[tailboom.end_mass]
mass = {END_MASS}
offset = [0.0, 0.5, 0.0]
inertia = [0.0, 0.0, 0.0]
"""


@pytest.fixture(scope="module")
def summary() -> dict:
    text = jeffcott_text(0.01, 0.0, elements=2).replace(
        "speed_rpm = 0.0\npower = 0.0", f"speed_rpm = {SPEED_RPM}\npower = {POWER}"
    )
    text = text.replace("shaft_elements = 2", "shaft_elements = 2\nboom_elements = 2")
    return model_summary(build_model(loads_design(text + BOOM)))


def test_operating_speed_and_torque_closed_form(summary):
    """N in rpm as given; T = P/Ω = 50 kW / (3000·2π/60 rad/s) = 159.15 N m. Tolerance 1e-12:
    both are one division each (round-off only)."""
    omega = SPEED_RPM * 2.0 * math.pi / 60.0
    assert summary["operating_speed_rpm"] == pytest.approx(SPEED_RPM, rel=1e-12)
    assert summary["torque_Nm"] == pytest.approx(POWER / omega, rel=1e-12)
    assert summary["torque_Nm"] == pytest.approx(159.1549, rel=1e-6)


def test_total_mass_is_the_sum_of_the_design_masses(summary):
    """disk 20 kg + boom 2700·2π·0.3·0.004·1.5 = 30.54 kg + end mass 30 kg = 80.54 kg. Tolerance
    1e-6: a rigid translation of consistent-mass elements carries their mass exactly; the steel
    tube (density 0.1, 7e-5 kg) is 1e-6 of the total."""
    tube = 0.1 * math.pi * (DO**2 - DI**2) / 4 * 1.0
    boom = BOOM_RHO * 2.0 * math.pi * BOOM_R * BOOM_T * BOOM_L
    assert summary["total_mass_kg"] == pytest.approx(M_DISK + boom + END_MASS + tube, rel=1e-6)


def test_loss_factors_of_a_zero_degree_laminate():
    """The tests' run design (T700/Adiprene, 4 shaft elements) with every ply at 0°: E loss
    factor η_EL = 0.0003 and G loss factor η_GLT = 0.12 of the design's lamina (at 20 °C, the
    temperature table's reference row), storage moduli E_L and G_LT. Tolerance 1e-9: one
    complex inversion of a diagonal compliance (round-off)."""
    text = RUN_DESIGN.replace("(55/-55/0/0)s", "(0/0/0/0)s")
    assert text != RUN_DESIGN
    design = loads_design(text)
    lamina = design.materials[design.shaft.material]
    s = model_summary(build_model(design))
    assert lamina.loss_E_L != lamina.loss_G_LT  # the test's premise: the two are told apart
    assert s["shaft_E_loss_factor"] == pytest.approx(lamina.loss_E_L, rel=1e-9)
    assert s["shaft_G_loss_factor"] == pytest.approx(lamina.loss_G_LT, rel=1e-9)
    assert s["shaft_E_storage_Pa"] == pytest.approx(lamina.E_L, rel=1e-9)
    assert s["shaft_G_storage_Pa"] == pytest.approx(lamina.G_LT, rel=1e-9)
