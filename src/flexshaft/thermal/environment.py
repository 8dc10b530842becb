"""Thermal environment of the driveline: the thesis Table 2.1 inputs, ambient and sunlit area.

:class:`ThermalEnvironment` holds SI values; its defaults equal the design schema's
``[thermal]`` defaults (the shipped baseline). Build one from a design with
:func:`flexshaft.thermal.options.environment_from`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from flexshaft.units import celsius_to_kelvin

__all__ = ["STEFAN_BOLTZMANN", "GRAVITY", "PROJECTED_AREA_FRACTION", "ThermalEnvironment"]

STEFAN_BOLTZMANN = 5.670374419e-8  # W/(m^2 K^4), CODATA 2018
GRAVITY = 9.80665  # m/s^2
#: Projected width over perimeter of a cylinder, D / (π D) [-]: the skin share lit by an overhead sun.
PROJECTED_AREA_FRACTION = 1.0 / math.pi


@dataclass(frozen=True)
class ThermalEnvironment:
    """Radiative and convective environment of the tailboom and shaft.

    Parameters
    ----------
    rotorcraft_mass : float
        m_rc [kg] (thesis Table 2.1: 6838 kg, AH-64 class).
    rotor_radius : float
        Main-rotor radius R_r [m] (7.315 m).
    emissivity : float
        Boom skin emissivity ε [-] (0.97).
    solar_absorptivity : float or None
        Solar absorptivity α_s [-]; ``None`` takes α_s = ε (the thesis lists ε only).
    solar_constant : float
        S_c [W/m^2] (1353).
    solar_fraction : float
        f [-], atmospheric transmission factor (1).
    solar_zenith : float
        θ_s [rad] (0: sun overhead).
    sky_temperature : float
        Effective sky temperature T_sky [K] (285).
    air_density : float
        ρ_air [kg/m^3] for the momentum-theory downwash (1.225, assumed).
    ambient_temperature : float
        T_amb [K] (25.6 °C: Swinbank's clear sky, T_sky = 0.0552 T_amb^1.5, at T_sky = 285 K).
    air_pressure : float
        Static pressure for the air properties [Pa] (101325).
    solar_area_fraction : float
        Share of the skin area π D L that absorbs G [-] (0.69, calibrated to the thesis's
        89 °C parked): :data:`PROJECTED_AREA_FRACTION` = 1/π for the direct beam of an overhead
        sun on the projected width D, 0.5 for the sunlit half, 1 for the whole skin.
    """

    rotorcraft_mass: float = 6838.0
    rotor_radius: float = 7.315
    emissivity: float = 0.97
    solar_absorptivity: float | None = None
    solar_constant: float = 1353.0
    solar_fraction: float = 1.0
    solar_zenith: float = 0.0
    sky_temperature: float = 285.0
    air_density: float = 1.225
    ambient_temperature: float = celsius_to_kelvin(25.6)
    air_pressure: float = 101325.0
    solar_area_fraction: float = 0.69

    def __post_init__(self) -> None:
        positive = (
            "rotorcraft_mass",
            "rotor_radius",
            "solar_constant",
            "sky_temperature",
            "air_density",
            "ambient_temperature",
            "air_pressure",
        )
        for name in positive:
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"ThermalEnvironment.{name} must be finite and > 0, got {value!r}")
        for name in ("emissivity", "solar_fraction", "solar_area_fraction"):
            value = getattr(self, name)
            if not (math.isfinite(value) and 0 <= value <= 1):
                raise ValueError(f"ThermalEnvironment.{name} must be in [0, 1], got {value!r}")
        if self.solar_absorptivity is not None and not 0 <= self.solar_absorptivity <= 1:
            raise ValueError(
                f"ThermalEnvironment.solar_absorptivity must be in [0, 1], got {self.solar_absorptivity!r}"
            )
        if not (math.isfinite(self.solar_zenith) and abs(self.solar_zenith) <= math.pi / 2):
            raise ValueError(f"ThermalEnvironment.solar_zenith must be in [-pi/2, pi/2] rad, got {self.solar_zenith!r}")

    @property
    def absorptivity(self) -> float:
        """Solar absorptivity used [-] (ε when not given)."""
        return self.emissivity if self.solar_absorptivity is None else self.solar_absorptivity

    @property
    def solar_irradiation(self) -> float:
        """G = S_c f cos θ_s [W/m^2] (thesis eq. 2.58)."""
        return self.solar_constant * self.solar_fraction * math.cos(self.solar_zenith)

    @property
    def rotorcraft_weight(self) -> float:
        """W = m_rc g [N]."""
        return self.rotorcraft_mass * GRAVITY

    @property
    def downwash_velocity(self) -> float:
        """Hover induced velocity at the rotor disk, V = √(W / (2 ρ π R²)) [m/s] (eq. 2.56)."""
        return math.sqrt(self.rotorcraft_weight / (2.0 * self.air_density * math.pi * self.rotor_radius**2))
