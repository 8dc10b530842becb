"""Proposed ``[thermal]`` table of the design file (not yet attached to :class:`Design`).

To attach it, add ``thermal: Thermal = Thermal()`` to ``Design`` in
:mod:`flexshaft.design.schema` and re-export :class:`Thermal`; the thermal analyses then take
``design.thermal.environment()`` and ``design.thermal.matrix_law()``. Temperatures are in
degrees Celsius in the file (the edge) and converted to kelvin by the two builders; the zenith
angle is in degrees. Defaults are DESIGN.md §5 (thesis Table 2.1 + assumed hot day) and the
assumed matrix law of :mod:`flexshaft.thermal.selfheating`.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from flexshaft.design.fields import FrozenModel, Positive

__all__ = ["Thermal"]

Fraction = Annotated[float, Field(strict=True, allow_inf_nan=False, ge=0.0, le=1.0)]
Celsius = Annotated[float, Field(strict=True, allow_inf_nan=False, gt=-273.15, le=400.0)]
Zenith = Annotated[float, Field(strict=True, allow_inf_nan=False, ge=-90.0, le=90.0)]
Conductivity = Annotated[float, Field(strict=True, allow_inf_nan=False, gt=0.0, le=2000.0)]


class Thermal(FrozenModel):
    """Thermal environment, shaft heat-transfer options and the matrix temperature law."""

    rotorcraft_mass: Positive = 6838.0          # kg, thesis Table 2.1
    rotor_radius: Positive = 7.315              # m
    emissivity: Fraction = 0.97
    solar_absorptivity: Fraction | None = None  # None: equal to the emissivity (assumed)
    solar_constant: Positive = 1353.0           # W/m^2
    solar_fraction: Fraction = 1.0
    solar_zenith_deg: Zenith = 0.0
    sky_temperature_c: Celsius = 285.0 - 273.15
    air_density: Positive = 1.225               # kg/m^3 (assumed)
    ambient_temperature_c: Celsius = 35.0       # assumed hot day
    solar_area: Literal["projected", "half_surface", "surface"] = "projected"
    boom_convection: Literal["churchill_bernstein", "hilpert"] = "churchill_bernstein"
    shaft_convection: Literal["becker", "kendoush"] = "becker"
    loss_model: Literal["thesis", "rotating"] = "rotating"
    fibre_conductivity: Conductivity = 5.0      # W/(m K), along the fibres (assumed)
    transverse_conductivity: Conductivity = 0.5 # W/(m K), across the fibres (assumed)
    matrix_reference_temperature_c: Celsius = 20.0
    matrix_modulus_decay: Positive = 40.0       # K
    matrix_loss_growth: Positive = 60.0         # K
    allowable_temperature_c: Celsius = 100.0    # matrix critical temperature (assumed)

    def environment(self):
        """The :class:`flexshaft.thermal.ThermalEnvironment` of this table (SI, kelvin)."""
        import math

        from flexshaft.thermal.environment import ZERO_CELSIUS, ThermalEnvironment

        return ThermalEnvironment(
            rotorcraft_mass=self.rotorcraft_mass, rotor_radius=self.rotor_radius, emissivity=self.emissivity,
            solar_absorptivity=self.solar_absorptivity, solar_constant=self.solar_constant,
            solar_fraction=self.solar_fraction, solar_zenith=math.radians(self.solar_zenith_deg),
            sky_temperature=self.sky_temperature_c + ZERO_CELSIUS, air_density=self.air_density,
            ambient_temperature=self.ambient_temperature_c + ZERO_CELSIUS, solar_area=self.solar_area,
        )

    def matrix_law(self):
        """The :class:`flexshaft.thermal.selfheating.MatrixTemperatureLaw` of this table."""
        from flexshaft.thermal.environment import ZERO_CELSIUS
        from flexshaft.thermal.selfheating import MatrixTemperatureLaw

        return MatrixTemperatureLaw(
            reference_temperature=self.matrix_reference_temperature_c + ZERO_CELSIUS,
            modulus_decay=self.matrix_modulus_decay, loss_growth=self.matrix_loss_growth,
            allowable_temperature=self.allowable_temperature_c + ZERO_CELSIUS,
        )
