"""A field read along the shaft at every node: a simply supported beam's static deflection (hunt h101e).

:meth:`~flexshaft.assembly.dofs.DofMap.values` gives ``field`` "at every node of ``component``"
(its docstring): the static deflection curve of the report's driveline figure and the largest
deflection of results.json are read with it, one value per station of ``DofMap.shaft_x``.

Reference, the uniform beam: the Jeffcott-like rotor of tests/rotors.py is a steel tube
(E = 210 GPa, D_o = 50 mm, D_i = 40 mm, L = 1 m, 8 Euler-Bernoulli elements) simply supported
at both ends (v, w fixed at both, rotations free). A static force P at midspan deflects it
(Euler-Bernoulli, any textbook on strength of materials, derived by integrating E I v'''' = 0
between the load and a support with v = v'' = 0 at the support and v' = 0 at midspan)

    v(x) = P x (3 L² − 4 x²) / (48 E I),   0 ≤ x ≤ L/2,   symmetric about L/2,

zero at both supports, P L³/(48 E I) at midspan. Cubic Hermite beam elements reproduce the
exact deflection at their nodes for loads at the nodes (the exact solution is cubic in each
element), so the nodal values are exact up to round-off: measured 1.9e-14 relative to the
midspan deflection; asserted to 1e-9 (the free stiffness matrix's condition number is 5.8e5,
so round-off, at most about 1e-10, stays below it). v and w are loaded differently (P and P/2) so that
each plane is read from its own DOFs.

CPU: one 8-element build and one static solve, well under 0.1 s. Written for
h101e-dofs-values-last-node-dropped of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np

# the simply supported tube and its assembled model
from rotors import DI, DO, E, L, jeffcott

from flexshaft.analyses import static_response

#: Midspan force [N] (any value: the problem is linear).
P = 1.0e3
#: Relative accuracy of the nodal deflections (round-off, measured 1.9e-14).
RTOL = 1e-9


def _simply_supported(x: np.ndarray, force: float) -> np.ndarray:
    ei = E * np.pi * (DO**4 - DI**4) / 64
    xi = np.minimum(x, L - x)  # symmetric about midspan
    return force * xi * (3 * L**2 - 4 * xi**2) / (48 * ei)


def test_the_deflection_is_read_at_every_station_of_the_shaft():
    model = jeffcott(0.0, 0.0)
    dm = model.dofs
    mid = dm.node_at("shaft", L / 2)
    loads = np.zeros(dm.size)
    loads[dm.shaft(mid, "v")] = P
    loads[dm.shaft(mid, "w")] = P / 2
    q = static_response(model, loads, speed=0.0)
    scale = P * L**3 / (48 * E * np.pi * (DO**4 - DI**4) / 64)
    for field, force in (("v", P), ("w", P / 2)):
        values = dm.values(q, "shaft", field)
        assert values.shape == dm.shaft_x.shape
        np.testing.assert_allclose(values, _simply_supported(dm.shaft_x, force), rtol=0, atol=RTOL * scale)
