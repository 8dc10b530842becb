"""A magnetic bearing's dynamic stiffness matrix and its current gain (flexshaft.assembly.model).

Reference: the force law of the :class:`~flexshaft.assembly.model.Actuator` docstring (thesis
eqs. 2.38-2.40 in the :mod:`flexshaft.assembly.model` docstring), worked by hand here. The magnet
pulls the shaft with ``f = k_s d_a + k_i i`` on each lateral direction, the coil current is
``i = −C(s) d_s`` (no amplifier lag), so the bearing carries ``−f = k_i C(s) d_s − k_s d_a``. With
``d_a = B_a q`` and ``d_s = B_s q`` the model's actuator dynamic stiffness is

    Z(s) = B_aᵀ (k_i C(s) B_s − k_s B_a).

A two-node DofMap (12 DOFs, no elements: the matrices are zero, only the bearing rows matter)
with the magnet on node 0 (``B_a`` picks node 0's v and w) and a PD law ``C(s) = K_p + s K_d``:

* collocated (``B_s = B_a``): ``Z[v0, v0] = Z[w0, w0] = k_i (K_p + s K_d) − k_s``, zero elsewhere;
* a remote sensor on node 1: ``Z[v0, v1] = Z[w0, w1] = k_i (K_p + s K_d)`` and
  ``Z[v0, v0] = Z[w0, w0] = −k_s``.

Numbers: ``k_i = 2 N/A``, ``K_p = 3e5 A/m``, ``K_d = 150 A s/m``, ``k_s = 4e5 N/m``, ``s = 200i``:
``k_i K_p − k_s = 2e5 N/m`` (half of ``k_s``, so that losing or flipping ``k_s`` is a factor
of 3 or 5 on the real part) and ``k_i K_d s = 6e4i N/m``. The entries are sums and products of
a few exact binary numbers with 0/1 rows (no LAPACK), so the relative tolerance 1e-12 only
covers the rounding of ``s K_d``; a lost ``k_s`` moves the real part by 200 %.

``current_gain`` (API contract: the Actuator's own check, "a finite number > 0 N/A", and
:func:`flexshaft.assembly.checks.check_magnet`'s docstring, "k_i in (0, 1e6] N/A", near line
174 of src/flexshaft/assembly/checks.py): the docstring's ``k_i [N/A]`` converts current to
force, and a bearing with ``k_i = 0`` makes no force for any current (a dead bearing, its law
silently zero), so the Actuator must refuse ``k_i <= 0``, while the default magnet stiffness
``k_s = 0`` is allowed.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from flexshaft.assembly.dofs import DofMap
from flexshaft.assembly.model import Actuator, BearingLink, Controller, Model, ShaftProperties

K_I, K_P, K_D, K_S = 2.0, 3e5, 150.0, 4e5
S = 200j
DOFS = DofMap(shaft_x=np.array([0.0, 1.0]), boom_x=np.zeros(0))
LAW = K_I * (K_P + S * K_D)  # k_i C(s) = 6e5 + 6e4i N/m


def link(node: int, name: str) -> BearingLink:
    """Rows (u, v, w, β, γ) of ``node`` relative to the ground."""
    cols = [DOFS.shaft(node, f) for f in ("u", "v", "w", "beta", "gamma")]
    rows = sp.csr_matrix((np.ones(5), (np.arange(5), cols)), shape=(5, DOFS.size))
    return BearingLink(name, "active", float(DOFS.shaft_x[node]), None, 0.0, rows)


def model(sensor: BearingLink | None) -> Model:
    actuator = Actuator(
        link(0, "amb"), Controller.pd(K_P, K_D), current_gain=K_I, negative_stiffness=K_S, sensor=sensor
    )
    zero = sp.csr_matrix((DOFS.size, DOFS.size))
    shaft = ShaftProperties(0.02, 0.0, 2e11, 8e10, 7800.0)
    return Model(DOFS, zero, zero, zero, zero, (actuator.link,), (actuator,), shaft, 0.0, 0.0)


def expected(entries: dict[tuple[tuple[int, str], tuple[int, str]], complex]) -> np.ndarray:
    Z = np.zeros((DOFS.size, DOFS.size), dtype=complex)
    for ((na, fa), (nb, fb)), value in entries.items():
        Z[DOFS.shaft(na, fa), DOFS.shaft(nb, fb)] = value
    return Z


def test_collocated_bearing_carries_its_law_less_the_magnet_stiffness():
    """Z = B_aᵀ (k_i C(s) − k_s) B_a: k_i (K_p + s K_d) − k_s on node 0's v and w."""
    Z = model(None).controller_matrix(S).toarray()
    ref = expected({((0, f), (0, f)): LAW - K_S for f in ("v", "w")})
    np.testing.assert_allclose(Z, ref, rtol=0, atol=1e-12 * abs(LAW))


def test_remote_sensor_bearing_splits_its_law_and_the_magnet_stiffness():
    """Z = B_aᵀ (k_i C(s) B_s − k_s B_a): the law couples node 0 to the sensed node 1, −k_s stays on node 0."""
    Z = model(link(1, "sensor")).controller_matrix(S).toarray()
    ref = expected({**{((0, f), (1, f)): LAW for f in ("v", "w")}, **{((0, f), (0, f)): -K_S for f in ("v", "w")}})
    np.testing.assert_allclose(Z, ref, rtol=0, atol=1e-12 * abs(LAW))


@pytest.mark.parametrize("current_gain", [0.0, -2.0, np.nan])
def test_an_actuator_without_a_positive_current_gain_is_refused(current_gain):
    """k_i <= 0 (or not finite) converts no current to force: refused, naming current_gain."""
    with pytest.raises(ValueError, match="current_gain"):
        Actuator(link(0, "amb"), Controller.pd(K_P, K_D), current_gain=current_gain)


def test_an_actuator_without_magnet_stiffness_is_accepted():
    """The default k_s = 0 (the thesis's ideal PD bearing) is a valid magnet."""
    actuator = Actuator(link(0, "amb"), Controller.pd(K_P, K_D), current_gain=K_I)
    assert actuator.negative_stiffness == 0.0
