"""The steel shaft over a tapered aluminium tailboom that several bearing and load tests build on
(design text only; each test adds its own name and bearings): a 2 m steel tube, 80 × 3 mm, held
axially and in twist at its forward end, over an elliptical boom tapering from 0.25 × 0.18 m to
0.12 × 0.09 m semi-axes, 2 mm wall."""

from __future__ import annotations


def shaft_and_boom(boom_length: float) -> str:
    """The materials, shaft and tailboom tables of the design, for a boom of ``boom_length`` [m]."""
    return f"""[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800.0
[materials.al]
kind = "isotropic"
E = 70e9
G = 26e9
density = 2700.0
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.08
wall_thickness = 0.003
material = "steel"
fixed_start = ["u", "theta"]
[tailboom]
length = {boom_length}
root_semi_axes = [0.25, 0.18]
tip_semi_axes = [0.12, 0.09]
wall_thickness = 0.002
material = "al"
shaft_clearance = 0.05
"""
