"""A magnet's pole angle is read in degrees: k_i, k_s and f_sat at α = 1°, by closed form.

Reference, docs/magnetic-bearings.md (hand-written): the design-file key "`pole_angle` | deg |
22.5 | pole axis to force axis (8-pole stator)"; the magnet constant "`k = ¼ μ0 N² A_a cos α`";
"k_i = 4 k i_0 / g_0²,      k_s = 4 k i_0² / g_0³"; and the saturation force
"f_sat = B_sat² A_a cos α / μ0". The bearing's geometry is tests/test_amb.py's magnet (N = 200
turns, A_a = 8 cm², i_0 = 4.775 A, g_0 = 1 mm, B_sat = 1.2 T) with ``pole_angle = 1.0``: cos 1° =
0.99985 where cos(1 rad) = 0.540, so a degree read as a radian lowers every gain by a factor
1.85 while staying inside the pole angle's range [0, π/2) rad (it is caught by the numbers, not
by a range refusal). With μ0 = 4π·10⁻⁷ H/m, at α = 1°: k = 1.00516e-5 N m²/A², k_i = 191.98 N/A,
k_s = 9.1673e5 N/m, f_sat = 916.59 N (hand evaluation of the forms below).

The rotor: a stiff steel tube on two such bearings, two shaft elements (the gains do not depend
on the mesh). Tolerance 1e-12 relative: each value is a few products of doubles and one cosine.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

MU0 = 4.0e-7 * math.pi
TURNS, POLE_AREA, BIAS, GAP, B_SAT = 200.0, 8.0e-4, 4.775, 1.0e-3, 1.2
POLE_ANGLE_DEG = 1.0

BEARING = f"""
kind = "active"
kp = 1.0e4
coil_turns = {TURNS}
pole_area = {POLE_AREA}
bias_current = {BIAS}
air_gap = {GAP}
saturation_flux_density = {B_SAT}
pole_angle = {POLE_ANGLE_DEG}
"""

DESIGN = f"""
name = "stiff tube on two magnets with a 1 degree pole angle"
[materials.steel]
kind = "isotropic"
E = 2.1e11
G = 8.1e10
density = 7800.0
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = 0.1
wall_thickness = 0.01
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "amb_1"
x = 0.1
{BEARING}
[[bearings]]
name = "amb_2"
x = 0.9
{BEARING}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 2
"""


def test_magnet_gains_and_saturation_force_take_the_pole_angle_in_degrees():
    cos_alpha = math.cos(math.radians(POLE_ANGLE_DEG))
    k = 0.25 * MU0 * TURNS**2 * POLE_AREA * cos_alpha
    k_i = 4.0 * k * BIAS / GAP**2
    k_s = 4.0 * k * BIAS**2 / GAP**3
    f_sat = B_SAT**2 * POLE_AREA * cos_alpha / MU0
    assert (k_i, k_s, f_sat) == pytest.approx((191.98, 9.1673e5, 916.59), rel=1e-4)  # hand values
    for act in build_model(loads_design(DESIGN)).actuators:
        assert act.current_gain == pytest.approx(k_i, rel=1e-12)
        assert act.negative_stiffness == pytest.approx(k_s, rel=1e-12)
        assert act.saturation_force == pytest.approx(f_sat, rel=1e-12)
