"""The heat model's element stiffness of a shear-deformable shaft (``shear_deformation = true``).

``flexshaft.thermal.heat.shaft_stiffness_matrices`` rebuilds each element with complex moduli
E* = E(1 + iη), G* = G(1 + iη) (its imaginary part is the loss stiffness K'' that makes the
heat). With shear deformation the element is a Timoshenko beam, whose cantilever tip
flexibility under an end force is exact for an element with end loads only:

    δ/P = L³/(3 E* I) + L/(κ G* A)

(bending plus shear, the correspondence principle for the complex moduli), with Cowper's shear
coefficient κ(ν, d_i/d_o) of a hollow circle (``flexshaft.elements.cowper_shear_coefficient``,
checked against ROSS's printed shear parameter in tests/test_timoshenko_shaft.py) at the
isotropic Poisson ratio ν = E/(2G) − 1 = 0.25 of this steel (E = 200 GPa, G = 80 GPa).

A thick tube (D_o = 100 mm, 20 mm wall) in 10 elements of 0.1 m, so the shear term
(4.3e-10 m/N, κ = 0.578) is as large as the bending one (3.9e-10 m/N); ν = 0.5 would give
κ = 0.598, 3.4 % less shear flexibility. The element's 2×2 tip block is inverted directly:
round-off 1e-12 relative; 1e-9 asserted.
"""

from __future__ import annotations

import math

import numpy as np

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict
from flexshaft.elements import TubeSection, cowper_shear_coefficient
from flexshaft.thermal.heat import shaft_stiffness_matrices

E, G, ETA = 200e9, 80e9, 0.02
D_O, WALL, LENGTH, N_EL = 0.1, 0.02, 1.0, 10


def test_tip_flexibility_of_each_element_is_bending_plus_shear():
    data = {
        "name": "thick steel tube",
        "materials": {"steel": {"kind": "isotropic", "E": E, "G": G, "density": 7850.0, "loss_factor": ETA}},
        "shaft": {
            "x_start": 0.0,
            "x_end": LENGTH,
            "outer_diameter": D_O,
            "wall_thickness": WALL,
            "material": "steel",
            "shear_deformation": True,
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": LENGTH, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 1e3},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": N_EL},
    }
    model = build_model(design_from_dict(data))
    K = shaft_stiffness_matrices(model)
    d_i = D_O - 2 * WALL
    inertia = math.pi * (D_O**4 - d_i**4) / 64
    area = math.pi * (D_O**2 - d_i**2) / 4
    kappa = cowper_shear_coefficient(TubeSection(D_O, d_i), E / (2 * G) - 1)
    L = LENGTH / N_EL
    Es, Gs = E * (1 + 1j * ETA), G * (1 + 1j * ETA)
    expected = L**3 / (3 * Es * inertia) + L / (kappa * Gs * area)
    tip = [7, 11]  # node 2's v and γ (the section's rotation about z), node 1 clamped ([u v w θ β γ] × 2)
    for element in K:
        flexibility = np.linalg.inv(element[np.ix_(tip, tip)])[0, 0]
        assert abs(flexibility - expected) < 1e-9 * abs(expected)
