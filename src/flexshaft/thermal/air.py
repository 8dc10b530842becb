"""Properties of dry air at atmospheric pressure, without a fluid-property database.

* dynamic viscosity: Sutherland's law as in the U.S. Standard Atmosphere 1976, through
  ``fluids.atmosphere.ATMOSPHERE_1976.viscosity`` (μ = 1.458e-6 T^1.5 / (T + 110.4));
* thermal conductivity: the U.S. Standard Atmosphere 1976 correlation, through
  ``fluids.atmosphere.ATMOSPHERE_1976.thermal_conductivity``
  (k = 2.64638e-3 T^1.5 / (T + 245.4 · 10^(−12/T)));
* specific heat c_p: linear interpolation of Incropera & DeWitt Table A.4 (250-400 K);
* density: ideal gas, ρ = p / (R T), R = 287.05 J/(kg K).

Within 1 % of Incropera Table A.4 for μ, k, ν and Pr between 250 and 400 K (tested).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from fluids.atmosphere import ATMOSPHERE_1976

__all__ = ["AIR_GAS_CONSTANT", "AIR_TEMPERATURE_RANGE", "AirProperties", "air_properties"]

AIR_GAS_CONSTANT = 287.05  # J/(kg K)
#: Temperatures [K] at which :func:`air_properties` evaluates air (c_p is interpolated from
#: 250-400 K data and extrapolated linearly; the correlations are not checked beyond).
AIR_TEMPERATURE_RANGE = (200.0, 600.0)
_CP_T = np.array([250.0, 300.0, 350.0, 400.0])  # K, Incropera Table A.4
_CP = np.array([1006.0, 1007.0, 1009.0, 1014.0])  # J/(kg K)


@dataclass(frozen=True)
class AirProperties:
    """Air at one temperature and pressure (SI)."""

    temperature: float  # K
    density: float  # kg/m^3
    viscosity: float  # Pa s
    conductivity: float  # W/(m K)
    specific_heat: float  # J/(kg K)

    @property
    def kinematic_viscosity(self) -> float:
        """ν = μ/ρ [m^2/s]."""
        return self.viscosity / self.density

    @property
    def prandtl(self) -> float:
        """Pr = c_p μ / k [-]."""
        return self.specific_heat * self.viscosity / self.conductivity

    @property
    def diffusivity(self) -> float:
        """α = k / (ρ c_p) [m^2/s]."""
        return self.conductivity / (self.density * self.specific_heat)

    @property
    def expansion_coefficient(self) -> float:
        """β = 1/T [1/K] (ideal gas)."""
        return 1.0 / self.temperature


def air_properties(temperature: float, pressure: float = 101325.0) -> AirProperties:
    """Dry-air properties at ``temperature`` [K] and ``pressure`` [Pa].

    Raises
    ------
    ValueError
        Outside 200-600 K, where the c_p interpolation and the correlations are not checked.
    """
    T = float(temperature)
    low, high = AIR_TEMPERATURE_RANGE
    if not low <= T <= high:
        raise ValueError(f"air temperature must be within {low:g}-{high:g} K, got {T!r} K")
    cp = float(np.interp(T, _CP_T, _CP, left=_CP[0], right=None))
    if T > _CP_T[-1]:  # gentle linear extrapolation of the last interval
        cp = float(_CP[-1] + (T - _CP_T[-1]) * (_CP[-1] - _CP[-2]) / (_CP_T[-1] - _CP_T[-2]))
    return AirProperties(
        temperature=T,
        density=pressure / (AIR_GAS_CONSTANT * T),
        viscosity=float(ATMOSPHERE_1976.viscosity(T)),
        conductivity=float(ATMOSPHERE_1976.thermal_conductivity(T)),
        specific_heat=cp,
    )
