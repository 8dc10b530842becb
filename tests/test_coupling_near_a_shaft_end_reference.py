"""A coupling station near a shaft end, against the mesh's merge tolerance and a hand sum of mass.

Rule (docs/segmented-driveline.md, "The model"): "two boundaries or couplings closer than the
tolerance, or a coupling closer than that to a shaft end, are refused (raise `shaft_elements`):
the shaft is always meshed to both its ends" (the tolerance: 5 % of an element). Each case below
is checked on physics as well: whatever happens to a coupling near an end, a model that is built
spans the whole shaft, so its axial rigid-body mass is the hand sum (a shaft meshed short of its
end, which a coupling swallowing the end station would give, misses it).

Reference numbers (derived here): a 2 m tube in 40 elements has 0.05 m elements, so the tolerance
is 0.05 × 0.05 = 2.5 mm. A coupling 2 mm from either end (0.8 tolerance) is refused; one 4 mm
from the aft end (1.6 tolerances) is accepted, and then the model still spans [0, 2] m: its
axial rigid-body mass rᵀ M r (r = 1 on every node's u) is the hand sum ρ A L + m_hub with
A = π (D_o² − D_i²)/4. The Hermite and linear shape functions reproduce a rigid translation
exactly, so the sum holds to rounding (about 40 element blocks of ~1e-16 relative each):
1e-12 relative is asserted; a shaft a few mm short misses it by about 1e-3 (2 mm: 8.0e-4).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, design_from_dict

RHO, D_O, WALL, LENGTH, ELEMENTS, HUB = 2700.0, 0.05, 0.002, 2.0, 40, 0.4
TOL = 0.05 * LENGTH / ELEMENTS  # 5 % of an element: 2.5 mm


def _design(x_coupling: float) -> dict:
    """An aluminium tube held axially at its fore end, on two stiff contact bearings at 0.5 and
    1.5 m (away from the ends, so a shortened mesh would still carry them), one rigid coupling."""
    return {
        "name": "coupling near an end",
        "materials": {"al": {"kind": "isotropic", "E": 70e9, "G": 26e9, "density": RHO, "loss_factor": 0.0}},
        "shaft": {
            "x_start": 0.0,
            "x_end": LENGTH,
            "outer_diameter": D_O,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "theta"],
            "fixed_end": [],
        },
        "bearings": [
            {"name": "fore", "kind": "contact", "x": 0.5, "stiffness": {"v": 1e7, "w": 1e7}},
            {"name": "aft", "kind": "contact", "x": 1.5, "stiffness": {"v": 1e7, "w": 1e7}},
        ],
        "couplings": [
            {
                "name": "j",
                "x": x_coupling,
                "mass": HUB,
                "angular_stiffness": "rigid",
                "axial_stiffness": "rigid",
                "torsional_stiffness": "rigid",
            }
        ],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": ELEMENTS},
    }


def _axial_mass(model) -> float:
    """rᵀ M r with r = 1 on every shaft node's u (the axial rigid-body mass)."""
    dm = model.dofs
    r = np.zeros(model.M.shape[0])
    r[[dm.shaft(node, "u") for node in range(dm.n_shaft_nodes)]] = 1.0
    return float(r @ (model.M @ r))


def _hand_mass() -> float:
    area = math.pi * (D_O**2 - (D_O - 2 * WALL) ** 2) / 4
    return RHO * area * LENGTH + HUB


@pytest.mark.parametrize("x_coupling", [0.8 * TOL, LENGTH - 0.8 * TOL])
def test_a_coupling_within_the_tolerance_of_a_shaft_end_is_refused(x_coupling):
    """0.8 tolerance from the fore or the aft end: refused, naming the mesh field and the station."""
    design = design_from_dict(_design(x_coupling))
    with pytest.raises(DesignError) as info:
        build_model(design)
    text = str(info.value)
    assert "mesh.shaft_elements" in text and f"x = {x_coupling:.6g} m" in text, text


@pytest.mark.parametrize("x_coupling", [0.8 * TOL, LENGTH - 0.8 * TOL])
def test_no_model_is_built_short_of_the_shaft_ends(x_coupling):
    """The physics half of the rule ("the shaft is always meshed to both its ends"): a model built
    from a coupling 0.8 tolerance from an end, if any, spans [0, L] and carries the whole tube's
    mass plus the hub's (module docstring's hand sum)."""
    try:
        model = build_model(design_from_dict(_design(x_coupling)))
    except DesignError:
        return
    assert (model.dofs.shaft_x[0], model.dofs.shaft_x[-1]) == (0.0, LENGTH)
    assert _axial_mass(model) == pytest.approx(_hand_mass(), rel=1e-12)


def test_a_coupling_just_outside_the_tolerance_keeps_the_whole_shaft():
    """1.6 tolerances from the aft end: built, the mesh ends at x_end and the axial rigid-body mass
    is ρ A L + the hub's mass (module docstring)."""
    x_coupling = LENGTH - 1.6 * TOL
    model = build_model(design_from_dict(_design(x_coupling)))
    dm = model.dofs
    assert dm.shaft_x[0] == 0.0 and dm.shaft_x[-1] == LENGTH
    (j,) = dm.shaft_joints
    assert dm.shaft_x[j] == dm.shaft_x[j + 1] == x_coupling
    assert _axial_mass(model) == pytest.approx(_hand_mass(), rel=1e-12)
