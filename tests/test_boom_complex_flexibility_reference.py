"""The tailboom's complex stiffness as built: a uniform elliptical cantilever's tip flexibility in
both bending planes and in torsion, with the aluminium's loss factor on E and G.

Closed forms (Euler-Bernoulli cantilever under a tip force, Saint-Venant torsion under a tip
torque), with the correspondence principle E* = E(1 + iη), G* = G(1 + iη):

    v_tip = F L³ / (3 E* I_z),   w_tip = F L³ / (3 E* I_y),   θ_tip = T L / (G* J)

for a thin wall of thickness t on the mid-line ellipse y = a sin ψ (vertical semi-axis a),
z = b cos ψ (lateral b): I_z = t ∮ y² ds resists the vertical (v) bending, I_y = t ∮ z² ds the
lateral (w) one (docs/model.md; elements/boom.py), Bredt's J = 4 A_m² t / ∮ ds with
A_m = π a b. The three contour integrals are computed here by adaptive quadrature
(scipy.integrate.quad on ds = √(a² cos² ψ + b² sin² ψ) dψ), not by the package's trapezoidal sums.

The model's boom block is K + iK'' (``model.K`` and ``model.boom_loss_stiffness``) on the boom's
free DOFs; the bearings carry no stiffness, so the block is the boom's alone. Cubic Hermite
elements with a uniform section are exact for a tip force (the static deflection is a cubic),
linear twist elements exact for a tip torque: agreement to the quadratures (1e-13) and the
solve's round-off (the boom block's condition number is about 8e3): 1e-9 relative asserted.

Numbers: a = 0.2 m, b = 0.1 m (2:1, so the planes differ by a factor about 3), t = 2 mm,
L = 2 m, aluminium E = 70 GPa, G = 26 GPa, η = 0.03; F = 1 kN, T = 1 kN m.

Written for the mutation h35c-build-boom-bending-loss-dropped of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

A, B, T_WALL, L = 0.2, 0.1, 0.002, 2.0
E, G, ETA = 70e9, 26e9, 0.03

DESIGN = """
name = "uniform elliptical boom"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800.0
[materials.al]
kind = "isotropic"
E = 70e9
G = 26e9
density = 2700.0
loss_factor = 0.03
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.08
wall_thickness = 0.003
material = "steel"
fixed_start = ["u", "v", "w", "theta", "beta", "gamma"]
fixed_end = ["v", "w"]
[tailboom]
length = 2.0
root_semi_axes = [0.2, 0.1]
tip_semi_axes = [0.2, 0.1]
wall_thickness = 0.002
material = "al"
shaft_clearance = 0.05
[[bearings]]
name = "idle"
kind = "contact"
x = 1.0
stiffness = { v = 0.0 }
[operating]
speed_rpm = 1000.0
power = 0.0
[mesh]
shaft_elements = 4
boom_elements = 4
"""


def _contour(f) -> float:
    return quad(
        lambda p: f(p) * math.sqrt((A * math.cos(p)) ** 2 + (B * math.sin(p)) ** 2),
        0.0,
        2 * math.pi,
        epsabs=0.0,
        epsrel=1e-13,
        limit=200,
    )[0]


I_Z = T_WALL * _contour(lambda p: (A * math.sin(p)) ** 2)
I_Y = T_WALL * _contour(lambda p: (B * math.cos(p)) ** 2)
J = 4 * (math.pi * A * B) ** 2 * T_WALL / _contour(lambda p: 1.0)


@pytest.fixture(scope="module")
def tip_solve():
    model = build_model(loads_design(DESIGN))
    dm = model.dofs
    boom = np.intersect1d(dm.boom_dofs, dm.free)
    K = (model.K + 1j * model.boom_loss_stiffness).tocsr()[boom][:, boom].toarray()

    def solve(field, load):
        f = np.zeros(boom.size, dtype=complex)
        tip = int(np.flatnonzero(boom == dm.boom(-1, field))[0])
        f[tip] = load
        return np.linalg.solve(K, f)[tip]

    return solve


def test_vertical_bending_tip_flexibility_is_complex(tip_solve):
    expected = 1e3 * L**3 / (3 * E * (1 + 1j * ETA) * I_Z)
    assert tip_solve("v", 1e3) == pytest.approx(expected, rel=1e-9)


def test_lateral_bending_tip_flexibility_is_complex(tip_solve):
    expected = 1e3 * L**3 / (3 * E * (1 + 1j * ETA) * I_Y)
    assert tip_solve("w", 1e3) == pytest.approx(expected, rel=1e-9)


def test_torsion_tip_flexibility_is_complex(tip_solve):
    expected = 1e3 * L / (G * (1 + 1j * ETA) * J)
    assert tip_solve("theta", 1e3) == pytest.approx(expected, rel=1e-9)
