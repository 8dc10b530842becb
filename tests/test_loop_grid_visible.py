"""The loops' grid leaves out the natural frequencies of modes no loop can see (issue 30).

A block of DOFs that no term of Z(ω, Ω) couples to the loops' actuation and sensing rows
(a shaft's axial motion and torsion) does not enter any loop's T = G sᵀ Z_c⁻¹ a: with Z block
diagonal, sᵀ Z⁻¹ a = s_Bᵀ Z_B⁻¹ a_B over the blocks B that hold the rows, so that block's
natural frequencies are no poles of S (derived; :mod:`flexshaft.analyses.loop_grid`), and the
grid takes no stand-in point there.

* A three-DOF stand-in (M = I): DOFs 0 and 1 coupled, K = [[500, −200], [−200, 500]] with
  eigenvalues 500 ∓ 200 = 300 and 700, DOF 2 alone with K = 400: natural frequencies √300,
  √700 and 20 rad/s by hand, and the same with K and M both 1e16 times larger (other units:
  the mode shapes' size changes, not what is seen). The loops' rows at DOF 0 see √300 and √700
  only, by both ways of computing them (the whole spectrum's modes classified by their shapes,
  the subset solve of the visible DOFs). With DOF 2's stiffness 300, its mode and the coupled
  block's first share one eigenvalue and the eigensolver may return any rotation of the two:
  √300 must stay.
  Rel 1e-12: square roots of exact small integers.
* A steel tube (1 m, 8 elements, a 20 kg disk) on two magnetic bearings, its axial and
  torsional motion held at its start: the loops' grid with no poles given holds every natural
  frequency of (K + K_a, M) restricted by DOF name to the lateral fields (v, w, β, γ) in range
  and none of those restricted to the axial and torsional fields (u, θ) — a dense solve of
  each named block, not the solver's sparsity pattern. The two sets of frequencies are at
  least 1e-4 apart here; a point is matched to 1e-9 relative (the same eigenproblem solved
  two ways: round-off 1e-13).

CPU: the stand-ins a few milliseconds; the tube's model and its loops on a 20-point grid
about 0.1 s.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
import scipy.linalg as la
import scipy.sparse as sp

from flexshaft.analyses import loop_grid
from flexshaft.analyses.bearing_loops import bearing_loops
from flexshaft.analyses.loop_grid import natural_frequencies
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


class _Model(SimpleNamespace):
    """A stand-in model, hashable by identity like a Model (the whole-spectrum cache's key)."""

    __hash__ = object.__hash__


def _three_dof_model(alone: float, scale: float = 1.0):
    K = np.array([[500.0, -200.0, 0.0], [-200.0, 500.0, 0.0], [0.0, 0.0, alone]])
    return _Model(
        dofs=SimpleNamespace(free=np.arange(3)),
        K=sp.csr_matrix(scale * K),
        Kp=sp.csr_matrix((3, 3)),
        M=sp.csr_matrix(scale * np.eye(3)),
    )


@pytest.mark.parametrize("scale", [1.0, 1e16], ids=["M = I", "M = 1e16 I"])
@pytest.mark.parametrize("whole_up_to", [400, 0], ids=["whole spectrum", "subset solve"])
def test_only_the_visible_blocks_natural_frequencies(monkeypatch, whole_up_to, scale):
    """K and M scaled together (other units) leave the frequencies and what is seen alone."""
    monkeypatch.setattr(loop_grid, "WHOLE_DENSE_BASIS_UP_TO", whole_up_to)
    model = _three_dof_model(400.0, scale)
    visible = np.array([True, True, False])
    np.testing.assert_allclose(natural_frequencies(model, 0.0, 100.0), np.sqrt([300.0, 400.0, 700.0]), rtol=1e-12)
    np.testing.assert_allclose(natural_frequencies(model, 0.0, 100.0, visible), np.sqrt([300.0, 700.0]), rtol=1e-12)
    np.testing.assert_allclose(natural_frequencies(model, 0.0, 100.0, ~visible), [20.0], rtol=1e-12)


@pytest.mark.parametrize("whole_up_to", [400, 0], ids=["whole spectrum", "subset solve"])
def test_a_frequency_shared_with_an_unseen_block_stays(monkeypatch, whole_up_to):
    monkeypatch.setattr(loop_grid, "WHOLE_DENSE_BASIS_UP_TO", whole_up_to)
    found = natural_frequencies(_three_dof_model(300.0), 0.0, 100.0, np.array([True, True, False]))
    assert found.size in (2, 3)  # the shared eigenvalue once or, from a rotated pair, twice
    expected = np.sqrt([300.0, 700.0])
    distance = np.abs(found[:, None] / expected[None, :] - 1.0)
    assert (distance.min(axis=0) <= 1e-12).all() and (distance.min(axis=1) <= 1e-12).all()


TUBE = """
name = "steel tube on two magnetic bearings"
[materials.steel]
kind = "isotropic"
E = 2.1e11
G = 8.1e10
density = 7800.0
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = 0.1
wall_thickness = 0.01
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "amb_1"
kind = "active"
x = 0.1
ks = 1.0e5
ki = 100.0
kp = 3000.0
kd = 5.0
[[bearings]]
name = "amb_2"
kind = "active"
x = 0.9
ks = 1.0e5
ki = 100.0
kp = 3000.0
kd = 5.0
[[disks]]
name = "disk"
x = 0.5
mass = 20.0
diametral_inertia = 0.5
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 8
"""


def _named_block_frequencies(model, fields: tuple[str, ...], high: float) -> np.ndarray:
    """Natural frequencies [rad/s] in (0, high] of (K + K_a, M) on the free shaft DOFs of
    ``fields`` (a dense solve of that block alone)."""
    free = set(model.dofs.free.tolist())
    dofs = sorted(
        i
        for node in range(model.dofs.n_shaft_nodes)
        for f in fields
        if (i := model.dofs.index("shaft", node, f)) in free
    )
    K = (model.K + model.Kp).tocsr()[dofs][:, dofs].toarray()
    M = model.M.tocsr()[dofs][:, dofs].toarray()
    w2 = la.eigh(K, M, eigvals_only=True)
    return np.sqrt(w2[(w2 > 0) & (w2 <= high * high)])


def test_the_tubes_grid_takes_the_lateral_natural_frequencies_only():
    model = build_model(loads_design(TUBE))
    high = 2 * np.pi * 2000.0
    lateral = _named_block_frequencies(model, ("v", "w", "beta", "gamma"), high)
    unseen = _named_block_frequencies(model, ("u", "theta"), high)
    assert lateral.size >= 4 and unseen.size >= 2  # both blocks have modes in the range
    gap = np.abs(np.log(unseen[:, None] / lateral[None, :])).min()
    assert gap > 1e-4  # the blocks' frequencies are distinct: a point at one is no point at the other
    (first, *_) = bearing_loops(model, frequency_range=(1.0, 2000.0), n_points=20, poles=np.zeros(0))
    grid = 2 * np.pi * first.frequencies

    def has(points) -> np.ndarray:
        return np.array([np.min(np.abs(grid / w - 1.0)) <= 1e-9 for w in points])

    assert has(lateral[lateral > 2 * np.pi]).all()
    assert not has(unseen).any()
