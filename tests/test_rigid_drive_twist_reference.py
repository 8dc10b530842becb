"""A tail rotor on a rigid drive adds no DOF: its inertia sits on the shaft's aft twist.

Reference: docs/model.md (*Torsional ends and torsional dynamics*): "inertia J_r = J_tr/n² on a
twist DOF of its own, joined to the shaft's aft θ by the drive's springs in series [...]
Without drive springs J_r and c_r sit on the shaft's aft θ." So with neither
``input_stiffness`` nor ``hub_stiffness`` the model has no extra DOF, the torsional subsystem
(flexshaft.analyses.torsional.torsional_system) has exactly the shaft's free twist DOFs, and
its mass matrix is that of the same shaft without the rotor plus J_r = J_tr/n² on the aft
twist's diagonal entry (J_tr = 0.8 kg m², n = 2: J_r = 0.2 kg m²).

Tolerance: the rotor's entry is one assembled sum J_r + (the aft element's own polar
inertia term ρ J_p l_e/3 = 2.2e-3 kg m² for this steel tube), so the difference of the two
models' entries is J_r to a few ulp of 0.2: rel 1e-12; every other entry is assembled from the
same element blocks in the same order and is compared to abs 1e-15 of the largest entry. The shaft is the steel tube
of tests/test_torsional.py (8 elements): milliseconds.

Written for the mutation h82a-drive-twist-dof-for-rigid-rotor of scripts/mutations.toml (a
rigid-drive rotor given an empty twist DOF of its own).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import RHO_STEEL, model_of, shaft_text

from flexshaft.analyses.torsional import torsional_system

J_TR, RATIO = 0.8, 2.0


def test_a_rigid_drive_puts_the_rotor_inertia_on_the_aft_twist_without_a_dof():
    """Rigid drive: no extra DOF, the torsional system's DOFs are the shaft's free twists, and
    M gains J_tr/n² on the aft twist's diagonal only (module docstring)."""
    rotor_table = f"[tail_rotor]\nblades = 2\npolar_inertia = {J_TR}\ngearbox_ratio = {RATIO}\n"
    rotor = model_of(shaft_text(rotor_table, density=RHO_STEEL))
    plain = model_of(shaft_text(density=RHO_STEEL))
    dm = rotor.dofs
    assert dm.extra == ()
    aft = dm.shaft(-1, "theta")
    assert rotor.drive.rotor_dof == aft
    twists = np.intersect1d(dm.shaft(np.arange(dm.n_shaft_nodes), "theta"), dm.free)
    system, reference = torsional_system(rotor), torsional_system(plain)
    np.testing.assert_array_equal(system.dofs, twists)
    np.testing.assert_array_equal(reference.dofs, twists)
    added = system.M - reference.M
    k = int(np.flatnonzero(system.dofs == aft)[0])
    assert added[k, k] == pytest.approx(J_TR / RATIO**2, rel=1e-12)
    added[k, k] = 0.0
    assert np.abs(added).max() <= 1e-15 * np.abs(reference.M).max()
