"""The model's description of its drive train (``Model.drive``) against hand reflections.

docs/model.md, "Torsional ends": every value is "reflected to the shaft's speed through the gear
ratio n = shaft speed / rotor speed"; the tail rotor's inertia is ``J_r = J_tr/n²`` "on a twist
DOF of its own, joined to the shaft's aft θ by the drive's springs in series,
``1/k_r = 1/k_input + n²/k_hub``"; "without drive springs ``J_r`` and ``c_r`` sit on the shaft's
aft θ"; the main gearbox's ``J_g`` sits on the forward θ with ``k_g`` to ground.

Hand values (derived here): J_tr = 4 kg m², n = 2, k_input = 2e4 N m/rad, k_hub = 8e4 N m/rad:
J_r = 4/2² = 1 kg m², 1/k_r = 1/2e4 + 2²/8e4 = 1e-4 rad/(N m), k_r = 1e4 N m/rad; a gearbox
J_g = 0.3 kg m², k_g = 5e4 N m/rad. The rotor's twist DOF carries only J_r (mass) and k_r
(its end of the drive spring), so the assembled diagonal entries there are J_r and k_r too.

A few divisions: 1e-12 relative (round-off only).

Written for the mutations h99a-drive-described-inertia-unreflected,
h99a-drive-described-stiffness-rotor-side and h99a-drive-elastic-rotor-ignores-rigid of
scripts/mutations.toml.
"""

from __future__ import annotations

import math

import pytest
from test_torsional import shaft_text

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

J_TR, N, K_INPUT, K_HUB = 4.0, 2.0, 2.0e4, 8.0e4
J_G, K_G = 0.3, 5.0e4
J_R = J_TR / N**2  # 1 kg m²
K_R = 1.0 / (1.0 / K_INPUT + N**2 / K_HUB)  # 1e4 N m/rad


def _model(drive_springs: bool):
    springs = f"input_stiffness = {K_INPUT}\nhub_stiffness = {K_HUB}\n" if drive_springs else ""
    tables = (
        f"[main_gearbox]\npolar_inertia = {J_G}\nstiffness = {K_G}\n"
        f"[tail_rotor]\nblades = 2\npolar_inertia = {J_TR}\ngearbox_ratio = {N}\n{springs}"
    )
    return build_model(loads_design(shaft_text(tables, fixed_start='["u", "v", "w"]', elements=4)))


def test_hand_values():
    assert J_R == pytest.approx(1.0, rel=1e-15)
    assert K_R == pytest.approx(1.0e4, rel=1e-12)


def test_an_elastic_drive_is_described_at_the_shafts_speed():
    """``Model.drive`` gives J_r = J_tr/n² and k_r of the springs in series through n², the
    values its own DOF carries in M and K; the gearbox's J_g and k_g as given."""
    model = _model(drive_springs=True)
    drive = model.drive
    assert drive.has_rotor and drive.elastic_rotor
    assert drive.gearbox_ratio == pytest.approx(N, rel=1e-15)
    assert drive.rotor_inertia == pytest.approx(J_R, rel=1e-12)
    assert drive.rotor_stiffness == pytest.approx(K_R, rel=1e-12)
    dof = drive.rotor_dof
    assert dof == model.dofs.extra_dof("tail_rotor")
    assert model.M[dof, dof] == pytest.approx(J_R, rel=1e-12)
    assert model.K[dof, dof] == pytest.approx(K_R, rel=1e-12)
    assert drive.gearbox_inertia == pytest.approx(J_G, rel=1e-15)
    assert drive.gearbox_stiffness == pytest.approx(K_G, rel=1e-15)


def test_a_rigid_drive_puts_the_rotor_on_the_shafts_aft_twist():
    """Without drive springs the rotor has no twist DOF of its own: the drive is not elastic,
    its stiffness is infinite and its DOF is the shaft's aft θ; J_r is still J_tr/n²."""
    model = _model(drive_springs=False)
    drive = model.drive
    assert drive.has_rotor
    assert not drive.elastic_rotor
    assert math.isinf(drive.rotor_stiffness)
    assert drive.rotor_dof == model.dofs.shaft(-1, "theta")
    assert drive.rotor_inertia == pytest.approx(J_R, rel=1e-12)
