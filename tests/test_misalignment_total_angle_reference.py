"""The largest angle a coupling sees: the static bend plus the whirl's amplitude (circular whirl).

For a circular whirl the sum is exact; for an ellipse static + major semi-axis is an upper bound.

Two aluminium tubes on pinned ends joined at x = a by a hinge of angular stiffness k (the model
of tests/test_misalignment_reference.py): a force P at ξ < a bends the hinge by the span's
moment, α = |P| ξ b/(L k) (b = L − a; statics of the determinate span), in the plane of P.

Over one turn the angle between the tube axes is the vector α(t) = α_s + Re(α_d e^{iΩt}) (the
static bend plus the whirl, each a vector (Δβ, Δγ)). For a circular whirl of radius r the tip of
α(t) runs round a circle of radius r centred on α_s, so the largest |α(t)| is |α_s| + r
(the triangle inequality, reached where the circle meets the ray through α_s): here a static
P = (30, 40) N (|P| = 50 N) and a forward whirl of 20 N give (50 + 20) ξ b/(L k), not the
root-sum-square √(50² + 20²) ξ b/(L k). The same largest angle is found by brute force here,
sampling α(t) at 3600 phases from the responses' DOFs (no flexshaft post-processing).
Tolerance: the Hermite beam is exact for point loads at nodes, 1e-8 covers the hinge's
round-off (as tests/test_segments.py); the sampled maximum is within 1 − cos(π/3600) ≈ 4e-7.
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


def _static(model, fy: float, fz: float) -> np.ndarray:
    return static_response(model, point_load(model, "shaft", (0.0, fy, fz), x=XI))


def test_the_largest_angle_is_the_static_bend_plus_the_whirl_radius(hinged):
    static = _static(hinged, 30.0, 40.0)
    whirl = _static(hinged, 20.0, 0.0) + 1j * _static(hinged, 0.0, -20.0)  # F (1, −i): forward whirl
    result = coupling_misalignment(hinged, static, whirl)
    unit = XI * B / ((A + B) * K)  # angle per newton
    assert result.static_angle[0] == pytest.approx(50.0 * unit, rel=1e-8)
    assert result.dynamic_angle[0] == pytest.approx(20.0 * unit, rel=1e-8)
    assert result.total_angle[0] == pytest.approx(70.0 * unit, rel=1e-8)

    # brute force: the angle between the axes over one turn, from the DOFs themselves
    dm, c = hinged.dofs, hinged.couplings[0]

    def delta(q, f):
        return q[dm.shaft(c.node_b, f)] - q[dm.shaft(c.node_a, f)]

    phase = np.exp(1j * np.linspace(0.0, 2 * np.pi, 3600, endpoint=False))
    beta = delta(static, "beta") + np.real(delta(whirl, "beta") * phase)
    gamma = delta(static, "gamma") + np.real(delta(whirl, "gamma") * phase)
    assert result.total_angle[0] == pytest.approx(np.hypot(beta, gamma).max(), rel=1e-6)
