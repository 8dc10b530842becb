"""Coupling misalignment under an oblique load and a circular whirl, against statics.

Two tubes on pinned ends joined at x = a by a hinge of angular stiffness k (the same in both
bending planes), a force P at ξ < a: the span is statically determinate, so the hinge carries the
span's bending moment M = |P| ξ b/L (b = L − a) in the plane of the force, and the angle between
the two tube axes is M/k, whatever the plane (tests/test_segments.py checks one plane). Both
component angles add as a vector, α = √(Δβ² + Δγ²) = |P| ξ b/(L k).

A forward circular whirl of that bend (the force F (1, −i) of a rotating load, the convention of
:mod:`flexshaft.assembly.loads`) sweeps the same angle around a circle: the largest whirling
angle, the ellipse's major semi-axis, is M/k again; of several imbalance cases, the worst
one's. The Hermite beam is exact for statics of point loads at nodes: tolerance 1e-8 (the
hinge's round-off, as in tests/test_segments.py).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.misalignment import coupling_misalignment
from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import design_from_dict

A, B, K, XI = 0.8, 1.2, 100.0, 0.5
AL = {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0}


@pytest.fixture(scope="module")
def hinged():
    """Two aluminium tubes on pinned ends, a hinge at x = a; no operating loads."""
    length = A + B
    data = {
        "name": "hinged tubes",
        "materials": {"al": AL},
        "shaft": {
            "x_start": 0.0,
            "x_end": length,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": length, "stiffness": {"u": 0.0}}],
        "couplings": [
            {
                "name": "hinge",
                "x": A,
                "angular_stiffness": K,
                "axial_stiffness": "rigid",
                "torsional_stiffness": "rigid",
            }
        ],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 20},
    }
    return build_model(design_from_dict(data))


def _response(model, force_y: complex, force_z: complex) -> np.ndarray:
    """Static response to the force (0, F_y, F_z) at ξ (complex parts solved separately)."""

    def part(fy: float, fz: float) -> np.ndarray:
        return static_response(model, point_load(model, "shaft", (0.0, fy, fz), x=XI))

    return part(np.real(force_y), np.real(force_z)) + 1j * part(np.imag(force_y), np.imag(force_z))


def test_an_oblique_force_bends_the_hinge_by_the_vector_moment(hinged):
    """P = (30, 40) N: |P| = 50 N, α = 50 ξ b/(L k) and the moment k α."""
    q = _response(hinged, 30.0, 40.0).real
    result = coupling_misalignment(hinged, q)
    moment = 50.0 * XI * B / (A + B)
    assert result.static_angle[0] == pytest.approx(moment / K, rel=1e-8)
    assert result.static_moment[0] == pytest.approx(moment, rel=1e-8)


def test_a_circular_whirl_sweeps_the_static_angle_of_its_amplitude(hinged):
    """Forward whirl of amplitude F = 50 N: largest whirling angle F ξ b/(L k)."""
    F = 50.0
    result = coupling_misalignment(hinged, np.zeros(hinged.dofs.size), _response(hinged, F, -1j * F))
    assert result.dynamic_angle[0] == pytest.approx(F * XI * B / ((A + B) * K), rel=1e-8)
    assert result.static_angle[0] == 0.0


def test_the_whirling_angle_is_the_worst_imbalance_cases(hinged):
    """Two imbalance cases as the columns of the response at speed (forward whirls of 20 N and
    50 N, the larger second): the largest whirling angle is the worse case's, 50 ξ b/(L k)."""
    whirls = np.column_stack([_response(hinged, F, -1j * F) for F in (20.0, 50.0)])
    result = coupling_misalignment(hinged, np.zeros(hinged.dofs.size), whirls)
    assert result.dynamic_angle[0] == pytest.approx(50.0 * XI * B / ((A + B) * K), rel=1e-8)
