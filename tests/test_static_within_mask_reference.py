"""Reference: static_response on a mask of free DOFs (``within``) refuses a load outside it and
solves the loaded block exactly.

API contract (the static_response docstring): the solve on ``within`` is exact "when they are
whole blocks the stiffness does not couple to the rest and the loads are zero outside them"; a
load outside is refused by the guard's own contract (its message: "within must hold every loaded
DOF"; it would otherwise be dropped, its deflection silently zero).

The rotor is the Jeffcott rotor of tests/rotors.py at rest, no loss: its lateral DOFs are not
coupled to its axial ones (linear beam elements, no spin), so the mask "every free DOF but the
axial u" is such a block. A force F at the disk (midspan of the pinned tube) deflects it by
F L³/(48 E I) = F/k (derived here, the Euler–Bernoulli simply supported beam); the FE solution
of a cubic beam element is nodally exact for a point load at a node, so the tolerance is
round-off on a well-conditioned 40-DOF solve (1e-9 relative).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, disk_dofs, jeffcott

from flexshaft.analyses.response import static_response

F = 100.0


@pytest.fixture(scope="module")
def setup():
    model = jeffcott(0.0, 0.0)
    dm = model.dofs
    axial = dm.shaft(np.arange(dm.n_shaft_nodes), "u")
    within = ~np.isin(dm.free, axial)
    return model, within, axial


def test_a_load_inside_the_mask_deflects_the_disk_by_f_over_k(setup):
    """F on the disk's v: q_v = F/k, q_w = 0."""
    model, within, _ = setup
    v, w = disk_dofs(model)
    loads = np.zeros(model.dofs.size)
    loads[v] = F
    q = static_response(model, loads, 0.0, within=within)
    assert q[v] == pytest.approx(F / K_SHAFT, rel=1e-9)
    assert abs(q[w]) < 1e-9 * F / K_SHAFT


def test_a_load_outside_the_mask_is_refused_not_dropped(setup):
    """F on the disk's v and an axial force on one free u DOF (outside the mask, the other u
    DOFs unloaded): solving would drop the axial force (zero axial displacement where the bar
    stretches by F/(E A) per metre), so it is refused."""
    model, within, axial = setup
    v, _ = disk_dofs(model)
    free_axial = np.intersect1d(axial, model.dofs.free)
    loads = np.zeros(model.dofs.size)
    loads[v] = F
    loads[free_axial[-1]] = F
    with pytest.raises(ValueError, match="within must hold every loaded DOF"):
        static_response(model, loads, 0.0, within=within)
