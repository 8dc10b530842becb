"""Steady-state tailboom skin temperature (thesis §2.8.1, eqs. 2.55-2.59).

Energy balance per unit boom length, for a lumped, isothermal, thin aluminium skin:

    α_s G A_sun = ε σ (T⁴ − T_sky⁴) π D + h(T) (T − T_amb) π D

* absorbed sun: G = S_c f cos θ_s (eq. 2.58) on ``A_sun = s πD`` per unit length, with the
  sunlit share s = :attr:`ThermalEnvironment.solar_area_fraction` (1/π: the projected width D
  under an overhead sun; 0.5: the sunlit half; 1: the whole skin); α_s = ε unless given (the
  thesis lists ε only);
* sky exchange: the whole surface sees a black sky at T_sky (eq. 2.55);
* convection: hover — forced cross-flow at the momentum-theory downwash V = √(W/(2ρπR²))
  (eq. 2.56) with Hilpert (eq. 2.57, the thesis's) or Churchill-Bernstein; parked — free convection from a
  horizontal cylinder, Churchill-Chu (eq. 2.59). Air properties at the film temperature.

The elliptical boom is replaced by a circle of the same perimeter (D = P/π, Ramanujan's
perimeter at the length-averaged semi-axes; exact average for the proportional baseline taper):
the convective and radiating area then equals the real skin area. The shaft's heat is
negligible against the boom's solar load and is not in this balance. The nonlinear equation is
solved by Brent's method on [T_sky − 100 K, T_amb + 300 K], narrowed so that the film
temperature stays within the 200-600 K of the air properties
(:func:`~flexshaft.thermal.air.air_properties`); a skin temperature outside it is refused with
the environment fields that set it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from fluids.numerics import NotBoundedError, brenth

from flexshaft.analyses.guards import RefusedInputError
from flexshaft.thermal.air import AIR_TEMPERATURE_RANGE, air_properties
from flexshaft.thermal.correlations import ForcedMethod, Nusselt, churchill_chu_nusselt, forced_cylinder_nusselt
from flexshaft.thermal.environment import GRAVITY, STEFAN_BOLTZMANN, ThermalEnvironment
from flexshaft.units import kelvin_to_celsius

__all__ = [
    "BoomCondition",
    "BoomTemperature",
    "ellipse_perimeter",
    "boom_equivalent_diameter",
    "boom_heat_transfer_coefficient",
    "tailboom_temperature",
    "tailboom_temperatures",
]

BoomCondition = Literal["hover", "parked"]
#: Temperatures at which the air's properties are evaluated [K] (flexshaft.thermal.air).
_AIR_RANGE = AIR_TEMPERATURE_RANGE


@dataclass(frozen=True)
class BoomTemperature:
    """Steady skin temperature of the tailboom and the terms of its energy balance.

    Attributes
    ----------
    condition : str
        "hover" or "parked".
    temperature : float
        Skin temperature [K].
    heat_transfer_coefficient : float
        h at the solution [W/(m^2 K)].
    nusselt : Nusselt
        Correlation, value and validity flag.
    dimensionless : float
        Re_D (hover) or Ra_D (parked) at the solution [-].
    velocity : float
        Cross-flow velocity [m/s] (0 when parked).
    diameter : float
        Equivalent diameter [m].
    absorbed_solar, net_radiation, convection : float
        Terms of the balance per unit skin area [W/m^2]: absorbed = radiation + convection.
    """

    condition: str
    temperature: float
    heat_transfer_coefficient: float
    nusselt: Nusselt
    dimensionless: float
    velocity: float
    diameter: float
    absorbed_solar: float
    net_radiation: float
    convection: float

    @property
    def celsius(self) -> float:
        """Skin temperature [°C]."""
        return kelvin_to_celsius(self.temperature)


def ellipse_perimeter(a: float, b: float) -> float:
    """Ramanujan's second approximation of an ellipse's perimeter [m] (error < 1e-9 relative
    for the boom's b/a = 0.8) for semi-axes ``a``, ``b`` [m]."""
    h = ((a - b) / (a + b)) ** 2
    return math.pi * (a + b) * (1 + 3 * h / (10 + math.sqrt(4 - 3 * h)))


def boom_equivalent_diameter(tailboom) -> float:
    """Diameter [m] of the circle with the boom's mean skin perimeter.

    ``tailboom`` is the design's tailboom table (``root_semi_axes``, ``tip_semi_axes`` mid-line
    [m], ``wall_thickness`` [m]); the outer surface is the mid-line plus half the wall.
    """
    t = tailboom.wall_thickness
    a = 0.5 * (tailboom.root_semi_axes[0] + tailboom.tip_semi_axes[0]) + t / 2
    b = 0.5 * (tailboom.root_semi_axes[1] + tailboom.tip_semi_axes[1]) + t / 2
    return ellipse_perimeter(a, b) / math.pi


def boom_heat_transfer_coefficient(
    temperature: float,
    diameter: float,
    condition: BoomCondition,
    env: ThermalEnvironment,
    method: ForcedMethod = "hilpert",
) -> tuple[float, Nusselt, float]:
    """Convection coefficient h [W/(m^2 K)] of the boom at skin ``temperature`` [K].

    Returns ``(h, Nusselt, Re_D or Ra_D)``; air properties at the film temperature.
    """
    film = air_properties(0.5 * (temperature + env.ambient_temperature), env.air_pressure)
    if condition == "hover":
        V = env.downwash_velocity
        Re = V * diameter / film.kinematic_viscosity
        nu = forced_cylinder_nusselt(Re, film.prandtl, method)
        return nu.value * film.conductivity / diameter, nu, Re
    if condition == "parked":
        dT = max(abs(temperature - env.ambient_temperature), 1e-6)
        Gr = GRAVITY * film.expansion_coefficient * dT * diameter**3 / film.kinematic_viscosity**2
        nu = churchill_chu_nusselt(film.prandtl, Gr)
        return nu.value * film.conductivity / diameter, nu, Gr * film.prandtl
    raise ValueError(f"condition must be 'hover' or 'parked', got {condition!r}")


def tailboom_temperature(
    condition: BoomCondition, diameter: float, env: ThermalEnvironment | None = None, method: ForcedMethod = "hilpert"
) -> BoomTemperature:
    """Steady tailboom skin temperature for ``condition`` ("hover" or "parked").

    Parameters
    ----------
    diameter : float
        Equivalent boom diameter [m] (:func:`boom_equivalent_diameter`).
    env : ThermalEnvironment
        Environment (default: the baseline's).
    method : {"hilpert", "churchill_bernstein"}
        Forced-convection correlation (hover only).
    """
    env = env or ThermalEnvironment()
    if not (math.isfinite(diameter) and diameter > 0):
        raise ValueError(f"diameter must be finite and > 0 [m], got {diameter!r}")
    absorbed = env.absorptivity * env.solar_irradiation * env.solar_area_fraction
    eps_sigma = env.emissivity * STEFAN_BOLTZMANN

    def residual(T: float) -> float:
        h, _, _ = boom_heat_transfer_coefficient(T, diameter, condition, env, method)
        return absorbed - eps_sigma * (T**4 - env.sky_temperature**4) - h * (T - env.ambient_temperature)

    T_amb = env.ambient_temperature
    lo = max(min(env.sky_temperature, T_amb) - 100.0, 200.0, 2 * _AIR_RANGE[0] - T_amb)
    hi = min(T_amb + 300.0, 2 * _AIR_RANGE[1] - T_amb)
    why = (
        f"tailboom energy balance ({condition}): no skin temperature between {lo:.6g} K and {hi:.6g} K, "
        f"where the film temperature stays within the air properties' {_AIR_RANGE[0]:g}-{_AIR_RANGE[1]:g} K "
        f"(ambient {T_amb:.6g} K, sky {env.sky_temperature:.6g} K, absorbed sun {absorbed:.6g} W/m²): "
        "[thermal] ambient_temperature_c, sky_temperature_c, solar_constant, solar_fraction, "
        "solar_area_fraction, emissivity and solar_absorptivity set it"
    )
    if not lo < hi:
        raise RefusedInputError(why)
    try:  # fluids' Brent (hyperbolic) root finder: scipy.optimize costs 0.35 s to import
        T = brenth(residual, lo, hi, xtol=1e-10, rtol=1e-14)
    except NotBoundedError as exc:
        raise RefusedInputError(why) from exc
    h, nu, dimensionless = boom_heat_transfer_coefficient(T, diameter, condition, env, method)
    return BoomTemperature(
        condition=condition,
        temperature=T,
        heat_transfer_coefficient=h,
        nusselt=nu,
        dimensionless=dimensionless,
        velocity=env.downwash_velocity if condition == "hover" else 0.0,
        diameter=diameter,
        absorbed_solar=absorbed,
        net_radiation=eps_sigma * (T**4 - env.sky_temperature**4),
        convection=h * (T - env.ambient_temperature),
    )


def tailboom_temperatures(
    diameter: float, env: ThermalEnvironment | None = None, method: ForcedMethod = "hilpert"
) -> dict[str, BoomTemperature]:
    """Hover and parked skin temperatures of a boom of equivalent ``diameter`` [m]
    (:func:`boom_equivalent_diameter` of the design's tailboom table)."""
    return {c: tailboom_temperature(c, diameter, env, method) for c in ("hover", "parked")}
