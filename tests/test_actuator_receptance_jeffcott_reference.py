"""The structure's receptance at its magnetic bearing (:mod:`flexshaft.analyses.receptance`), closed form.

The Jeffcott rotor of tests/jeffcott_bearing.py with its bearing at the disk an active one: with
the actuator removed (what :func:`actuator_receptance` solves) it is the undamped Jeffcott rotor,
a disk m = 20 kg on a near-massless tube of k = 48 E I/L³. In complex coordinates its disk
responds to a force f as f/(k − mΩ²), in each plane alone (no gyroscopic coupling: the disk has
no inertia about its axes; the tube's mass, 0.1 kg/m³ × 7.07e-4 m² × 1 m = 7.1e-5 kg, is 3.5e-6
of the disk's). So, per unit actuator force,
the receptance S = B_a Z₀⁻¹ B_aᵀ = I/(k − mΩ²) (v then w), and under the forward imbalance
Q₁ = U (1, −i) at the disk, times Ω², the disk's v = U Ω²/(k − mΩ²) and w = −i v. The
docstring of :class:`ActuatorReceptance` orders the shaft rows "v DOFs of every node followed by
the w DOFs"; the magnet's k_s is handed on as given (2e5 N/m).

Speeds 0.3, 0.6 and 1.4 ω_n (away from the undamped resonance). Tolerance: the tube's mass and
rotary inertia, 3.5e-6 of the disk's, change the answers by about that: rtol 1e-4; the cross
terms below 1e-4 of the direct ones. The two rtol=1e-12 comparisons are wiring checks (the
same solution read through two outputs), not references. CPU: a few milliseconds.
"""

from __future__ import annotations

import numpy as np
from jeffcott_bearing import ACTIVE, KS, U, imbalance_vector, model_with
from rotors import K_SHAFT, M_DISK, WN

from flexshaft.analyses.receptance import actuator_receptance


def test_receptance_and_imbalance_response_without_the_actuator():
    model = model_with(ACTIVE)
    speeds = np.array([0.3, 0.6, 1.4]) * WN
    rec = actuator_receptance(model, speeds, imbalance_vector(model)[:, None])
    flexibility = 1.0 / (K_SHAFT - M_DISK * speeds**2)
    node = model.dofs.node_at("shaft", 0.5)
    n = model.dofs.n_shaft_nodes
    v, w = rec.shaft_free[:, node, 0], rec.shaft_free[:, n + node, 0]
    np.testing.assert_allclose(v, U * speeds**2 * flexibility, rtol=1e-4)
    np.testing.assert_allclose(w, -1j * U * speeds**2 * flexibility, rtol=1e-4)
    # wiring check, code against code: the actuator's rows read the same free response
    np.testing.assert_allclose(rec.actuator_free[:, :, 0], np.column_stack([v, w]), rtol=1e-12)
    for k in range(speeds.size):
        direct = np.diag(rec.receptance[k])
        np.testing.assert_allclose(direct, [flexibility[k]] * 2, rtol=1e-4)
        assert np.abs(rec.receptance[k] - np.diag(direct)).max() <= 1e-4 * abs(flexibility[k])
        # wiring check, code against code: the shaft's response to a unit actuator force, read
        # at the actuator's own DOFs, is the receptance
        np.testing.assert_allclose(rec.shaft_per_force[k, [node, n + node]], rec.receptance[k], rtol=1e-12)
    np.testing.assert_array_equal(rec.negative_stiffness, [KS])
