"""The composite ply check on a unidirectional tube, against beam theory and the uniaxial strengths.

A [0] tube (one ply along the axis) under bending carries, on its outer wall, the fibre stress
σ₁ = ±M r_o/I and nothing else: N_y = 0 leaves σ₂ = 0 in a single ply (σ₂ = Q₁₂ε_x + Q₂₂ε_y = 0
is the condition itself), and then σ₁ = (Q₁₁ − Q₁₂²/Q₂₂) ε_x = E_L ε_x with ε_x = M r_o/(E_L I)
(the tube's bending modulus is E_L). Tsai-Wu under uniaxial fibre stress reaches the envelope
exactly at σ₁ = X_t or −X_c (thesis eq. 2.48-2.53, tested in tests/test_strength.py), so the
safety factor is X_c I/(M r_o) when X_c < X_t: the compressed fibre governs. The Hermite beam
element is exact at a loaded node: the tolerance 1e-9 is round-off.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.response import static_response
from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import loads_design

L, D, WALL, P = 2.0, 0.1016, 0.003, 300.0
X_T, X_C = 2000.0e6, 1000.0e6

UNIDIRECTIONAL_TUBE = f"""
name = "unidirectional [0] tube on pinned ends"
[materials.ply]
kind = "lamina"
density = 1600.0
E_L = 120.0e9
E_T = 8.0e9
G_LT = 4.0e9
nu_LT = 0.3
X_t = {X_T}
X_c = {X_C}
Y_t = 40.0e6
Y_c = 140.0e6
S = 60.0e6
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {D}
wall_thickness = {WALL}
material = "ply"
layup = "0"
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
shaft_elements = 10
"""


@pytest.fixture(scope="module")
def bent_tube():
    """The model and its static response to a midspan force P (moment P L/4 at midspan)."""
    model = build_model(loads_design(UNIDIRECTIONAL_TUBE))
    return model, static_response(model, point_load(model, "shaft", (0.0, -P, 0.0), x=L / 2))


def _fibre_stress(moment: float) -> float:
    """σ₁ = M r_o/I of the outer fibre [Pa]."""
    inertia = np.pi * (D**4 - (D - 2 * WALL) ** 4) / 64
    return moment * (D / 2) / inertia


def test_the_compressed_fibre_of_a_bent_unidirectional_tube_governs(bent_tube):
    """R = X_c/σ₁ (not X_t/σ₁: both extreme fibres are checked, the compressed one is weaker)."""
    model, q = bent_tube
    result = shaft_safety_factor(model, q, speed=0.0, thermal_residual=False)
    assert result.safety_factor == pytest.approx(X_C / _fibre_stress(P * L / 4), rel=1e-9)
    assert result.x == pytest.approx(L / 2)
    assert result.stresses[0] == pytest.approx(-_fibre_stress(P * L / 4), rel=1e-9)


def test_a_whirl_in_quadrature_adds_to_the_static_bend_a_quarter_turn_before_the_start(bent_tube):
    """Static bend q plus the imbalance amplitude i q/2 (the same shape, a quarter period
    ahead): Re(i q/2 e^{iφ}) = −(q/2) sin φ, so the bend peaks at 1.5 q at φ = 270° (on the
    72-phase grid), and R = X_c/(1.5 σ₁). A sweep of half a turn would see at most q."""
    model, q = bent_tube
    result = shaft_safety_factor(model, q, 0.5j * q, speed=0.0, thermal_residual=False)
    assert result.safety_factor == pytest.approx(X_C / (1.5 * _fibre_stress(P * L / 4)), rel=1e-9)
    assert result.phase_deg == pytest.approx(270.0)
