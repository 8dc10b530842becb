"""The loads and conditions the recipe of one operating point hands to its checks
(:func:`flexshaft.verdict.operating_point.analyse_point`), each against a closed form or a
result known by construction. Written for the wiring mutations of scripts/mutations.toml
(``point-*``) that the suite did not catch: every analysis right, the recipe wrong.

* **The static deflection carries the drive torque** (point-static-without-torque). The steady
  torque T = P/Ω twists a uniform tube at the rate θ' = T/(G J), J = π(D_o⁴ − D_i⁴)/32
  (Saint-Venant torsion of a circular tube; Timoshenko & Goodier, *Theory of Elasticity*, §
  on circular shafts). The elements' linear twist shape functions are exact for a constant
  torque, so the nodal twists agree with it to the static solve's round-off.
* **The metal segments see the peak torque** (point-metal-without-torque-factor). The mean
  shear stress of an aluminium tube under the steady torque times the torsional response's
  factor is τ_m = factor · T (D_o/2)/J at its outer fibre (same closed form); the factor itself
  is checked against the damped one-DOF closed form in tests/test_torsional.py.
* **The strength is that of the worst imbalance placement** (point-best-imbalance-case). With
  ``imbalance_placement = "worst"`` the bays' imbalance makes several load cases (the bays in
  phase and in opposition); the point's static + imbalance safety factor is the smallest of
  them, each computed by :func:`flexshaft.analyses.shaft_strength.shaft_safety_factor`
  (verified in tests/test_ply_strength_reference.py and tests/test_strength.py) on its own
  response column.
* **The thermal residual stress is at the point's material temperature**
  (point-residual-at-ambient). An envelope point's conditions name the shaft's material
  temperature; the ply check must use it, not the design's ambient air temperature.

Coarse meshes (18 shaft, 12 boom elements) and the smallest grids a resolution accepts: the
static twist is exact at any mesh and none of these quantities reads the grids (CPU budget,
issue 23).
"""

from __future__ import annotations

import math

import numpy as np
from conftest import SMALLEST

from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.design import embedded_design, tuned_design, with_overrides
from flexshaft.thermal.envelope import PointConditions
from flexshaft.verdict.operating_point import analyse_point

COARSE = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}


def _polar_moment(outer: float, inner: float) -> float:
    return math.pi * (outer**4 - inner**4) / 32.0


def test_the_static_deflection_twists_the_shaft_by_the_steady_torque():
    """Twist rate between consecutive shaft nodes of the tuned design's one-piece tube, against
    T/(G J) with T = P/Ω. Round-off bound: the static solve's relative error is about the
    stiffness matrix's condition number (~1e8 for this mesh, tailboom and bearings included)
    times 1e-16, far below the 1e-6 asserted; dropping the torque leaves no twist at all. The
    sense of the drive torque is the model's convention: either sign is accepted, the same for
    every element."""
    p = analyse_point(with_overrides(tuned_design(), COARSE), SMALLEST, detail=False)
    model = p.model
    (segment,) = model.segments
    tube = segment.properties
    expected = (model.power / model.speed) / (
        tube.shear_modulus.real * _polar_moment(tube.outer_diameter, tube.inner_diameter)
    )
    x = model.dofs.shaft_x
    twist = np.real(model.dofs.values(p.static_displacement, "shaft", "theta"))
    rate = np.diff(twist) / np.diff(x)
    assert expected > 0 and np.all(np.abs(rate) > 0)
    sign = np.sign(rate[0])
    np.testing.assert_allclose(sign * rate, expected, rtol=1e-6)


def test_the_metal_segments_mean_shear_is_the_peak_torques():
    """The segmented ``current`` driveline (aluminium tubes and couplings) with a light tail rotor
    (0.1 kg m² instead of 17: the 1/rev and 4/rev torque oscillation reaches the shaft, torque
    factor ~1.22). Every metal element's mean shear stress is factor · (P/Ω) (D_o/2)/J of its
    tube (exact: constant torque, linear twist elements; rel 1e-6 as above), while the steady
    torque alone is off by a fifth."""
    design = with_overrides(embedded_design("current"), {"tail_rotor.polar_inertia": 0.1})
    p = analyse_point(design, SMALLEST, detail=False)
    assert p.torque_factor > 1.15  # the test needs a factor well away from 1
    model, metal = p.model, p.metal_strength
    torque = p.torque_factor * model.power / model.speed
    tubes = {seg.name: seg.properties for seg in model.segments}
    assert metal.segment.size > 0 and set(metal.segment) <= set(tubes)
    for name, tau in zip(metal.segment, metal.tau_mean):
        tube = tubes[name]
        expected = torque * (tube.outer_diameter / 2) / _polar_moment(tube.outer_diameter, tube.inner_diameter)
        np.testing.assert_allclose(tau, expected, rtol=1e-6, err_msg=name)


def test_the_static_plus_imbalance_strength_is_the_worst_placements(monkeypatch):
    """The point's static + imbalance ply safety factor is the smallest of the placements'
    (the results of :func:`~flexshaft.analyses.shaft_strength.shaft_safety_factor` on each
    column of the response at speed, recorded as the recipe computes them), and the two differ,
    so that taking the larger would be seen."""
    from flexshaft.verdict import operating_point

    totals = []

    def recorded(model, parts, dynamic=None, **options):
        result = shaft_safety_factor(model, parts, dynamic, **options)
        if dynamic is not None:
            totals.append(result.safety_factor)
        return result

    monkeypatch.setattr(operating_point, "shaft_safety_factor", recorded)
    # the in/anti-phase patterns as load cases, and an imbalance 50x the design's (a poorly
    # balanced shaft) so that the placements' safety factors differ by more than round-off
    worst = {**COARSE, "loads.imbalance_placement": "worst", "loads.eccentricity": 9.1e-4}
    p = analyse_point(with_overrides(tuned_design(), worst), SMALLEST, detail=False)
    assert p.imbalance_at_speed.shape[1] == len(totals) >= 2
    assert max(totals) - min(totals) > 1e-2 * min(totals)
    assert p.strength_total.safety_factor == min(totals)


def test_the_residual_stress_is_at_the_points_material_temperature():
    """Conditions whose material temperature (60 °C) differs from the design's ambient air (the
    tuned design's file): the ply check's residual temperature is the conditions', exactly."""
    design = with_overrides(tuned_design(), COARSE)
    ambient = design.thermal.ambient_temperature_c + 273.15
    material = ambient + 45.0
    conditions = PointConditions(point=None, ambient_temperature=ambient, material_temperature=material)  # type: ignore[arg-type]
    p = analyse_point(design, SMALLEST, conditions=conditions, detail=False)
    assert p.residual_temperature == material
