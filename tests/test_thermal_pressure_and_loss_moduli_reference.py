"""Thermal physics that the baseline cannot see (mutation hunt h45b): the air pressure in the
convection, per-element loss moduli in the heat, the peak rise with hot ends, and the flags of
the correlations' validity ranges.

References, typed here:

* Ideal-gas air (Incropera & DeWitt §2.2, kinetic theory): ρ = p/(R T); the dynamic viscosity
  μ, conductivity k and c_p do not depend on pressure, so ν = μ/ρ ∝ 1/p and Pr is unchanged.
  Hence at one temperature Re = V D/ν ∝ p, Re_ω = Ω D²/ν ∝ p, Gr = g β ΔT D³/ν² ∝ p² (Ra too),
  and Becker's Nu = 0.133 Re_ω^{2/3} Pr^{1/3} gives h(p)/h(p₀) = (p/p₀)^{2/3}. Ratios of two
  evaluations at p and p₀ = 101325 Pa: round-off only, 1e-12 relative asserted.
* Euler-Bernoulli shaft element (Przemieniecki; any FE text): axial stiffness E A/L on u,
  torsional G J/L on θ, A = π(D_o² − D_i²)/4, J = π(D_o⁴ − D_i⁴)/32; with complex moduli E*, G*
  (correspondence principle) the loss stiffness K'' holds Im(E*) A/L and Im(G*) J/L there.
  Built from four multiplications: 1e-12 relative asserted.
* Steady conduction without heat or convection between ends at T_a, T_b (Incropera §3.1):
  the straight line, so the peak is T_a when T_a > T_b and its rise over the air is T_a − T_∞
  (exact on any mesh, tests/test_shaft_conduction_exact_reference.py): 1e-9 K asserted.
* Validity ranges: Churchill & Bernstein (1977, J. Heat Transfer 99, 300, abstract): the
  equation is a lower bound "except possibly for Re Pr < 0.2" — the Péclet number, not Re, sets
  the range; Churchill & Chu (1975) for 1e-5 ≤ Ra_D, with Incropera's (Bergman et al.) upper
  limit Ra_D ≤ 1e12 (as quoted in the docstring of ``ht``'s
  ``Nu_horizontal_cylinder_Churchill_Chu``), which is past the laminar 1e9.

Well under 0.1 s in all (one 4-element model).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict
from flexshaft.thermal.correlations import churchill_bernstein_nusselt, churchill_chu_nusselt
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.heat import shaft_loss_matrices
from flexshaft.thermal.shaft import rotating_shaft_convection, solve_shaft_temperature
from flexshaft.thermal.tailboom import boom_heat_transfer_coefficient

P0 = 101325.0
P = 0.7 * P0  # about 3000 m altitude


def test_rotating_shaft_h_scales_with_pressure_to_the_two_thirds():
    h0, nu0 = rotating_shaft_convection(0.1, 600.0, 320.0, "becker", P0)
    h, nu = rotating_shaft_convection(0.1, 600.0, 320.0, "becker", P)
    assert h / h0 == pytest.approx((P / P0) ** (2.0 / 3.0), rel=1e-12)


@pytest.mark.parametrize("condition, exponent", [("hover", 1), ("parked", 2)])
def test_boom_reynolds_and_rayleigh_scale_with_pressure(condition, exponent):
    """Re ∝ p in hover, Ra ∝ p² parked, at one skin temperature and diameter."""
    at = {p: boom_heat_transfer_coefficient(330.0, 0.4, condition, ThermalEnvironment(air_pressure=p)) for p in (P0, P)}
    assert at[P][2] / at[P0][2] == pytest.approx((P / P0) ** exponent, rel=1e-12)


def test_loss_stiffness_takes_each_elements_own_youngs_and_shear_moduli():
    E, G, D_o, wall, length, n_el = 70e9, 26e9, 0.08, 0.004, 1.2, 4
    data = {
        "name": "aluminium tube",
        "materials": {"al": {"kind": "isotropic", "E": E, "G": G, "density": 2700.0, "loss_factor": 0.001}},
        "shaft": {
            "x_start": 0.0,
            "x_end": length,
            "outer_diameter": D_o,
            "wall_thickness": wall,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": length, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 1e3},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": n_el},
    }
    model = build_model(design_from_dict(data))
    eta_E = np.array([0.01, 0.02, 0.03, 0.04])
    eta_G = np.array([0.05, 0.07, 0.11, 0.13])  # distinct from eta_E: a swap shows
    Kpp = shaft_loss_matrices(model, E * (1 + 1j * eta_E), G * (1 + 1j * eta_G))
    d_i = D_o - 2 * wall
    area = math.pi * (D_o**2 - d_i**2) / 4
    polar = math.pi * (D_o**4 - d_i**4) / 32
    L = length / n_el
    np.testing.assert_allclose(Kpp[:, 0, 0], E * eta_E * area / L, rtol=1e-12)  # u: E'' A / L
    np.testing.assert_allclose(Kpp[:, 3, 3], G * eta_G * polar / L, rtol=1e-12)  # θ: G'' J / L


def test_peak_rise_is_over_the_air_not_over_the_hot_end():
    x = np.array([0.0, 0.2, 0.5, 0.9, 1.3])
    res = solve_shaft_temperature(x, np.zeros(4), 4.0, 2e-4, 0.25, 0.0, 300.0, (350.0, 320.0))
    assert res.peak_rise == pytest.approx(50.0, abs=1e-9)


def test_churchill_bernstein_range_is_on_the_peclet_number():
    assert not churchill_bernstein_nusselt(1.0, 0.1).in_range  # Re Pr = 0.1 < 0.2, though Re > 0.2
    assert churchill_bernstein_nusselt(0.5, 0.7).in_range  # Re Pr = 0.35


def test_churchill_chu_holds_into_the_turbulent_rayleigh_range():
    assert churchill_chu_nusselt(0.7, 1e10 / 0.7).in_range  # Ra = 1e10: turbulent, still valid
    assert not churchill_chu_nusselt(0.7, 2e12 / 0.7).in_range  # Ra = 2e12 > 1e12
