"""The ply check's thermal residual stress at a given absolute temperature, against a cross-ply.

A [0/90]s tube of equal plies, free, cooled (or heated) by ΔT = T − T_sf from its stress-free
temperature T_sf: by the symmetry of the two ply families the laminate strains equally along x
and y, ε_x = ε_y = ε₀, and N_x = 0 reads (Q₁₁ + Q₂₂ + 2Q₁₂) ε₀ = ((Q₁₁ + Q₁₂) α_L + (Q₂₂ + Q₁₂) α_T) ΔT
(derived: the 0° ply gives σ_x = Q₁₁(ε₀ − α_L ΔT) + Q₁₂(ε₀ − α_T ΔT), the 90° ply
σ_x = Q₁₂(ε₀ − α_L ΔT) + Q₂₂(ε₀ − α_T ΔT), and the two have equal thickness). Every ply then
carries, in its material axes,

    σ₁ = Q₁₁ (ε₀ − α_L ΔT) + Q₁₂ (ε₀ − α_T ΔT),   σ₂ = Q₁₂ (ε₀ − α_L ΔT) + Q₂₂ (ε₀ − α_T ΔT),

with Q₁₁ = E_L/(1 − ν_LT ν_TL), Q₂₂ = E_T/(…), Q₁₂ = ν_LT E_T/(…), ν_TL = ν_LT E_T/E_L
(derived: the inverse of the plane-stress compliance [[1/E_L, −ν_LT/E_L], [−ν_LT/E_L, 1/E_T]]). The
temperature is absolute [K] and the design's stress-free temperature is in °C: at
T = T_sf + 273.15 K the plies are stress free (the check equals the one without residual),
and 80 K below it they carry the stresses above with ΔT = −80 K. The tube is bent by a
midspan force so that the safety factor is finite; the closed form is exact (tolerance 1e-9).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.response import static_response
from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import loads_design

E_L, E_T, NU_LT = 120.0e9, 8.0e9, 0.3
ALPHA_L, ALPHA_T = -0.5e-6, 40.0e-6
T_SF_C = 120.0
L, P = 1.5, 200.0

CROSS_PLY_TUBE = f"""
name = "cross-ply tube on pinned ends"
[materials.ply]
kind = "lamina"
density = 1600.0
E_L = {E_L}
E_T = {E_T}
G_LT = 4.0e9
nu_LT = {NU_LT}
X_t = 2000.0e6
X_c = 1200.0e6
Y_t = 50.0e6
Y_c = 150.0e6
S = 70.0e6
alpha_L = {ALPHA_L}
alpha_T = {ALPHA_T}
stress_free_temperature_c = {T_SF_C}
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = 0.1
wall_thickness = 0.004
material = "ply"
layup = "(0/90)s"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "stop"
kind = "contact"
x = {L}
stiffness = {{}}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 4
"""


@pytest.fixture(scope="module")
def bent_cross_ply():
    model = build_model(loads_design(CROSS_PLY_TUBE))
    return model, static_response(model, point_load(model, "shaft", (0.0, -P, 0.0), x=L / 2))


def _cross_ply_residual(delta_T: float) -> tuple[float, float]:
    """(σ₁, σ₂) [Pa] of every ply of the free [0/90]s laminate (module docstring)."""
    nu_TL = NU_LT * E_T / E_L
    d = 1.0 - NU_LT * nu_TL
    Q11, Q22, Q12 = E_L / d, E_T / d, NU_LT * E_T / d
    eps0 = ((Q11 + Q12) * ALPHA_L + (Q22 + Q12) * ALPHA_T) * delta_T / (Q11 + Q22 + 2 * Q12)
    mech_L, mech_T = eps0 - ALPHA_L * delta_T, eps0 - ALPHA_T * delta_T
    return Q11 * mech_L + Q12 * mech_T, Q12 * mech_L + Q22 * mech_T


def test_no_residual_stress_at_the_stress_free_temperature_in_kelvin(bent_cross_ply):
    model, q = bent_cross_ply
    at_stress_free = shaft_safety_factor(model, q, speed=0.0, temperature=T_SF_C + 273.15)
    without = shaft_safety_factor(model, q, speed=0.0, thermal_residual=False)
    assert at_stress_free.safety_factor == pytest.approx(without.safety_factor, rel=1e-9)
    assert "thermal" not in at_stress_free.stress_parts
    assert at_stress_free.temperature_change == pytest.approx(0.0, abs=1e-9)


def test_residual_stress_80_kelvin_below_the_stress_free_temperature(bent_cross_ply):
    model, q = bent_cross_ply
    result = shaft_safety_factor(model, q, speed=0.0, temperature=T_SF_C + 273.15 - 80.0)
    assert result.temperature_change == pytest.approx(-80.0, rel=1e-9)
    sigma1, sigma2, tau12 = result.stress_parts["thermal"]
    expected1, expected2 = _cross_ply_residual(-80.0)
    scale = np.hypot(expected1, expected2)
    assert sigma1 == pytest.approx(expected1, abs=1e-9 * scale)
    assert sigma2 == pytest.approx(expected2, abs=1e-9 * scale)
    assert tau12 == pytest.approx(0.0, abs=1e-9 * scale)
    # cooling puts the matrix-dominated transverse direction in tension (α_T > α_L)
    assert sigma2 > 0.0
