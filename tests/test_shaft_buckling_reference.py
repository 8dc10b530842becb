"""The laminated shaft's torsional buckling check: its shell radius and its torque, in closed form.

A [0] ply tube whose transverse shear moduli are equal, G_13 = G_23 = G, has the transverse shear
stiffness A_44 = A_55 = k G t and A_45 = 0 at any ply angle (k = 5/6, Reissner 1945), so its
shear-crimping limit is T_crimp = 2π R² k G t in both senses (Allen 1969, ch. 8: N_xy = k G t;
:mod:`flexshaft.buckling.shear`), with R the mid-surface radius (D_o − t)/2 of the thin shell.
The transmitted torque is T = P/Ω (Ω in rad/s) and the safety factor T_cr/T in the weaker
sense. Tolerance: round-off (1e-12).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.analyses.shaft_buckling import shaft_buckling
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

L, D, WALL, G, RPM, POWER = 1.0, 0.1016, 0.003, 4.0e9, 4000.0, 150e3

TUBE = f"""
name = "[0] tube, transversely isotropic in shear"
[materials.ply]
kind = "lamina"
density = 1600.0
E_L = 120.0e9
E_T = 8.0e9
G_LT = {G}
G_13 = {G}
G_23 = {G}
nu_LT = 0.3
X_t = 2000.0e6
X_c = 1000.0e6
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
speed_rpm = {RPM}
power = {POWER}
[mesh]
shaft_elements = 4
"""


def test_crimping_at_the_mid_surface_radius_and_the_safety_factor_against_p_over_omega():
    """T_crimp = 2π ((D_o − t)/2)² (5/6) G t; T = P/Ω; safety factor min(T+, T−)/T."""
    result = shaft_buckling(build_model(loads_design(TUBE)), compare_classical=False)
    crimping = 2 * math.pi * ((D - WALL) / 2) ** 2 * (5 / 6) * G * WALL
    assert result.result.crimping_torque_positive == pytest.approx(crimping, rel=1e-12)
    assert result.result.crimping_torque_negative == pytest.approx(crimping, rel=1e-12)
    torque = POWER / (RPM * 2 * math.pi / 60)
    assert result.torque == pytest.approx(torque, rel=1e-12)
    critical = min(result.result.torque_positive, result.result.torque_negative)
    assert result.safety_factor == pytest.approx(critical / torque, rel=1e-12)
    # compare_classical=False: no classical shell solved, none reported (shaft_buckling's docstring)
    assert result.classical is None and "classical_critical_torque_Nm" not in result.to_dict()
