"""Static deflection of a rotor on a PD magnetic bearing weaker than its magnet's negative stiffness.

The Jeffcott rotor of tests/jeffcott_bearing.py (a pinned-pinned tube, k = 48 E I/L³ at its
midspan disk) with a collocated PD magnetic bearing at the disk: statically the magnet adds
k_i k_p − k_s (:func:`~flexshaft.analyses.response.static_response`'s docstring: "a PD law: K_p;
the magnet's negative stiffness counts"). With k_i k_p = 100 × 1000 = 1e5 N/m below
k_s = 2e5 N/m the magnet is a net negative spring of −1e5 N/m, which the modal basis leaves out
of its basis stiffness (never negative) but the static problem must keep: a load P = 100 N at
the disk deflects it by P/(k + k_i k_p − k_s), not P/k (Euler-Bernoulli statics, exact on the
cubic elements under nodal loads; the tube stays far stiffer, k = 1.8e6 N/m). The bearing
carries (k_i k_p − k_s) x, negative: the shaft receives −(k_i k_p − k_s) x = +1e5 x (the magnet
pushes it outwards).

Tolerance: a sparse solve of a 5-node model (4 elements) with condition number ~1e5: rtol 1e-9. CPU: a few
milliseconds.
"""

from __future__ import annotations

import numpy as np
from jeffcott_bearing import disk, model_with
from rotors import K_SHAFT

from flexshaft.analyses.response import static_actuator_forces, static_response

KI, KP, KS, P = 100.0, 1000.0, 2.0e5, 100.0


def test_a_weak_pd_law_keeps_the_magnets_negative_stiffness_statically():
    model = model_with(f'kind = "active"\nkp = {KP}\nkd = 2.0\nks = {KS}\nki = {KI}')
    v, w = disk(model)
    loads = np.zeros(model.dofs.size)
    loads[v] = P
    q = static_response(model, loads)
    x = P / (K_SHAFT + KI * KP - KS)
    np.testing.assert_allclose(q[v], x, rtol=1e-9)
    assert abs(q[w]) <= 1e-12 * x
    carried = static_actuator_forces(model, loads)["b"]
    np.testing.assert_allclose(carried[0], (KI * KP - KS) * x, rtol=1e-9)
