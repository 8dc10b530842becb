"""A coupling's bending stiffness and its whirling angle as the angle *between* the two shafts.

* docs/design-reference.md, ``[[couplings]]``: ``angular_stiffness`` [N m/rad] is the bending
  stiffness between the flanges about each bending axis, ``torsional_stiffness`` the torsional
  one; the assembled :class:`~flexshaft.assembly.model.CouplingLink` must report the first as
  its ``angular_stiffness`` (here 100 N m/rad beside a torsional 7000 N m/rad).
* :mod:`flexshaft.analyses.misalignment`: the misalignment angle is the angle between the two
  shaft axes, α = √((β_b − β_a)² + (γ_b − γ_a)²). A whirl is written by hand on the two nodes of
  the coupling: the forward shaft's slope (β, γ) = (1, −i) mrad, the aft one's (3, −3i) mrad
  (forward circular whirls). Their difference (2, −2i) mrad sweeps a circle of radius 2 mrad:
  the largest whirling angle is 2 mrad (the aft slope alone would read 3 mrad). Both sides
  with the same slope whirl together: no angle.

Tolerance 1e-12 rad (three subtractions and a square root of numbers of order 1e-3).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.misalignment import coupling_misalignment
from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict

AL = {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0}


@pytest.fixture(scope="module")
def hinged():
    data = {
        "name": "hinged tubes",
        "materials": {"al": AL},
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": 2.0, "stiffness": {"u": 0.0}}],
        "couplings": [
            {
                "name": "hinge",
                "x": 0.8,
                "angular_stiffness": 100.0,
                "axial_stiffness": "rigid",
                "torsional_stiffness": 7000.0,
            }
        ],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 4},
    }
    return build_model(design_from_dict(data))


def test_the_link_reports_the_bending_stiffness_of_the_design(hinged):
    (link,) = hinged.couplings
    assert link.angular_stiffness == 100.0


def _whirl(model, slope_a, slope_b) -> np.ndarray:
    (c,) = model.couplings
    dm = model.dofs
    d = np.zeros(dm.size, dtype=complex)
    for node, (beta, gamma) in ((c.node_a, slope_a), (c.node_b, slope_b)):
        d[dm.shaft(node, "beta")], d[dm.shaft(node, "gamma")] = beta, gamma
    return d


def test_the_whirling_angle_is_the_relative_slope(hinged):
    static = np.zeros(hinged.dofs.size)
    found = coupling_misalignment(hinged, static, _whirl(hinged, (1e-3, -1e-3j), (3e-3, -3e-3j)))
    assert found.dynamic_angle[0] == pytest.approx(2e-3, abs=1e-12)
    together = coupling_misalignment(hinged, static, _whirl(hinged, (2e-3, -2e-3j), (2e-3, -2e-3j)))
    assert together.dynamic_angle[0] == pytest.approx(0.0, abs=1e-12)
