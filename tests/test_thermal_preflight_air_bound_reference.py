"""The thermal preflight refuses a shaft air (the boom's hover skin) above the air properties'
600 K, even when every film temperature of the boom's balance lies inside 200-600 K.

The rule (docs/limits.md, section 2: ``thermal_guards`` refuses "a tailboom skin or shaft air
outside the air properties' range"; the air is evaluated from 200 to 600 K). The boom's balance
keeps its *film* temperature (T + T_amb)/2 within 200-600 K, so with the hottest ambient the
schema allows (176 °C = 449.15 K) a hover skin up to 1200 − 449.15 = 750.85 K is solvable; the
shaft's convection is then evaluated with the skin itself as its air, which must be refused.

Worked by hand (derived here). The baseline's boom with ``[thermal]`` ambient 176 °C, sun
S = 1e4 W/m² (the schema's maximum) on the whole skin (f = 1, s = 1, overhead, α = ε = 1), sky
285 K, and a 1 kg rotorcraft under a 100 m rotor: the momentum-theory downwash (thesis eq. 2.56)
V = √(m g/(2ρπR²)) = √(9.80665/(2·1.225·π·1e4)) = 0.01129 m/s, a near-still air. The hover
balance per unit skin area (thesis eq. 2.55),

    r(T) = α S f s − ε σ (T⁴ − T_sky⁴) − h(T) (T − T_amb),

falls with T (both losses grow with T above T_amb), so the skin lies above 600 K exactly when
r(600 K) > 0. At 600 K, with the film at 524.575 K, the air's properties from the formulas
``flexshaft.thermal.air`` documents (Sutherland μ = 1.458e-6 T^1.5/(T + 110.4) = 2.759e-5 Pa s,
k = 2.64638e-3 T^1.5/(T + 245.4·10^(−12/T)) = 0.04198 W/(m K), ρ = p/(287.05 T) = 0.6729 kg/m³,
c_p = 1026.5 J/(kg K) extrapolated from 1014 at 400 K by 0.1 J/(kg K²)): ν = 4.100e-5 m²/s,
Pr = 0.6745; the boom's equivalent diameter D = P/π = 0.6816 m (Ramanujan's perimeter at the
mean semi-axes 0.37725, 0.30225 m, outer surface), Re = V D/ν = 187.7, Hilpert's
Nu = 0.683 Re^0.466 Pr^(1/3) = 6.87 (40 ≤ Re < 4000), h = Nu k/D = 0.423 W/(m² K). Then

    r(600 K) = 1e4 − 5.670374e-8 (600⁴ − 285⁴) − 0.423 · 150.85 = 1e4 − 6974.7 − 63.8 = 2961.5 W/m² > 0,

so the hover skin is above 600 K, and below (S/σ + T_sky⁴)^¼ = 654.0 K, where the radiation alone
balances the sun (convection only adds loss above the ambient): the balance has its root inside
the boom's bracket. The root of the hand balance is the skin the message must report, to the
1e-5 of its six printed digits (Hilpert's correlation is used at Pr = 0.6745, just below its
Pr ≥ 0.7, as the product does and flags; h barely matters, see below). The margin is wide: h would have
to be 20 W/(m² K), 47 times Hilpert's, to bring the skin down to 600 K, so no digit of the air
properties matters.

The lamina's temperature table is dropped so that the assumed matrix law, which only softens
the ply above its 20 °C reference (ν²E_T/E_L shrinks), is what the range check would see: with
the air check gone nothing else refuses the design. A few ms, no model built.
"""

from __future__ import annotations

import copy
import math

import pytest
from scipy.optimize import brentq

from flexshaft.design import design_from_dict, embedded_design
from flexshaft.thermal.preflight import thermal_guards

SIGMA = 5.670374e-8  # W/(m² K⁴), CODATA 2018 (exact in SI 2019)
T_AMB, T_SKY, SUN = 449.15, 285.0, 1e4
RADIATION_ONLY = (SUN / SIGMA + T_SKY**4) ** 0.25  # 654.0 K: radiation alone balances the sun


def hot_still_day(**thermal):
    data = copy.deepcopy(embedded_design("baseline").model_dump())
    data["thermal"].update(
        {
            "ambient_temperature_c": 176.0,
            "solar_constant": SUN,
            "solar_fraction": 1.0,
            "solar_area_fraction": 1.0,
            "emissivity": 1.0,
            "solar_absorptivity": 1.0,
            "rotorcraft_mass": 1.0,
            "rotor_radius": 100.0,
            **thermal,
        }
    )
    data["materials"]["t700_adiprene"]["temperature_table"] = None
    data["envelope"] = None  # the envelope's own points are judged by the verdict's preflight
    return design_from_dict(data)


def _hover_residual(T: float) -> float:
    """r(T) of the docstring, typed here with its hand-worked air properties at the film."""
    film = 0.5 * (T + T_AMB)
    mu = 1.458e-6 * film**1.5 / (film + 110.4)
    k = 2.64638e-3 * film**1.5 / (film + 245.4 * 10 ** (-12.0 / film))
    rho = 101325.0 / (287.05 * film)
    cp = 1014.0 + (film - 400.0) * 0.1
    nu, prandtl = mu / rho, mu * cp / k
    a, b = 0.5 * (0.5 + 0.25) + 0.00225, 0.5 * (0.4 + 0.2) + 0.00225
    g = ((a - b) / (a + b)) ** 2
    D = (a + b) * (1 + 3 * g / (10 + math.sqrt(4 - 3 * g)))
    V = math.sqrt(1.0 * 9.80665 / (2 * 1.225 * math.pi * 100.0**2))
    Re = V * D / nu
    assert 40.0 <= Re < 4000.0
    h = 0.683 * Re**0.466 * prandtl ** (1 / 3) * k / D
    return SUN - SIGMA * (T**4 - T_SKY**4) - h * (T - T_AMB)


def test_the_hand_balance_puts_the_hover_skin_between_600_and_654_K():
    assert _hover_residual(600.0) > 2900.0  # 2961.5 W/m² by hand
    assert _hover_residual(RADIATION_ONLY) < 0.0
    # the heat-transfer coefficient that would hold the skin at 600 K: 20 W/(m² K)
    assert (SUN - SIGMA * (600.0**4 - T_SKY**4)) / (600.0 - T_AMB) > 20.0


def test_a_hover_skin_above_600_K_is_refused_as_the_shaft_air():
    problems = thermal_guards(hot_still_day())
    assert [p.path for p in problems] == ["thermal"], problems
    assert "shaft's air" in problems[0].message and "200-600 K" in problems[0].message
    # the hover skin the message reports lies where the hand balance puts it
    reported = float(problems[0].message.split("would be ")[1].split(" K")[0])
    assert reported == pytest.approx(brentq(_hover_residual, 600.0, RADIATION_ONLY), rel=1e-5)


def test_the_same_sun_with_the_baseline_downwash_is_accepted():
    """The contrast: the baseline's 6838 kg under a 7.315 m rotor blows V = 12.8 m/s, h of tens of
    W/(m² K) (r(600 K) < 0 needs only h > 20), and the skin stays below 600 K: accepted."""
    assert thermal_guards(hot_still_day(rotorcraft_mass=6838.0, rotor_radius=7.315)) == []
