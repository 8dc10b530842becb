"""Tailboom skin balance and its convection against textbook formulas (mutation hunt h35d).

References, typed here independently of flexshaft.thermal.tailboom:

* energy balance per unit skin area (thesis eq. 2.55, Incropera & DeWitt §1.3 surface balance):
  alpha_s G s = eps sigma (T^4 - T_sky^4) + h (T - T_amb), G = S_c f cos(theta_s), with the
  solar absorptivity alpha_s and the infrared emissivity eps distinct properties (a white
  paint: alpha_s = 0.25, eps = 0.9); sigma = 5.670374419e-8 W/(m^2 K^4) (CODATA 2018);
* hover: cross-flow at the momentum-theory downwash V = sqrt(m g / (2 rho pi R^2)) (thesis
  eq. 2.56), Hilpert Nu_D = C Re_D^m Pr^(1/3), C = 0.027, m = 0.805 for 4e4 <= Re_D <= 4e5
  (Incropera & DeWitt Table 7.2), h = Nu_D k / D (the Nusselt number is on the diameter);
* parked: free convection from a horizontal cylinder, Churchill-Chu (Incropera & DeWitt
  eq. 9.34) Nu_D = {0.60 + 0.387 Ra^(1/6) / [1 + (0.559/Pr)^(9/16)]^(8/27)}^2,
  Ra = g beta |T - T_amb| D^3 / (nu alpha), beta = 1/T_film (ideal gas): the buoyant flow runs
  down a skin colder than the air (night sky) as it runs up a warmer one, with the same |dT|.

Air properties (flexshaft.thermal.air, tested against tables elsewhere) are taken at the film
temperature (T + T_amb)/2, the same source and film temperature as the code's, so the h typed
here differs from the code's only by rounding (the correlations in another order, ~1e-15).
Tolerances: the skin temperature is solved by Brent to 1e-10 K; the balance's slope in T is
4 eps sigma T^3 + h + ... < 100 W/(m^2 K), so at the reported T it closes to < 1e-8 W/m^2, under
1e-10 of the ~230 W/m^2 absorbed (1e-8 asserted: a wrong emissivity or h moves T by kelvins,
a residual of order 1e-2); the closed forms repeat the same floating-point arithmetic in another
order, 1e-10.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.thermal.air import air_properties
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.tailboom import boom_heat_transfer_coefficient, tailboom_temperature

SIGMA = 5.670374419e-8
G0 = 9.80665
PAINT = {"emissivity": 0.9, "solar_absorptivity": 0.25}


def churchill_chu(Ra: float, Pr: float) -> float:
    return (0.60 + 0.387 * Ra ** (1 / 6) / (1 + (0.559 / Pr) ** (9 / 16)) ** (8 / 27)) ** 2


def textbook_h(condition: str, T: float, D: float, env: ThermalEnvironment) -> float:
    """h [W/(m^2 K)] at skin temperature T from the formulas typed above (film properties)."""
    T_amb = env.ambient_temperature
    film = air_properties(0.5 * (T + T_amb), env.air_pressure)
    if condition == "hover":
        V = math.sqrt(env.rotorcraft_mass * G0 / (2 * env.air_density * math.pi * env.rotor_radius**2))
        Re = V * D / film.kinematic_viscosity
        assert 4e4 <= Re <= 4e5  # the Hilpert row typed above
        return 0.027 * Re**0.805 * film.prandtl ** (1 / 3) * film.conductivity / D
    Ra = G0 / film.temperature * abs(T - T_amb) * D**3 / (film.kinematic_viscosity * film.diffusivity)
    return churchill_chu(Ra, film.prandtl) * film.conductivity / D


@pytest.mark.parametrize("condition", ["hover", "parked"])
def test_skin_balance_with_distinct_absorptivity_and_emissivity(condition):
    """At the code's skin temperature, the sun absorbed with alpha_s = 0.25 equals the radiation
    emitted with eps = 0.9 plus the convection with the textbook h computed here (not the
    code's h): eq. 2.55 closes only at the right temperature."""
    env, D = ThermalEnvironment(**PAINT), 0.4
    r = tailboom_temperature(condition, D, env)
    T = r.temperature
    assert T > env.ambient_temperature  # sunlit: convection leaves the skin
    absorbed = 0.25 * env.solar_constant * env.solar_fraction * math.cos(env.solar_zenith) * env.solar_area_fraction
    radiated = 0.9 * SIGMA * (T**4 - env.sky_temperature**4)
    convected = textbook_h(condition, T, D, env) * (T - env.ambient_temperature)
    assert r.absorbed_solar == pytest.approx(absorbed, rel=1e-12)
    assert r.net_radiation == pytest.approx(radiated, rel=1e-10)
    assert r.convection == pytest.approx(convected, rel=1e-10)
    assert absorbed - radiated - convected == pytest.approx(0.0, abs=1e-8 * absorbed)


def test_hover_coefficient_is_hilpert_on_the_diameter():
    env, D, T = ThermalEnvironment(), 0.1, 320.0
    film = air_properties(0.5 * (T + env.ambient_temperature), env.air_pressure)
    V = math.sqrt(env.rotorcraft_mass * G0 / (2 * env.air_density * math.pi * env.rotor_radius**2))
    Re = V * D / film.kinematic_viscosity
    assert 4e4 <= Re <= 4e5  # the row of Table 7.2 typed above
    h = 0.027 * Re**0.805 * film.prandtl ** (1 / 3) * film.conductivity / D
    got, _, Re_got = boom_heat_transfer_coefficient(T, D, "hover", env)
    assert Re_got == pytest.approx(Re, rel=1e-10)
    assert got == pytest.approx(h, rel=1e-10)


@pytest.mark.parametrize("dT", [-15.0, 15.0])
def test_parked_free_convection_runs_both_ways(dT):
    env, D = ThermalEnvironment(), 0.4
    T = env.ambient_temperature + dT
    film = air_properties(0.5 * (T + env.ambient_temperature), env.air_pressure)
    Ra = G0 / film.temperature * abs(dT) * D**3 / (film.kinematic_viscosity * film.diffusivity)
    h = churchill_chu(Ra, film.prandtl) * film.conductivity / D
    got, _, Ra_got = boom_heat_transfer_coefficient(T, D, "parked", env)
    assert Ra_got == pytest.approx(Ra, rel=1e-10)
    assert got == pytest.approx(h, rel=1e-10)


def test_parked_skin_at_night_is_below_the_air_and_convects_from_it():
    """No sun: the skin radiates to a sky colder than the air and settles below the ambient,
    where the air heats it by free convection (the balance eps sigma (T^4 - T_sky^4) =
    h (T_amb - T) with the Churchill-Chu h of |T - T_amb|)."""
    env = ThermalEnvironment(solar_fraction=0.0, sky_temperature=250.0)
    r = tailboom_temperature("parked", 0.4, env)
    T, T_amb = r.temperature, env.ambient_temperature
    assert env.sky_temperature < T < T_amb
    film = air_properties(0.5 * (T + T_amb), env.air_pressure)
    Ra = G0 / film.temperature * (T_amb - T) * 0.4**3 / (film.kinematic_viscosity * film.diffusivity)
    h = churchill_chu(Ra, film.prandtl) * film.conductivity / 0.4
    assert env.emissivity * SIGMA * (T**4 - env.sky_temperature**4) == pytest.approx(h * (T_amb - T), rel=1e-8)
