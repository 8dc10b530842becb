"""Where a bearing sits on the boom and what it carries.

References (derived here):

* the shaft runs a height h above the boom's neutral axis: by default h = the boom's vertical
  mid-line semi-axis at the bearing's station plus the shaft clearance (docs/design-reference.md,
  the baseline file's comment), the semi-axis tapering linearly from root to tip;
* the attachment point moves with the boom section as r_b + θ_b × (0, h, 0) = (−h γ, v, w + h θ)
  (thesis §2.2.3): a rigid boom twist θ = 1 moves it by w = h, a rigid boom turn about z
  (v = x, γ = 1) by u = −h and v = x_b. The relative displacement is shaft minus attachment.
* a viscous damper carries f = c ẋ, i.e. iωc X for a harmonic X e^{iωt}; on the Jeffcott rotor of
  tests/rotors.py with the damper at the disk, X = F/(k − mω² + iωc) for a force F at the disk.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

import flexshaft as fs
from flexshaft.analyses.reactions import bearing_forces
from flexshaft.analyses.response import frequency_response
from flexshaft.design import baseline_design

ROOT_A, TIP_A, BOOM_L, CLEARANCE = 0.50, 0.25, 8.05, 0.08  # the baseline [tailboom] table


@pytest.fixture(scope="module")
def baseline():
    return fs.build_model(baseline_design())


def test_default_bearing_height_is_the_vertical_semi_axis_plus_clearance(baseline):
    design = baseline.design
    assert design.tailboom.root_semi_axes[0] == ROOT_A and design.tailboom.tip_semi_axes[0] == TIP_A
    assert len(baseline.bearings) == 4
    for link in baseline.bearings:
        a = ROOT_A + (TIP_A - ROOT_A) * link.x_boom / BOOM_L
        assert link.offset == pytest.approx(a + CLEARANCE, rel=1e-12), link.name


def test_rigid_boom_motion_moves_the_attachment_point(baseline):
    dm = baseline.dofs
    nodes = np.arange(dm.n_boom_nodes)
    twist = np.zeros(dm.size)
    twist[dm.boom(nodes, "theta")] = 1.0
    turn = np.zeros(dm.size)
    turn[dm.boom(nodes, "v")] = np.asarray(dm.boom_x, dtype=float)
    turn[dm.boom(nodes, "gamma")] = 1.0
    for link in baseline.bearings:
        h = link.offset
        rel = link.rows @ twist  # (u, v, w, β, γ): shaft (at rest) minus attachment
        assert rel == pytest.approx([0.0, 0.0, -h, 0.0, 0.0], abs=1e-12)
        rel = link.rows @ turn
        assert rel == pytest.approx([h, -link.x_boom, 0.0, 0.0, -1.0], rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("ratio", [0.5, 1.0, 1.7])
def test_a_dashpot_carries_i_omega_c_times_its_stroke(ratio):
    c = 0.2 * 2 * np.sqrt(K_SHAFT * M_DISK)
    model = jeffcott(0.0, c)
    v, _ = disk_dofs(model)
    Q = np.zeros(model.dofs.size, complex)
    Q[v] = 1.0
    omega = ratio * WN
    q = np.asarray(frequency_response(model, Q, [omega], speed=0.0))[..., 0].ravel()
    X = 1.0 / (K_SHAFT - M_DISK * omega**2 + 1j * omega * c)
    # the tube's mass (7e-6 of the disk's) shifts the closed form by a few 1e-6
    assert q[v] == pytest.approx(X, rel=1e-4)
    force = bearing_forces(model, q, omega)["external_damper"]
    assert force[1] == pytest.approx(1j * omega * c * X, rel=1e-4)
    assert force[[0, 2, 3, 4]] == pytest.approx(np.zeros(4), abs=1e-12)
