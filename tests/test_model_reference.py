"""The assembled model's own physics (:mod:`flexshaft.assembly.model`) from closed forms.

* The tube mass of a hollow section, ρ π (r_o² − r_i²) L, written with radii by hand.
* The rotation generator S: each shaft node's lateral pair (v, w) rotated by −90° about x, the
  rotation matrix [[cos θ, −sin θ], [sin θ, cos θ]] at θ = −π/2; a forward circular whirl
  (v, w) = Re((1, −i) e^{iωt}) = (cos ωt, sin ωt) is an eigenvector with S q = −i q.
* The loss split: the shaft's lateral loss K''_lat is K'' restricted to the lateral DOFs
  (v, w, β, γ) of the shaft nodes; the fixed-frame part is the rest, so both add to K''.
* A first-order amplifier lag 1/(1 + s/ω_a) at its corner s = iω_a: magnitude 1/√2, phase −45°.
* The magnet acts on the lateral pair (v, w) of the bearing's rows (u, v, w, β, γ).

Tolerances: the matrices are built from a few products of O(1) numbers (1e-12 is far above
their round-off); the masses and the lag are a few floating-point operations (rel 1e-12).
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
LATERAL = ("v", "w", "beta", "gamma")


def _dofs(n: int = 3) -> DofMap:
    return DofMap(shaft_x=np.linspace(0.0, 2.0, n), boom_x=np.zeros(0))


def _tube(density=2700.0, outer=0.1, inner=0.09) -> ShaftProperties:
    return ShaftProperties(
        outer_diameter=outer, inner_diameter=inner, youngs_modulus=70e9, shear_modulus=26e9, density=density
    )


def _model(dofs: DofMap, **kwargs) -> Model:
    zero = sp.csr_matrix((dofs.size, dofs.size))
    return Model(
        dofs=dofs,
        M=zero,
        K=zero,
        C=zero,
        G=zero,
        bearings=(),
        actuators=(),
        shaft=_tube(),
        speed=0.0,
        power=0.0,
        **kwargs,
    )


def test_tube_masses_by_hand():
    """ρ π (r_o² − r_i²) L: aluminium 2700 kg/m³, r_o = 50 mm, r_i = 45 mm, L = 2 m → 8.0582 kg."""
    by_hand = 2700.0 * math.pi * (0.05**2 - 0.045**2) * 2.0
    segment = SegmentProperties(name="tube", x_start=1.0, x_end=3.0, material="al", properties=_tube())
    assert segment.mass == pytest.approx(by_hand, rel=TOL)
    assert _model(_dofs()).shaft_mass == pytest.approx(by_hand, rel=TOL)


def test_rotation_generator_rotates_each_lateral_pair_by_minus_ninety_degrees():
    dofs = _dofs()
    S = rotation_generator(dofs).toarray()
    theta = -math.pi / 2
    R = np.array([[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]])
    rng = np.random.default_rng(0)
    q = rng.standard_normal(dofs.size)
    Sq = S @ q
    for node in range(dofs.n_shaft_nodes):
        v, w, b, g = (dofs.shaft(node, f) for f in LATERAL)
        np.testing.assert_allclose(Sq[[v, w]], R @ q[[v, w]], atol=TOL)
        # (γ, −β) = ∂(v, w)/∂x rotates with (v, w): γ' = −β, β' = γ.
        np.testing.assert_allclose(Sq[[g, b]], [-q[b], q[g]], atol=TOL)
        assert Sq[dofs.shaft(node, "u")] == 0.0 and Sq[dofs.shaft(node, "theta")] == 0.0
    # a forward circular whirl W = −iV at every node is an eigenvector with eigenvalue −i
    fwd = np.zeros(dofs.size, dtype=complex)
    for node in range(dofs.n_shaft_nodes):
        V, B = rng.standard_normal(2)
        fwd[dofs.shaft(node, "v")], fwd[dofs.shaft(node, "w")] = V, -1j * V
        fwd[dofs.shaft(node, "gamma")], fwd[dofs.shaft(node, "beta")] = B, 1j * B  # (γ, −β) = (B, −iB)
    np.testing.assert_allclose(S @ fwd, -1j * fwd, atol=TOL)


def test_loss_split_partitions_the_shaft_loss():
    """K''_lat = K'' on the shaft's lateral DOFs only; fixed + lateral = shaft + boom; K''_lat S."""
    dofs = _dofs()
    rng = np.random.default_rng(1)
    A = rng.standard_normal((dofs.size, dofs.size))
    loss = A + A.T
    model = _model(dofs, shaft_loss_stiffness=sp.csr_matrix(loss))
    lateral = np.zeros(dofs.size, dtype=bool)
    for node in range(dofs.n_shaft_nodes):
        for f in LATERAL:
            lateral[dofs.shaft(node, f)] = True
    expected_lat = np.where(np.outer(lateral, lateral), loss, 0.0)
    np.testing.assert_allclose(model.loss_lateral.toarray(), expected_lat, atol=TOL)
    np.testing.assert_allclose(model.loss_fixed.toarray(), loss - expected_lat, atol=TOL)
    S = rotation_generator(dofs).toarray()
    np.testing.assert_allclose(model.loss_circulatory.toarray(), expected_lat @ S, atol=TOL)


def _link(dofs: DofMap, node: int = 1) -> BearingLink:
    """Relative-displacement rows (u, v, w, β, γ) of a bearing on shaft node ``node`` to ground."""
    cols = [dofs.shaft(node, f) for f in ("u", "v", "w", "beta", "gamma")]
    rows = sp.csr_matrix((np.ones(5), (np.arange(5), cols)), shape=(5, dofs.size))
    return BearingLink(name="amb", kind="active", x_shaft=1.0, x_boom=None, offset=0.0, rows=rows)


def test_amplifier_lag_at_its_corner():
    """G(iω_a) = k_p / (1 + i): |G| = k_p/√2 and phase −45° for a lag of bandwidth ω_a [rad/s]."""
    kp, wa = 2.0e6, 3000.0
    act = Actuator(link=_link(_dofs()), controller=Controller.pd(kp, 0.0), amplifier_bandwidth=wa)
    g = complex(act.feedback_gain(1j * wa))
    assert abs(g) == pytest.approx(kp / math.sqrt(2.0), rel=TOL)
    assert math.degrees(math.atan2(g.imag, g.real)) == pytest.approx(-45.0, rel=TOL)
    assert complex(act.plant(1j * wa)) == pytest.approx(1.0 / (1.0 + 1j), rel=TOL)


def test_magnet_carries_force_in_v_and_w():
    """A collocated PD magnet of stiffness k_p with the shaft displaced (u, v, w) = (3, 1, −2) mm
    carries k_p (v, w) = k_p (1, −2) mm: the axial displacement plays no part."""
    dofs = _dofs()
    kp = 1.0e6
    act = Actuator(link=_link(dofs), controller=Controller.pd(kp, 0.0))
    q = np.zeros(dofs.size)
    q[dofs.shaft(1, "u")], q[dofs.shaft(1, "v")], q[dofs.shaft(1, "w")] = 3e-3, 1e-3, -2e-3
    np.testing.assert_allclose(act.carried_force(q, 0.0), [kp * 1e-3, -kp * 2e-3], rtol=TOL)
    gram = act.lateral_gram.toarray()
    expected = np.zeros((dofs.size, dofs.size))
    for f in ("v", "w"):
        expected[dofs.shaft(1, f), dofs.shaft(1, f)] = 1.0
    np.testing.assert_array_equal(gram, expected)


def test_tube_mass_of_a_shaft_starting_aft_of_the_origin():
    """The same tube between x = 1 m and x = 3 m: L = x_end − x_start = 2 m, 8.0582 kg (not the
    3 m of its aft station)."""
    by_hand = 2700.0 * math.pi * (0.05**2 - 0.045**2) * 2.0
    dofs = DofMap(shaft_x=np.linspace(1.0, 3.0, 3), boom_x=np.zeros(0))
    assert _model(dofs).shaft_mass == pytest.approx(by_hand, rel=TOL)


def test_a_torsional_loss_alone_is_a_loss():
    """A shaft whose only loss is torsional (K''_θθ = 1e3 N m/rad at one node) has loss: the
    module docstring puts the shaft's torsional strains in the fixed-frame loss matrix."""
    dofs = _dofs()
    t = dofs.shaft(1, "theta")
    loss = sp.csr_matrix(([1.0e3], ([t], [t])), shape=(dofs.size, dofs.size))
    model = _model(dofs, shaft_loss_stiffness=loss)
    assert model.loss_lateral.nnz == 0 and model.loss_fixed.nnz == 1
    assert model.has_loss
    assert not _model(dofs).has_loss
