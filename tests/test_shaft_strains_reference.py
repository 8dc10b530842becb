"""Wall strains of the shaft read from a prescribed displacement field, against calculus.

The strain recovery of the ply and metal checks evaluates, at both ends of every element, the
axial strain u', the bending curvatures v'' and w'' and the twist rate θ'. A field made of the
polynomials the element interpolates exactly,

    u = e x,  v = a x²,  w = b x²,  θ = k x,   with the node rotations γ = v' = 2 a x and
    β = −w' = −2 b x (the sign convention of :mod:`flexshaft.elements.shape`),

has u' = e, v'' = 2a, w'' = 2b and θ' = k everywhere (derived by differentiation). The linear
(u, θ) and Hermite cubic (v, w) functions reproduce these fields exactly on any mesh, so the
strains are exact to round-off (tolerance 1e-9 of the largest value); a, b are chosen with
different signs and sizes so that a curvature with the wrong sign or plane shows. Four
elements of unequal length (a bearing station at x = 0.7 m splits the mesh) keep it cheap.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.shaft_strength import shaft_strains
from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict

E_AX, A_V, B_W, K_TW = 3.0e-4, 0.02, -0.05, 0.7


@pytest.fixture(scope="module")
def tube():
    data = {
        "name": "tube",
        "materials": {"al": {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0}},
        "shaft": {
            "x_start": 0.3,
            "x_end": 1.8,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "mid", "kind": "contact", "x": 0.7, "stiffness": {"v": 1.0e6, "w": 1.0e6}}],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 4},
    }
    return build_model(design_from_dict(data))


def test_strains_of_a_quadratic_field_are_its_derivatives(tube):
    dm = tube.dofs
    x = np.asarray(dm.shaft_x, dtype=float)
    q = np.zeros(dm.size)
    fields = {
        "u": E_AX * x,
        "v": A_V * x**2,
        "w": B_W * x**2,
        "theta": K_TW * x,
        "gamma": 2 * A_V * x,
        "beta": -2 * B_W * x,
    }
    for field, values in fields.items():
        for node, value in enumerate(values):
            q[dm.shaft(node, field)] = value
    strains = shaft_strains(tube, q)
    assert np.ptp(np.diff(x)) > 0.01  # the bearing station makes the elements unequal
    tol = 1e-9 * max(abs(E_AX), abs(2 * A_V), abs(2 * B_W), abs(K_TW))
    assert strains.axial == pytest.approx(np.full(strains.axial.shape, E_AX), abs=tol)
    assert strains.curvature_v == pytest.approx(np.full(strains.curvature_v.shape, 2 * A_V), abs=tol)
    assert strains.curvature_w == pytest.approx(np.full(strains.curvature_w.shape, 2 * B_W), abs=tol)
    assert strains.twist == pytest.approx(np.full(strains.twist.shape, K_TW), abs=tol)
