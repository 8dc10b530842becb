"""Shear deformation (``shear_deformation = true``): Cowper's coefficient and the exact
Timoshenko frequencies of a thick simply supported tube.

References:

* Cowper's (1966) shear coefficient of a hollow circle, as implemented by ROSS
  (petrobras/ross, ``ross/shaft_element.py``, ``shear_method_calc="cowper"``), read there:
  κ = 6(1 + ν)(1 + r²)² / [(7 + 6ν)(1 + r²)² + (20 + 12ν) r²], r = D_i/D_o. ROSS's docstring
  prints, for its steel (E = 2.11e11 Pa, G = 8.12e10 Pa, ν = E/(2G) − 1) and an element
  L = 0.5 m, D_i = 0.05 m, D_o = 0.1 m, the shear parameter φ = 12EI/(κGAL²) =
  0.1571268472906404 — an independent number that fixes κ. Its thin-walled limit r → 1,
  derived here, is 2(1 + ν)/(4 + 3ν).
* The simply supported Timoshenko beam (rotary inertia and shear): with w = W sin kx,
  ψ = Ψ cos kx, k = nπ/L (w = 0 and EIψ' = 0 at both ends), the equations
  κGA(w'' − ψ') = ρA ẅ and EIψ'' + κGA(w' − ψ) = ρI ψ̈ give the exact frequency equation
  (κGA k² − ρAω²)(EI k² + κGA − ρIω²) − (κGA k)² = 0, whose lower root is the bending
  frequency of mode n (solved here as a quadratic in ω²).

The tube is thick and short (D_o = 0.2 m, D_i = 0.1 m, L = 1 m): shear and rotary inertia
lower the first frequency by 7 % and the second by 21 % from Euler-Bernoulli, so a wrong κ
(or the Euler-Bernoulli element) is far outside the tolerance. The element converges at second
order in the mesh size (consistent mass); the test checks the order on 16 and 32 elements and
compares the Richardson extrapolation with the exact root at 2e-5 (the extrapolated error is
~2e-6, the next term of the expansion).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.design import loads_design
from flexshaft.elements.shaft import TubeSection, cowper_shear_coefficient

E, G, RHO = 210e9, 80e9, 7850.0
DO, DI, L = 0.2, 0.1, 1.0
NU = E / (2 * G) - 1  # 0.3125, isotropic
A = math.pi * (DO**2 - DI**2) / 4
I = math.pi * (DO**4 - DI**4) / 64


def cowper_hollow_circle(r: float, nu: float) -> float:
    """Cowper's hollow-circle κ, as ROSS writes it (module docstring)."""
    r2 = r * r
    r12 = (1 + r2) ** 2
    return 6 * r12 * (1 + nu) / (r12 * (7 + 6 * nu) + r2 * (20 + 12 * nu))


def test_cowper_coefficient_reproduces_the_ross_shear_parameter():
    E_ross, G_ross, L_ross, di, do = 2.11e11, 8.12e10, 0.5, 0.05, 0.1
    nu = E_ross / (2 * G_ross) - 1
    A_r, I_r = math.pi * (do**2 - di**2) / 4, math.pi * (do**4 - di**4) / 64
    kappa = cowper_shear_coefficient(TubeSection(do, di), nu)
    phi = 12 * E_ross * I_r / (G_ross * kappa * A_r * L_ross**2)
    assert phi == pytest.approx(0.1571268472906404, rel=1e-12)


@pytest.mark.parametrize("nu", [0.0, 0.25, 0.3125, 0.5])
def test_cowper_coefficient_of_hollow_thin_and_solid_circles(nu):
    for r in (0.0, 0.3, 0.5, 0.9):
        assert cowper_shear_coefficient(TubeSection(0.1, 0.1 * r), nu) == pytest.approx(
            cowper_hollow_circle(r, nu), rel=1e-12
        )
    # solid circle (r = 0): 6(1 + ν)/(7 + 6ν)
    assert cowper_shear_coefficient(TubeSection(0.1, 0.0), nu) == pytest.approx(6 * (1 + nu) / (7 + 6 * nu), rel=1e-12)
    # thin-walled limit: κ → 2(1 + ν)/(4 + 3ν) with an error O(t/D)
    thin = 2 * (1 + nu) / (4 + 3 * nu)
    for wall in (1e-3, 1e-4):
        kappa = cowper_shear_coefficient(TubeSection(0.1, 0.1 * (1 - 2 * wall)), nu)
        assert kappa == pytest.approx(thin, rel=10 * wall)
    # a thin tube carries about half its area in shear (κ ≈ 0.5), much less than a solid bar
    assert 0.49 < thin < 0.58


def exact_frequency(n: int, kappa: float) -> float:
    """Lower root ω [rad/s] of the simply supported Timoshenko frequency equation, mode n."""
    k = n * math.pi / L
    kGA = kappa * G * A
    a = RHO * A * RHO * I
    b = -(kGA * k**2 * RHO * I + RHO * A * (E * I * k**2 + kGA))
    c = kGA * k**2 * (E * I * k**2 + kGA) - (kGA * k) ** 2
    return math.sqrt((-b - math.sqrt(b * b - 4 * a * c)) / (2 * a))


def design_text(elements: int, shear: bool = True) -> str:
    return f"""
name = "thick simply supported tube"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G}
density = {RHO}
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
shear_deformation = {"true" if shear else "false"}
[[bearings]]
name = "none"
kind = "contact"
x = {L / 2}
stiffness = {{}}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = {elements}
"""


def bending_frequencies(elements: int, shear: bool = True) -> np.ndarray:
    """The first two bending frequencies [rad/s] (each a v/w pair) at rest."""
    model = fs.build_model(loads_design(design_text(elements, shear)))
    m = fs.modes(model, n_modes=10, damped=False)
    lateral = np.sort(np.abs(m.eigenvalues[m.kind == "lateral"]))
    pairs = lateral[:4].reshape(2, 2)
    assert pairs[:, 0] == pytest.approx(pairs[:, 1], rel=1e-9)  # axisymmetric: v and w planes agree
    return pairs[:, 0]


@pytest.fixture(scope="module")
def meshes():
    return {n: bending_frequencies(n) for n in (16, 32)}


def test_thick_tube_matches_the_exact_timoshenko_frequencies(meshes):
    kappa = cowper_hollow_circle(DI / DO, NU)
    exact = np.array([exact_frequency(1, kappa), exact_frequency(2, kappa)])
    coarse, fine = meshes[16], meshes[32]
    # second-order convergence from above (consistent mass): error ratio 4 within 5 %
    assert np.all(fine > exact) and np.all(coarse > fine)
    order = np.log2((coarse - exact) / (fine - exact))
    assert order == pytest.approx([2.0, 2.0], abs=0.1)
    richardson = (4 * fine - coarse) / 3
    assert richardson == pytest.approx(exact, rel=2e-5)


def test_shear_deformation_lowers_the_frequencies_as_the_closed_forms_say(meshes):
    # κ → ∞ in the frequency equation leaves the Rayleigh beam (rotary inertia only):
    # ω² = EI k⁴ / (ρA + ρI k²); the model without shear deformation keeps the rotary inertia.
    k = np.array([1.0, 2.0]) * math.pi / L
    rayleigh = np.sqrt(E * I * k**4 / (RHO * A + RHO * I * k**2))
    euler = k**2 * math.sqrt(E * I / (RHO * A))
    kappa = cowper_hollow_circle(DI / DO, NU)
    exact = np.array([exact_frequency(1, kappa), exact_frequency(2, kappa)])
    assert exact / euler == pytest.approx([0.929, 0.789], abs=0.002)  # the effect is large here
    assert exact / rayleigh == pytest.approx([0.944, 0.837], abs=0.002)  # mostly from shear
    no_shear = bending_frequencies(32, shear=False)
    # Hermite cubics with consistent mass converge as (kh)⁴: measured < 2e-5 at 32 elements
    assert no_shear == pytest.approx(rayleigh, rel=1e-4)
    assert np.all(no_shear > 1.05 * meshes[32])
