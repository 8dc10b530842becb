"""Rayleigh's cantilever-with-tip-mass frequency (flexshaft.validation.reference) against its limits.

The formula the VPCS sheet SDLL15/89 prints (code_aster V2.02.015 §2.1, as docs/validation.md
cites it): f1 = (1/2π) sqrt(3 E I / (L³ (m_c + 0.24 M))), M the tube's mass ρ A L. The only
validation case that evaluates it has L = 1 m, where the tube's mass and its mass per metre are
the same number; these tests take L ≠ 1 m and check the two limits derived here:

* m_c = 0 (no tip mass): f1 = (1/2π) sqrt(3/0.24) sqrt(EI/(ρA)) / L², Rayleigh's estimate of the
  Euler cantilever's first mode f1 = (1.87510407²/2π) sqrt(EI/(ρA)) / L² (β1 L = 1.87510407, the
  root of cos βL cosh βL = −1). sqrt(3/0.24) = 3.5355 against 1.8751² = 3.5160: Rayleigh's
  estimate is 0.55 % high (an upper bound, as every Rayleigh quotient is), so the test asks
  0.5 % < f_Rayleigh/f_exact − 1 < 0.6 %. The L⁻² law is checked over L = 0.5, 2 and 3 m: a mass
  read per metre instead of per tube changes f1 by sqrt(L), 41 % at L = 2 m.
* ρ → 0 (massless tube): f1 = (1/2π) sqrt(k/m_c), k = 3 E I / L³ the static tip stiffness of a
  cantilever (Roark, tip load on a cantilever: δ = P L³/(3 E I)), derived here.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.validation.reference import rayleigh_cantilever_tip_mass

BETA1_L = 1.87510407  # first root of cos(x) cosh(x) = -1 (cantilever), 9 digits


def tube(outer: float, wall: float) -> tuple[float, float]:
    """Area and second moment of area of a round tube, by hand: π(D²−d²)/4 and π(D⁴−d⁴)/64."""
    inner = outer - 2.0 * wall
    return math.pi * (outer**2 - inner**2) / 4.0, math.pi * (outer**4 - inner**4) / 64.0


@pytest.mark.parametrize("length", [0.5, 2.0, 3.0])
def test_without_tip_mass_is_rayleighs_estimate_of_the_euler_cantilever(length):
    """m_c = 0: f1 is 0.55 % above the exact Euler cantilever's first frequency at every length.

    The ratio sqrt(3/0.24)/1.87510407² − 1 = 0.5517 % is exact arithmetic on the formula, so the
    window 0.50-0.60 % only allows for the 9 digits of β1 L (1e-8 relative) and round-off.
    """
    outer, wall, modulus, density = 0.08, 0.006, 70.0e9, 2700.0
    area, inertia = tube(outer, wall)
    f = rayleigh_cantilever_tip_mass(
        length=length, outer_diameter=outer, wall_thickness=wall, modulus=modulus, density=density, tip_mass=0.0
    )
    exact = BETA1_L**2 / (2.0 * math.pi * length**2) * math.sqrt(modulus * inertia / (density * area))
    assert 0.005 < f / exact - 1.0 < 0.006


def test_massless_tube_is_a_spring_of_the_cantilever_tip_stiffness():
    """ρ → 0: f1 = sqrt(k/m_c)/2π with k = 3EI/L³, at L = 2.5 m, 10 kg at the tip.

    With ρ = 1e-9 kg/m³ the tube's 0.24 M is about 1e-12 of m_c, so rel 1e-9 is ample and far
    below the effect of any slip in E, I or L.
    """
    length, outer, wall, modulus, tip = 2.5, 0.05, 0.005, 210.0e9, 10.0
    _, inertia = tube(outer, wall)
    stiffness = 3.0 * modulus * inertia / length**3
    f = rayleigh_cantilever_tip_mass(
        length=length, outer_diameter=outer, wall_thickness=wall, modulus=modulus, density=1.0e-9, tip_mass=tip
    )
    assert f == pytest.approx(math.sqrt(stiffness / tip) / (2.0 * math.pi), rel=1e-9)
