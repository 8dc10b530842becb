"""Self-heating's model variant: the shaft's per-element moduli replace its uniform ones.

:func:`flexshaft.thermal.selfheating.model_with_shaft_moduli` gives the model whose shaft
elements carry the moduli E*_e (1 + iη), G*_e of each element's temperature. For a pinned tube
whose elements all get E* = E/2 (a matrix softened by warming), the midspan deflection under a
force P is the Euler-Bernoulli closed form P L³/(48 E* I) (the Hermite element is exact at a
loaded node: round-off, 1e-9), twice the cold tube's; the twist under an end torque T is
T L/(G* J) (linear twist is exact). Both are solved at rest (speed 0): spinning, the rotating-frame
loss would add a cross-coupled part and shrink the in-plane deflection by 1/(1 + η²). The loss
stiffness is Im of the same elements, η times their storage stiffness: half the cold tube's.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load, torque_load
from flexshaft.design import design_from_dict
from flexshaft.thermal.selfheating import model_with_shaft_moduli

E, G, ETA = 70.0e9, 26.0e9, 0.02
L, D_O, WALL, P, T = 2.0, 0.05, 0.002, 100.0, 50.0
INERTIA = math.pi * (D_O**4 - (D_O - 2 * WALL) ** 4) / 64


@pytest.fixture(scope="module")
def tube():
    data = {
        "name": "pinned tube",
        "materials": {"al": {"kind": "isotropic", "E": E, "G": G, "density": 2700.0, "loss_factor": ETA}},
        "shaft": {
            "x_start": 0.0,
            "x_end": L,
            "outer_diameter": D_O,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": L, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 10},
    }
    return build_model(design_from_dict(data))


def test_softened_elements_bend_and_twist_as_the_closed_forms_of_the_soft_tube(tube):
    """E* = E/2, G* = G/2 on every element: deflection P L³/(48 E* I), twist T L/(G* J)."""
    n = len(tube.dofs.shaft_element_nodes)
    soft = model_with_shaft_moduli(tube, np.full(n, E / 2 * (1 + 1j * ETA)), np.full(n, G / 2 * (1 + 1j * ETA)))
    middle = tube.dofs.node_at("shaft", L / 2)
    bend = static_response(soft, point_load(soft, "shaft", (0.0, P, 0.0), x=L / 2), speed=0.0)
    assert bend[soft.dofs.shaft(middle, "v")] == pytest.approx(P * L**3 / (48 * (E / 2) * INERTIA), rel=1e-9)
    twist = static_response(soft, torque_load(soft, T), speed=0.0)
    assert abs(twist[soft.dofs.shaft(-1, "theta")]) == pytest.approx(T * L / ((G / 2) * 2 * INERTIA), rel=1e-9)
    # the loss stiffness is η times the softened storage stiffness of the shaft elements
    cold_loss = tube.shaft_loss_stiffness.toarray()
    np.testing.assert_allclose(
        soft.shaft_loss_stiffness.toarray(), cold_loss / 2, rtol=0, atol=1e-12 * abs(cold_loss).max()
    )
