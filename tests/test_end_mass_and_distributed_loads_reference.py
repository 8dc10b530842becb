"""An end-mass point load and a distributed imbalance as load vectors, against statics by hand.

* **A force F and a couple M at the end mass**, whose centre sits at offset e from the boom's tip
  node (DOFs v, w and the small rotation φ = (θ, β, γ) about x, y, z). The mass point moves by
  δr = (0, δv, δw) + φ × e (rigid-body kinematics; the boom has no axial DOF), so the virtual
  work F · δr + M · φ = F_y δv + F_z δw + φ · (e × F + M) gives the generalised forces on the
  tip: Q_v = F_y, Q_w = F_z and (Q_θ, Q_β, Q_γ) = e × F + M, the moment of F about the tip node
  plus the couple. An offset with all three components and a force with all three make every
  term of e × F count (a flipped arm reverses it, a flipped couple reverses M's part).
* **The distributed imbalance** of a single bay [0, L] between bearings at both ends: the force
  e_c m (per unit Ω², ISO 21940-11: m the whole rotor, here the tube ρ π (r_o² − r_i²) L) spread
  uniformly over the bay's length, e_c m / L per metre. Its consistent load vector has the
  resultant e_c m and the first moment e_c m L/2 (a uniform load's centroid at mid-bay), and
  Q_w = −i Q_v (a forward-rotating force). Sums as in tests/test_load_vectors_reference.py.

Tolerance: a few products of O(1) numbers; rel 1e-9 (the Gauss rule of the line load is exact
on the cubic shape functions). The models are those of tests/test_load_vectors_reference.py
(10 shaft and 4 boom elements: the identities hold at any mesh).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_load_vectors_reference import BOOM, ECC, TEXT, L, shaft_sums, tube_mass

from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads, point_load
from flexshaft.design import loads_design

OFFSET = (0.3, -0.2, 0.4)  # m, e from the tip node
FORCE = (120.0, -350.0, 80.0)  # N
COUPLE = (15.0, -40.0, 25.0)  # N m


@pytest.fixture(scope="module")
def offset_mass():
    text = TEXT + BOOM.replace("offset = [0.0, 0.0, 0.0]", f"offset = [{OFFSET[0]}, {OFFSET[1]}, {OFFSET[2]}]")
    return build_model(loads_design(text))


def _tip(model, Q):
    dm = model.dofs
    return np.array([Q[dm.boom(-1, f)] for f in ("v", "w", "theta", "beta", "gamma")])


def test_an_end_mass_force_acts_at_the_tip_with_its_moment_about_the_tip(offset_mass):
    Q = point_load(offset_mass, "end_mass", FORCE)
    e, F = np.array(OFFSET), np.array(FORCE)
    expected = np.concatenate([F[1:], np.cross(e, F)])
    np.testing.assert_allclose(_tip(offset_mass, Q), expected, rtol=1e-9, atol=1e-9 * np.abs(F).max())
    # nothing anywhere else: the mass hangs on the tip node alone
    assert np.abs(Q).sum() == pytest.approx(np.abs(expected).sum(), rel=1e-12)


def test_an_end_mass_couple_adds_to_the_tip_rotations(offset_mass):
    both = _tip(offset_mass, point_load(offset_mass, "end_mass", FORCE, COUPLE))
    force_only = _tip(offset_mass, point_load(offset_mass, "end_mass", FORCE))
    np.testing.assert_allclose(both - force_only, [0.0, 0.0, *COUPLE], rtol=1e-9, atol=1e-9)


def test_the_distributed_imbalance_is_e_m_spread_over_the_bay():
    tube = build_model(loads_design(TEXT))
    Q = imbalance_loads(tube, placement="distributed")[:, 0]
    force, moment = shaft_sums(tube, Q.real, "v")
    total = ECC * tube_mass()
    assert force == pytest.approx(total, rel=1e-9)
    assert moment == pytest.approx(total * L / 2, rel=1e-9)
    dm = tube.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    np.testing.assert_allclose(Q[dm.shaft(nodes, "w")], -1j * Q[dm.shaft(nodes, "v")], rtol=1e-12, atol=1e-20)
