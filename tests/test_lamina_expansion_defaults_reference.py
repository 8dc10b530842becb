"""The default thermal expansion of a carbon-fibre ply along its fibres: slightly negative.

A design-file lamina that gives no ``alpha_L`` takes the package's default, which stands for a
carbon-fibre ply whose fibres dominate the axial expansion (the soft matrix adds nothing,
Schapery 1968). PAN carbon fibres contract along their axis when heated: the Toray T300 data
sheet (No. CFA-001, functional properties) gives CTE = −0.41 × 10⁻⁶ /°C; the T700S of the
default is quoted at −0.38 × 10⁻⁶ /°C in :mod:`flexshaft.design.materials` (that sheet not read
here). So the default must lie in (−1e-6, 0) 1/K, and it must reach the ply the laminate is built
from (the thermal residual stresses of :mod:`flexshaft.laminate` use it). A positive value (the
sign of a metal's or the matrix's) would be a different material. The sign is what is checked;
the bound 1e-6 leaves room for the fibre grades (T300 to T700S), not for a matrix value (~1e-4).
"""

from __future__ import annotations

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

TUBE_WITHOUT_EXPANSION_KEYS = """
name = "ply without expansion keys"
[materials.ply]
kind = "lamina"
density = 1600.0
E_L = 120.0e9
E_T = 8.0e9
G_LT = 4.0e9
nu_LT = 0.3
X_t = 2000.0e6
X_c = 1200.0e6
Y_t = 50.0e6
Y_c = 150.0e6
S = 70.0e6
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = 0.1
wall_thickness = 0.004
material = "ply"
layup = "(45/-45)s"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "stop"
kind = "contact"
x = 1.0
stiffness = {}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 2
"""


def test_default_fibre_expansion_is_that_of_carbon_fibre():
    design = loads_design(TUBE_WITHOUT_EXPANSION_KEYS)
    assert -1.0e-6 < design.materials["ply"].alpha_L < 0.0
    laminate = build_model(design).shaft.laminate
    assert laminate is not None
    assert laminate.lamina.alpha_L == design.materials["ply"].alpha_L
