"""The wall study's forced response (thesis figure 3.5) reaches the shaft's free aft end.

A steel tube (D_o = 0.1 m, t = 5 mm, L = 2 m, Timoshenko elements) on two contact bearings
(k = 1e8 N/m) at x = 0 and x = a = L/2, its aft half an unloaded overhang of length b = a,
with no active bearing: :func:`flexshaft.thesis.wall.forced_response` takes the largest shaft
orbit over the nodes of the imbalance response (``long_name`` "largest shaft orbit over the
nodes"). The imbalance ``e m Ω²`` (m = ρ A L the tube, one bay between the bearings, the
mid-bay placement) acts at a/2. Derived here, quasi-statically: the simply supported bay bends
with end slope θ = F a²/(16 EI); the unloaded overhang stays straight and swings against the
load, so its tip moves θ b = F a³/(16 EI), three times the mid-bay deflection F a³/(48 EI), the
other way; both bearings carry F/2 and yield F/(2k) with the load, a rigid translation. The
tip's orbit F a³/(16 EI) − F/(2k) is the largest of all the nodes; the node at 7L/8, the
largest without the tip, is 25 % smaller. Timoshenko shear leaves this exact: the bay is
statically determinate, so its shear strain moves the loaded bay but not the support's
rotation, and the overhang carries no shear. The speeds, 0.02 to 1.30 × 60 rev/min
(≤ 8.2 rad/s), stay far below the overhung tube's first bending mode (a few hundred rad/s):
the quasi-static error, the dynamic amplification 1 + (Ω/ω)², is below 1e-3 (4.8e-4 seen at
the top speed, 1.2e-4 at half of it: it grows as Ω²); 2e-3 asserted.
"""

from __future__ import annotations

import numpy as np

from flexshaft.design import loads_design
from flexshaft.thesis.wall import forced_response

E, RHO, DO, T, L, K = 210e9, 7800.0, 0.1, 0.005, 2.0, 1e8
ECC, RPM = 1e-4, 60.0

TEXT = f"""
name = "overhung tube"
[materials.steel]
kind = "isotropic"
E = {E}
G = 80e9
density = {RHO}
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {T}
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "fore"
kind = "contact"
x = 0.0
stiffness = {{ v = {K}, w = {K} }}
[[bearings]]
name = "mid"
kind = "contact"
x = {L / 2}
stiffness = {{ v = {K}, w = {K} }}
[operating]
speed_rpm = {RPM}
power = 0.0
[loads]
eccentricity = {ECC}
[mesh]
shaft_elements = 8
"""


def test_the_largest_orbit_is_the_overhangs_free_tip():
    di = DO - 2 * T
    area, inertia = np.pi / 4 * (DO**2 - di**2), np.pi / 64 * (DO**4 - di**4)
    a = L / 2
    out = forced_response(loads_design(TEXT), (T,), 3)
    speeds = out.coords["speed"].values
    force = ECC * RHO * area * L * speeds**2
    tip = force * a**3 / (16 * E * inertia) - force / (2 * K)
    np.testing.assert_allclose(out["shaft_peak"].values[0], tip, rtol=2e-3)
