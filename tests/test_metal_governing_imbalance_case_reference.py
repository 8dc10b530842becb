"""Metal segments: the imbalance case kept at a station is the one whose weaker check governs.

A pinned steel tube loaded at midspan by two synchronous imbalance cases (each whirl solved
statically as its shape; the Hermite beam element is exact at a loaded node):

* case A, a **backward** circular whirl under F_A: the material sees its bend M c/I at 2/rev,
  an alternating stress s_A = F_A L/4 · c/I with no mean bending;
* case B, a **forward** circular whirl under F_B = 3 F_A: frozen in the rotating material, a
  mean stress s_B = 3 s_A with no alternating part.

Derived here: a forward circular whirl at Ω has the curvature vector κ_v + iκ_w = κ e^{iΩt};
seen in the frame turning with the shaft it is κ e^{iΩt} · e^{−iΩt} = κ, a constant curvature,
so each fibre's bending stress is constant (a mean). A backward whirl κ e^{−iΩt} gives
κ e^{−iΩt} · e^{−iΩt} = κ e^{−2iΩt}: the fibre's stress alternates at 2/rev with zero mean.

With the mean hoop stress σ_θ = ρ Ω² r_m², the compressed fibre σ_x = −s in the plane-stress
von Mises form σ_x² − σ_x σ_θ + σ_θ² gives s² + s σ_θ + σ_θ² (the worse of the two fibres).
The distortion-energy forms of Budynas & Nisbett, *Shigley's Mechanical Engineering Design*,
10th ed., eqs. 7-7 and 7-16 (as the module quotes them, not read) then give, derived here for
these two states,

    n_f(A) = 1/(s_A/S_e + σ_θ/S_ut),   n_y(A) = S_y/√(s_A² + s_A σ_θ + σ_θ²),
    n_f(B) = S_ut/√(s_B² + s_B σ_θ + σ_θ²),   n_y(B) = S_y/√(s_B² + s_B σ_θ + σ_θ²).

The strengths (S_y, S_ut, S_e) = (300, 600, 150) MPa put the two cases on either side: A has
the smaller fatigue factor (about 6.9 against 9.2) and B the smaller yield factor (about 4.6
against 14), and B's yield factor is the smallest of all four. The physics catch: the station
must report n_y = n_y(B) and min(n_f, n_y) equal to the minimum over both cases and both
checks (the one that governs the verdict); a check that kept the fatigue-worst case A would
report n_y(A) ≈ 3 n_y(B) and miss the governing yield.

The further pins n_f = n_f(B), σ_m = s_B, σ_a = 0 check the module's documented rule, not
physics: the MetalStrength docstring reports the "stresses [Pa] of the worst imbalance case at
each end", i.e. one whole case per station (B's own stresses and fatigue factor, not A's
smaller n_f mixed in).

Tolerance 1e-9: the stresses are round-off exact (exact element at the loaded node), the
factors a few multiplications and one square root of them.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.metal_strength import metal_strength
from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import design_from_dict

STEEL = {
    "kind": "isotropic",
    "E": 200.0e9,
    "G": 77.0e9,
    "density": 7850.0,
    "yield_strength": 300e6,
    "ultimate_strength": 600e6,
    "fatigue_strength": 150e6,
}
L, D_O, WALL, F_A, RPM = 2.0, 0.05, 0.002, 150.0, 3000.0
INERTIA = math.pi * (D_O**4 - (D_O - 2 * WALL) ** 4) / 64
OMEGA = RPM * 2 * math.pi / 60


@pytest.fixture(scope="module")
def tube():
    """A 2 m steel tube on pinned ends at 3000 rpm, built from a design dict."""
    data = {
        "name": "steel tube",
        "materials": {"steel": STEEL},
        "shaft": {
            "x_start": 0.0,
            "x_end": L,
            "outer_diameter": D_O,
            "wall_thickness": WALL,
            "material": "steel",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": L, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": RPM, "power": 10e3},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 10},
    }
    return build_model(design_from_dict(data))


def _whirl(model, force: float, sense: float) -> np.ndarray:
    """Shape of the midspan force force·(1, sense·i): sense −1 forward, +1 backward whirl."""
    lateral_y = static_response(model, point_load(model, "shaft", (0.0, force, 0.0), x=L / 2))
    lateral_z = static_response(model, point_load(model, "shaft", (0.0, 0.0, force), x=L / 2))
    return lateral_y + sense * 1j * lateral_z


def test_the_case_whose_weaker_check_is_smallest_is_kept(tube):
    """Backward whirl A (fatigue-worst) and forward whirl B = 3A (yield-worst): n_y = n_y(B) and
    min(n_f, n_y) is the minimum over both cases (physics); n_f = n_f(B), σ_m = s_B, σ_a = 0
    check the MetalStrength docstring's rule, "stresses of the worst imbalance case at each end"
    (one whole case kept per station)."""
    dynamic = np.column_stack([_whirl(tube, F_A, 1.0), _whirl(tube, 3.0 * F_A, -1.0)])
    result = metal_strength(tube, np.zeros(tube.dofs.size), dynamic, buckling=False)

    s_a = F_A * L / 4 * (D_O / 2) / INERTIA
    s_b = 3.0 * s_a
    hoop = STEEL["density"] * OMEGA**2 * ((D_O - WALL) / 2) ** 2

    def von_mises(s):
        return math.sqrt(s * s + s * hoop + hoop * hoop)

    n_f_a = 1.0 / (s_a / STEEL["fatigue_strength"] + hoop / STEEL["ultimate_strength"])
    n_y_a = STEEL["yield_strength"] / von_mises(s_a)
    n_f_b = STEEL["ultimate_strength"] / von_mises(s_b)
    n_y_b = STEEL["yield_strength"] / von_mises(s_b)
    # the premise: the two checks' worst cases differ
    assert n_f_a < n_f_b and n_y_b < n_y_a and n_y_b < n_f_a

    middle = int(np.argmin(np.abs(result.x - L / 2)))
    e, end = np.unravel_index(middle, result.x.shape)
    # physics: the governing yield of case B and the minimum over all cases and checks
    assert result.yield_safety_factor[e, end] == pytest.approx(n_y_b, rel=1e-9)
    weaker = min(result.yield_safety_factor[e, end], result.fatigue_safety_factor[e, end])
    assert weaker == pytest.approx(min(n_f_a, n_y_a, n_f_b, n_y_b), rel=1e-9)
    # the module's documented rule (MetalStrength docstring): "stresses [Pa] of the worst
    # imbalance case at each end", one whole case per station, so B's own n_f and stresses
    assert result.fatigue_safety_factor[e, end] == pytest.approx(n_f_b, rel=1e-9)
    assert result.sigma_mean[e, end] == pytest.approx(s_b, rel=1e-9)
    assert abs(result.sigma_alternating[e, end]) <= 1e-9 * s_b
