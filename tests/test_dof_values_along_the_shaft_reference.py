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

A second reference reads the last node where it matters: the simply supported beam's last
node has zero deflection, so a read that drops it is seen there only through the array's length.
The same tube clamped at the start (v, w and both slopes fixed, besides u and θ) and free at the
end, a static force P at the tip (the last node), deflects (Euler-Bernoulli, integrating
E I v'''' = 0 with v = v' = 0 at the clamp and v'' = 0, E I v''' = −P at the free end)

    v(x) = P x² (3 L − x) / (6 E I),

increasing along the shaft to its largest, P L³/(3 E I), at the last node. The design's
``shear_deformation`` defaults to false (flexshaft.design.components), so the elements are
Euler-Bernoulli and again exact at the nodes: measured 5.2e-13 of P L³/(3 E I) (round-off),
asserted to the same 1e-9; the last value read must be P L³/(3 E I) and the largest, and the
read must hold one value per station (a read one node short fails on the tip's value first).

CPU: two 8-element builds and two static solves, well under 0.1 s each. Written for
h101e-dofs-values-last-node-dropped of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np

# the simply supported tube and its assembled model
from rotors import DI, DO, E, L, jeffcott, jeffcott_text

from flexshaft.analyses import static_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

#: Midspan force [N] (any value: the problem is linear).
P = 1.0e3
#: Relative accuracy of the nodal deflections (round-off, measured 1.9e-14).
RTOL = 1e-9


#: E I of the tube [N m²].
EI = E * np.pi * (DO**4 - DI**4) / 64


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


def _cantilever_model():
    """The same tube clamped at x = 0 (v, w, β, γ fixed besides u, θ) and free at x = L."""
    text = jeffcott_text(0.0, 0.0).replace(
        'fixed_start = ["u", "v", "w", "theta"]', 'fixed_start = ["u", "v", "w", "theta", "beta", "gamma"]'
    )
    text = text.replace('fixed_end = ["v", "w"]', "fixed_end = []")
    return build_model(loads_design(text))


def test_a_cantilevers_tip_deflection_is_read_at_the_last_node():
    model = _cantilever_model()
    dm = model.dofs
    tip = dm.node_at("shaft", L)
    loads = np.zeros(dm.size)
    loads[dm.shaft(tip, "v")] = P
    loads[dm.shaft(tip, "w")] = P / 2
    q = static_response(model, loads, speed=0.0)
    x = dm.shaft_x
    assert x[-1] == L
    for field, force in (("v", P), ("w", P / 2)):
        values = dm.values(q, "shaft", field)
        tip_deflection = force * L**3 / (3 * EI)
        exact = force * x**2 * (3 * L - x) / (6 * EI)
        # the values station by station (a shorter read is compared on the stations it has)
        np.testing.assert_allclose(values[: x.size], exact[: values.size], rtol=0, atol=RTOL * tip_deflection)
        # the last value read is the tip's, P L³/(3 E I), and it is the largest
        assert abs(values[-1] - tip_deflection) <= RTOL * tip_deflection
        assert values.max() == values[-1]
        assert values.size == x.size
