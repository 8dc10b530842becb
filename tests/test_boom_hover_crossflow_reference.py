"""Hovering tailboom: the cross-flow Reynolds number and the chosen correlation, by hand.

References, typed here independently of flexshaft.thermal.tailboom:

* momentum-theory hover induced velocity at the disk (thesis eq. 2.56)
  V = √(m g / (2 ρ_air π R²)), derived here from T = W = 2 ρ A v_i² (actuator disk);
* cross-flow Reynolds number on the diameter, Re_D = V D / ν with ν = μ/ρ and the film's
  ideal-gas density ρ = p / (R T_f), R = 287.05 J/(kg K), at T_f = (T + T_amb)/2;
* Churchill & Bernstein (1977), as printed by the htcie correlation docs
  (alinbobolea.github.io/docs/htcie/correlations/external.html) and boardflare's Nu_cyl_CB:
  Nu_D = 0.3 + 0.62 Re^½ Pr^⅓ / [1 + (0.4/Pr)^⅔]^¼ · [1 + (Re/282000)^⅝]^⅘
  (boardflare's worked value, boardflare.com/tools/engineering/heat-transfer/conv-external/Nu_cyl_CB,
  Nu(6071, 0.7) = 40.6371, is checked below);
* skin balance (thesis eq. 2.55) α_s G s = εσ(T⁴ − T_sky⁴) + h (T − T_amb), h = Nu k / D.

The dynamic viscosity, conductivity and Prandtl number come from
:func:`flexshaft.thermal.air.air_properties` (tested against Incropera's table elsewhere); the
density and the kinematic viscosity are formed here. Tolerances: Re and Nu repeat the same
floating-point operations in another order (relative 1e-12 asked, ~1e-15 expected; a dynamic
viscosity in place of ν, a sea-level density or a far-wake velocity move Re by 10-100 %). The
skin temperature is Brent-solved to 1e-10 K and the balance's slope is < 100 W/(m² K), so
the balance closes to < 1e-8 W/m² of the ~900 W/m² absorbed (1e-10 relative asked; Hilpert's
h in place of Churchill-Bernstein's leaves ~1e-2).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.thermal.air import air_properties
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.tailboom import tailboom_temperatures

SIGMA = 5.670374419e-8  # W/(m^2 K^4), CODATA 2018
G0 = 9.80665  # m/s^2
R_AIR = 287.05  # J/(kg K)


def churchill_bernstein(Re: float, Pr: float) -> float:
    return 0.3 + 0.62 * Re**0.5 * Pr ** (1 / 3) / (1 + (0.4 / Pr) ** (2 / 3)) ** 0.25 * (
        1 + (Re / 282000.0) ** (5 / 8)
    ) ** (4 / 5)


def hover_reynolds(T: float, D: float, env: ThermalEnvironment) -> float:
    """Re_D = V D ρ_f / μ_f at skin temperature T [K]."""
    T_f = 0.5 * (T + env.ambient_temperature)
    rho = env.air_pressure / (R_AIR * T_f)
    V = math.sqrt(env.rotorcraft_mass * G0 / (2 * env.air_density * math.pi * env.rotor_radius**2))
    return V * D * rho / air_properties(T_f, env.air_pressure).viscosity


def test_typed_churchill_bernstein_reproduces_the_printed_example():
    """The typed form gives the printed Nu(6071, 0.7) = 40.6371 (6 figures)."""
    assert churchill_bernstein(6071.0, 0.7) == pytest.approx(40.6371, abs=1e-4)


@pytest.mark.parametrize("pressure", [101325.0, 70000.0])
def test_hover_reynolds_is_downwash_diameter_over_kinematic_viscosity(pressure):
    """The hover Re_D reported at the solved skin temperature is V D ρ_f/μ_f with the disk
    induced velocity and the ideal-gas film density (at sea level and at 70 kPa, where ρ_f is
    ~30 % lower and a fixed density would show)."""
    env, D = ThermalEnvironment(air_pressure=pressure), 0.45
    r = tailboom_temperatures(D, env)["hover"]
    assert r.dimensionless == pytest.approx(hover_reynolds(r.temperature, D, env), rel=1e-12)


def test_tailboom_temperatures_forward_the_chosen_correlation():
    """With method="churchill_bernstein", the hover Nusselt number is Churchill-Bernstein's at
    the hand Re_D and the film Pr, and the hover skin closes eq. 2.55 with that h; the parked
    skin does not depend on the forced-convection choice, by the documented rule
    (docs/thermal.md): `boom_convection` is the "hover correlation: Hilpert (thesis eq. 2.57) or
    `"churchill_bernstein"`", while "Parked: free convection, Churchill–Chu (eq. 2.59)"."""
    env, D = ThermalEnvironment(), 0.45
    both = tailboom_temperatures(D, env, "churchill_bernstein")
    hover = both["hover"]
    T, T_amb = hover.temperature, env.ambient_temperature
    film = air_properties(0.5 * (T + T_amb), env.air_pressure)
    nu = churchill_bernstein(hover_reynolds(T, D, env), film.prandtl)
    assert hover.nusselt.value == pytest.approx(nu, rel=1e-12)
    h = nu * film.conductivity / D
    absorbed = env.emissivity * env.solar_constant * env.solar_area_fraction  # α_s = ε, f = 1, θ = 0
    balance = absorbed - env.emissivity * SIGMA * (T**4 - env.sky_temperature**4) - h * (T - T_amb)
    assert balance == pytest.approx(0.0, abs=1e-10 * absorbed)
    parked_hilpert = tailboom_temperatures(D, env, "hilpert")["parked"]
    assert both["parked"].temperature == pytest.approx(parked_hilpert.temperature, rel=1e-14)
