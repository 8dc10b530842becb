"""The assembled model's bookkeeping (:mod:`flexshaft.assembly.model`) against hand forms.

* **The rotation generator at a rigid coupling.** S rotates each node's lateral pair by −90°
  about x: (v, w) → (w, −v), (β, γ) → (γ, −β) (rotation matrix at θ = −π/2). Where a rigid
  coupling ties the aft node's v, w (and β, γ) to the forward node's, both nodes share one
  unknown pair, and S must rotate that pair once: (S q)_v = q_w, not 2 q_w. A forward circular
  whirl W = −iV, (γ, −β) = (B, −iB) stays an eigenvector with S q = −i q.
* **The tube mass of a two-zone shaft** is Σ ρ π/4 (D_o² − D_i²) L over its zones, here
  2700 · π/4 (0.1² − 0.09²) · 1 + 7800 · π/4 (0.06² − 0.05²) · 1.5 = 4.02909 + 10.10807 kg,
  not the nominal ``[shaft]`` tube over the whole length.
* **A PD law.** The collocated force law ``G − k_s`` of a bearing is a PD law K_p + s K_d (its
  gains describe it, :attr:`~flexshaft.assembly.model.Model.all_pd`) only without an amplifier
  lag: k_p/(1 + s/ω_a) is a first-order rational with a pole at s = −ω_a.

Exact integers and a few products: tolerances 1e-12 (round-off only).

Written for the mutations h51b-model-rotation-generator-tied-summed,
h51b-model-shaft-mass-two-segments-nominal and h51b-model-all-pd-ignores-lag of
scripts/mutations.toml.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.sparse as sp

from flexshaft.assembly.controller import Controller
from flexshaft.assembly.dofs import DofMap
from flexshaft.assembly.model import (
    Actuator,
    BearingLink,
    Model,
    SegmentProperties,
    ShaftProperties,
    rotation_generator,
)

TOL = 1e-12


def _coupled_dofs() -> DofMap:
    """Four shaft nodes, nodes 1 and 2 at the coupling's station; v, w, β, γ of node 2 tied to
    node 1's (a coupling rigid in bending and shear)."""
    tied = np.array([[6 * 2 + f, 6 * 1 + f] for f in (1, 2, 4, 5)])
    return DofMap(shaft_x=np.array([0.0, 1.0, 1.0, 2.0]), boom_x=np.zeros(0), shaft_joints=np.array([1]), tied=tied)


def _tube(density=2700.0, outer=0.1, inner=0.09) -> ShaftProperties:
    return ShaftProperties(
        outer_diameter=outer, inner_diameter=inner, youngs_modulus=70e9, shear_modulus=26e9, density=density
    )


def _model(dofs: DofMap, **kwargs) -> Model:
    zero = sp.csr_matrix((dofs.size, dofs.size))
    defaults = {"bearings": (), "actuators": (), "shaft": _tube(), "speed": 0.0, "power": 0.0}
    defaults.update(kwargs)
    return Model(dofs=dofs, M=zero, K=zero, C=zero, G=zero, **defaults)


def test_the_rotation_generator_rotates_a_tied_pair_once():
    dofs = _coupled_dofs()
    S = rotation_generator(dofs).toarray()
    rng = np.random.default_rng(3)
    q = rng.standard_normal(dofs.size)
    Sq = S @ q
    for node in range(4):
        v, w, b, g = (dofs.shaft(node, f) for f in ("v", "w", "beta", "gamma"))
        np.testing.assert_allclose(Sq[[v, w]], [q[w], -q[v]], atol=TOL)
        np.testing.assert_allclose(Sq[[b, g]], [q[g], -q[b]], atol=TOL)
    fwd = np.zeros(dofs.size, dtype=complex)
    for node in (0, 1, 3):  # node 2's lateral DOFs are node 1's
        V, B = rng.standard_normal(2)
        fwd[dofs.shaft(node, "v")], fwd[dofs.shaft(node, "w")] = V, -1j * V
        fwd[dofs.shaft(node, "gamma")], fwd[dofs.shaft(node, "beta")] = B, 1j * B
    np.testing.assert_allclose(S @ fwd, -1j * fwd, atol=TOL)


def test_the_tube_mass_of_a_two_zone_shaft_sums_its_zones():
    front = SegmentProperties("front", 0.0, 1.0, "al", _tube())
    rear = SegmentProperties("rear", 1.0, 2.5, "steel", _tube(density=7800.0, outer=0.06, inner=0.05))
    by_hand = 2700.0 * math.pi / 4 * (0.1**2 - 0.09**2) * 1.0 + 7800.0 * math.pi / 4 * (0.06**2 - 0.05**2) * 1.5
    assert by_hand == pytest.approx(4.02909 + 10.10807, rel=1e-5)
    dofs = DofMap(shaft_x=np.linspace(0.0, 2.5, 6), boom_x=np.zeros(0))
    assert _model(dofs, segments=(front, rear)).shaft_mass == pytest.approx(by_hand, rel=TOL)


def _actuator(**kwargs) -> Actuator:
    dofs = DofMap(shaft_x=np.linspace(0.0, 2.0, 3), boom_x=np.zeros(0))
    cols = [dofs.shaft(1, f) for f in ("u", "v", "w", "beta", "gamma")]
    rows = sp.csr_matrix((np.ones(5), (np.arange(5), cols)), shape=(5, dofs.size))
    link = BearingLink(name="amb", kind="active", x_shaft=1.0, x_boom=None, offset=0.0, rows=rows)
    return Actuator(link=link, controller=Controller.pd(1.0e6, 200.0), **kwargs)


def test_a_pd_law_behind_an_amplifier_lag_is_not_a_pd_law():
    dofs = DofMap(shaft_x=np.linspace(0.0, 2.0, 3), boom_x=np.zeros(0))
    assert _model(dofs, actuators=(_actuator(),)).all_pd
    assert _model(dofs, actuators=(_actuator(negative_stiffness=2.0e5, current_gain=50.0),)).all_pd
    lagged = _actuator(amplifier_bandwidth=3000.0)
    assert not _model(dofs, actuators=(lagged,)).all_pd
    assert not _model(dofs, actuators=(_actuator(), lagged)).all_pd
