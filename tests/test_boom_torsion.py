"""Torsion of a uniform elliptical tailboom: Bredt's J, the wall's polar inertia and the first
torsional frequency of the cantilever, with and without a tip inertia.

References (derived here):

* thin-walled closed section (Bredt-Batho): J = 4 A_m² t / ∮ds, A_m = π a b the area enclosed
  by the mid-line, ∮ds = 4a E(1 − b²/a²) (complete elliptic integral of the second kind,
  scipy.special.ellipe);
* polar inertia per length of the wall: ρ t ∮ (y² + z²) ds (scipy quad);
* a uniform rod fixed at x = 0, free at x = L, with G J θ'' = ρ I_p θ̈: ω₁ = (π / 2L) √(GJ / ρI_p);
  with a tip inertia J_t the free end carries G J θ'(L) = J_t ω² θ(L), so with
  β = ω √(ρ I_p / GJ): β L tan(β L) = ρ I_p L / J_t (first root in (0, π/2)).

The model is built from a design (``[tailboom]`` with equal root and tip semi-axes, a short
clamped shaft, no bearing stiffness), so the path through ``build_model`` is the one checked.
The torsion mode is the one whose kinetic energy lies in the boom's twist DOFs (> 99.9 %): a
symmetric section and a centred tip inertia decouple it from bending. The linear torsion
elements converge at second order; 16 and 32 elements are extrapolated (Richardson) and compared
at 1e-6, well below a 1 % error of J or I_p and the 8 % of I_y alone.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.special import ellipe

import flexshaft as fs
from flexshaft.design import loads_design
from flexshaft.elements.boom import ellipse_section

E, G, RHO = 71e9, 27e9, 2800.0
LENGTH, A_AXIS, B_AXIS, T = 6.0, 0.3, 0.2, 0.003  # m; mid-line semi-axes (vertical, lateral)


def perimeter() -> float:
    return 4 * A_AXIS * ellipe(1 - (B_AXIS / A_AXIS) ** 2)


def bredt_J() -> float:
    return 4 * (math.pi * A_AXIS * B_AXIS) ** 2 * T / perimeter()


def polar_per_length() -> float:
    """ρ t ∮ (y² + z²) ds on y = a sin ψ, z = b cos ψ."""

    def f(p):
        return (A_AXIS**2 * math.sin(p) ** 2 + B_AXIS**2 * math.cos(p) ** 2) * math.hypot(
            A_AXIS * math.cos(p), B_AXIS * math.sin(p)
        )

    return RHO * T * quad(f, 0, 2 * math.pi, epsabs=0, epsrel=1e-13)[0]


def design_text(elements: int, tip_inertia: float | None) -> str:
    end = (
        ""
        if tip_inertia is None
        else f"""
[tailboom.end_mass]
mass = 1.0
offset = [0.0, 0.0, 0.0]
inertia = [{tip_inertia}, 0.0, 0.0]
"""
    )
    return f"""
name = "uniform elliptical boom"
[materials.al]
kind = "isotropic"
E = {E}
G = {G}
density = {RHO}
[shaft]
x_start = 0.0
x_end = 0.5
outer_diameter = 0.1
wall_thickness = 0.01
material = "al"
fixed_start = ["u", "v", "w", "theta", "beta", "gamma"]
[tailboom]
length = {LENGTH}
root_semi_axes = [{A_AXIS}, {B_AXIS}]
tip_semi_axes = [{A_AXIS}, {B_AXIS}]
wall_thickness = {T}
material = "al"
shaft_clearance = 0.05
{end}
[[bearings]]
name = "unloaded"
kind = "contact"
x = 0.0
stiffness = {{}}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 2
boom_elements = {elements}
"""


def first_torsion_frequency(elements: int, tip_inertia: float | None = None) -> float:
    model = fs.build_model(loads_design(design_text(elements, tip_inertia)))
    m = fs.modes(model, n_modes=12, damped=False)
    dm = model.dofs
    M = model.M.toarray()
    twist = dm.boom(np.arange(dm.n_boom_nodes), "theta")
    shares = []
    for k in range(m.shapes.shape[1]):
        phi = m.shapes[:, k].real
        shares.append(phi[twist] @ M[np.ix_(twist, twist)] @ phi[twist] / (phi @ M @ phi))
    torsion = [k for k in np.argsort(np.abs(m.eigenvalues)) if shares[k] > 0.999]
    assert torsion, shares
    return float(np.abs(m.eigenvalues[torsion[0]]))


def extrapolated(tip_inertia: float | None) -> float:
    coarse, fine = first_torsion_frequency(16, tip_inertia), first_torsion_frequency(32, tip_inertia)
    assert fine < coarse  # consistent mass: from above
    return (4 * fine - coarse) / 3


def test_bredt_torsion_constant_and_perimeter_of_the_ellipse():
    sec = ellipse_section(A_AXIS, B_AXIS, T)
    assert float(sec.perimeter) == pytest.approx(perimeter(), rel=1e-12)
    assert float(sec.torsion_constant) == pytest.approx(bredt_J(), rel=1e-12)
    # a circle (a = b = r): J = 2π r³ t, the thin-tube value
    circle = ellipse_section(0.25, 0.25, T)
    assert float(circle.torsion_constant) == pytest.approx(2 * math.pi * 0.25**3 * T, rel=1e-12)


def test_first_torsion_frequency_of_the_uniform_cantilever_boom():
    exact = math.pi / (2 * LENGTH) * math.sqrt(G * bredt_J() / polar_per_length())
    assert extrapolated(None) == pytest.approx(exact, rel=1e-6)


def test_first_torsion_frequency_with_a_tip_inertia():
    rod = polar_per_length() * LENGTH  # kg m², the boom's own twist inertia
    J_tip = 0.5 * rod
    ratio = rod / J_tip
    beta_L = brentq(lambda x: x * math.tan(x) - ratio, 1e-9, math.pi / 2 - 1e-12, xtol=1e-15)
    exact = beta_L / LENGTH * math.sqrt(G * bredt_J() / polar_per_length())
    assert extrapolated(J_tip) == pytest.approx(exact, rel=1e-6)
    # the tip inertia lowers the frequency well below the bare rod's
    assert exact < 0.7 * math.pi / (2 * LENGTH) * math.sqrt(G * bredt_J() / polar_per_length())
