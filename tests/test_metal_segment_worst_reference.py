"""The weakest point of each metal segment on its own, checked against beam theory by hand.

A pinned aluminium tube of two segments, a = [0, 0.7] m and b = [0.7, 2] m (rigid coupling at
0.7 m), carries a static lateral force P at mid-span and the torque T = P_w/Ω of P_w = 10 kW at
3000 rpm; no imbalance. Derived here from statics: the pinned ends react P/2 each, so the bending
moment M(x) = P x/2 rises linearly up to mid-span. Segment a's largest moment is at its far end,
M = 0.7 P/2, and segment b's at mid-span, M = P L/4. On the spinning tube the static bending is
fully reversed, σ_a = M c/I, the torque gives the steady shear τ_m = T c/J (J = 2I) and the spin
the hoop stress ρ Ω² r_m² (r_m the mid-wall radius). The criteria are those of
docs/segmented-driveline.md (Budynas & Nisbett, Shigley 10th ed. §7-4, eqs. 7-7, 7-15, 7-16,
extended there with the hoop stress): DE-Goodman gives
n_f = 1/(σ_a/S_e + sqrt(σ_θ² + 3τ_m²)/S_ut) and the first-cycle von Mises yield
n_y = S_y/sqrt(σ_a² + σ_a σ_θ + σ_θ² + 3τ_m²). The sign of the σ_a σ_θ term: the von Mises
stress of the axial σ_x and the hoop σ_θ is sqrt(σ_x² − σ_x σ_θ + σ_θ² + 3τ²); the fully
reversed bending puts σ_x = +σ_a on one fibre and −σ_a on the opposite one, and the compressive
fibre σ_x = −σ_a against the tensile hoop stress σ_θ > 0 is the worse, giving + σ_a σ_θ (the
doc's "worse sign ... taken with the hoop stress", its (σ_m + σ_a)σ_θ with σ_m = 0).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.analyses.metal_strength import metal_strength
from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load, torque_load
from flexshaft.design import design_from_dict

AL = {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0, "loss_factor": 0.0}
STRENGTHS = {"yield_strength": 276e6, "ultimate_strength": 310e6, "fatigue_strength": 100e6}
D_O, WALL, L, JOINT, P, POWER, RPM = 0.05, 0.002, 2.0, 0.7, 200.0, 10e3, 3000.0


def _two_segment_tube() -> dict:
    rigid = {"angular_stiffness": "rigid", "axial_stiffness": "rigid", "torsional_stiffness": "rigid"}
    return {
        "name": "two-segment tube",
        "materials": {"al": {**AL, **STRENGTHS}},
        "shaft": {
            "x_start": 0.0,
            "x_end": L,
            "outer_diameter": D_O,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
            "segments": [{"name": "a", "x_start": 0.0, "x_end": JOINT}, {"name": "b", "x_start": JOINT, "x_end": L}],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": L, "stiffness": {"u": 0.0}}],
        "couplings": [{"name": "j", "x": JOINT, **rigid}],
        "disks": [],
        "operating": {"speed_rpm": RPM, "power": POWER},
        "loads": {"eccentricity": 0.0, "point": [{"name": "P", "on": "shaft", "x": L / 2, "force": [0.0, 0.0, P]}]},
        "mesh": {"shaft_elements": 20},
    }


def _hand_factors(moment: float) -> tuple[float, float]:
    """(n_f, n_y) at a section carrying the bending moment ``moment`` [N m] (module docstring)."""
    inertia = math.pi * (D_O**4 - (D_O - 2 * WALL) ** 4) / 64
    c = D_O / 2
    omega = RPM * 2 * math.pi / 60
    sigma_a = moment * c / inertia
    tau_m = POWER / omega * c / (2 * inertia)
    hoop = AL["density"] * omega**2 * ((D_O - WALL) / 2) ** 2
    n_f = 1 / (
        sigma_a / STRENGTHS["fatigue_strength"] + math.sqrt(hoop**2 + 3 * tau_m**2) / STRENGTHS["ultimate_strength"]
    )
    n_y = STRENGTHS["yield_strength"] / math.sqrt(sigma_a**2 + sigma_a * hoop + hoop**2 + 3 * tau_m**2)
    return n_f, n_y


def test_each_segments_worst_point_is_its_own_largest_moment():
    """Asked for segment a, the worst fatigue and yield point is a's far end (x = 0.7 m, M =
    0.7 P/2), not the tube's overall worst at mid-span in segment b (M = P L/4, a σ_a 1/0.7
    times larger, n_f 28 % smaller). The Hermite beam elements are exact for the cubic
    deflection between loaded nodes, so the end curvatures carry only round-off (measured
    2e-12 relative on the factors): tolerance 1e-8 relative leaves room for any BLAS kernel."""
    model = build_model(design_from_dict(_two_segment_tube()))
    q = static_response(model, external_static_load(model) + torque_load(model))
    result = metal_strength(model, q, buckling=False)
    for segment, station, moment in (("a", JOINT, P * JOINT / 2), ("b", L / 2, P * L / 4)):
        n_f, n_y = _hand_factors(moment)
        fatigue, yielding = result.worst("fatigue", segment), result.worst("yield", segment)
        assert fatigue["segment"] == segment
        assert fatigue["station"] == pytest.approx(station, rel=1e-12)
        assert fatigue["safety_factor"] == pytest.approx(n_f, rel=1e-8)
        assert yielding["station"] == pytest.approx(station, rel=1e-12)
        assert yielding["safety_factor"] == pytest.approx(n_y, rel=1e-8)
