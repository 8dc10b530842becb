"""The ``[thermal]`` table of the design file: plain validated values, no runtime objects.

Temperatures are in degrees Celsius in the file (the edge) and the zenith angle in degrees;
:func:`flexshaft.thermal.options.thermal_options` converts the table to the SI objects the
thermal analyses use. The defaults are the shipped baseline's values (docs/thermal.md: thesis
Table 2.1, the assumed and calibrated values marked in ``baseline.toml``). The shaft's loss
model is not a thermal choice: it is the design's ``[analysis] internal_damping``.
"""

from __future__ import annotations

from typing import Annotated, Literal

from flexshaft.design.fields import FrozenModel
from flexshaft.design.quantities import quantity_field
from flexshaft.units import ZERO_CELSIUS

__all__ = ["Thermal", "BoomConvection", "ShaftConvection"]

Fraction = Annotated[float, quantity_field("-", "fraction from 0 to 1", ge=0.0, le=1.0)]
Celsius = Annotated[
    float, quantity_field("degC", "temperature above absolute zero and at most 400 °C", gt=-ZERO_CELSIUS, le=400.0)
]
#: The air's properties are evaluated from 200 to 600 K (flexshaft.thermal.air), at the film
#: temperature (skin + ambient)/2 of the tailboom, whose skin temperature is sought up to the
#: ambient + 300 K: an ambient within 200-450 K keeps every film temperature in range.
AmbientCelsius = Annotated[
    float,
    quantity_field(
        "degC",
        "ambient air temperature from -73 °C (200.15 K) to 176 °C (449.15 K): the air properties are "
        "evaluated from 200 to 600 K, at film temperatures up to the ambient + 150 K",
        ge=-73.0,
        le=176.0,
    ),
]
Zenith = Annotated[float, quantity_field("deg", "solar zenith angle within ±90 deg", ge=-90.0, le=90.0)]
Conductivity = Annotated[
    float,
    quantity_field(
        "W/(m K)",
        "thermal conductivity from 1e-3 (below an aerogel, 0.013) to 2000 W/(m K) (diamond)",
        ge=1e-3,
        le=2000.0,
    ),
]
RotorcraftMass = Annotated[
    float,
    quantity_field("kg", "rotorcraft mass from 1 kg to 1e6 kg (the heaviest helicopter weighs 56 t)", ge=1.0, le=1e6),
]
RotorRadius = Annotated[
    float,
    quantity_field(
        "m", "main-rotor radius from 0.1 m to 100 m (the largest rotor, Mi-12, is 17.5 m)", ge=0.1, le=100.0
    ),
]
SolarConstant = Annotated[
    float, quantity_field("W/m^2", "solar irradiance above 0 and at most 1e4 W/m² (1361 at the Earth)", gt=0.0, le=1e4)
]
AirDensity = Annotated[
    float, quantity_field("kg/m^3", "air density from 1e-3 to 100 kg/m³ (1.225 at sea level)", ge=1e-3, le=100.0)
]
TemperatureScale = Annotated[
    float,
    quantity_field(
        "K",
        "temperature scale θ of the matrix law exp(±ΔT/θ) from 5 K to 1e6 K: over the "
        "673 K span of allowed temperatures the factor stays below 1e59 (a glass transition "
        "takes about 10 K per factor e)",
        ge=5.0,
        le=1e6,
    ),
]

#: Forced-convection correlation of the hovering tailboom (cross-flow over a cylinder).
BoomConvection = Literal["hilpert", "churchill_bernstein"]
#: Convection correlation of the shaft spinning in still air.
ShaftConvection = Literal["becker", "kendoush"]


class Thermal(FrozenModel):
    """Thermal environment, heat-transfer correlations, ply conductivities and matrix law.

    Attributes
    ----------
    rotorcraft_mass : float
        m_rc [kg]; its weight sets the hover downwash (thesis Table 2.1).
    rotor_radius : float
        Main-rotor radius R_r [m].
    emissivity : float
        Tailboom skin emissivity ε [-].
    solar_absorptivity : float or None
        Solar absorptivity α_s [-]; None takes α_s = ε.
    solar_constant : float
        S_c [W/m^2].
    solar_fraction : float
        Atmospheric transmission f [-] in G = S_c f cos θ_s.
    solar_zenith_deg : float
        Solar zenith angle θ_s [deg].
    sky_temperature_c : float
        Effective sky temperature [°C].
    air_density : float
        Air density for the momentum-theory downwash [kg/m^3].
    ambient_temperature_c : float
        Ambient air temperature [°C].
    solar_area_fraction : float
        Share of the boom skin that absorbs the solar irradiation G [-]: 1/π (0.318) is the
        projected area of a cylinder under an overhead sun, 0.5 the sunlit half, 1 the whole skin.
    boom_convection : {"hilpert", "churchill_bernstein"}
        Hover cross-flow correlation of the tailboom (thesis eq. 2.57 is Hilpert's).
    shaft_convection : {"becker", "kendoush"}
        Rotating-shaft convection correlation (thesis eq. 2.63 cites Kendoush).
    fibre_conductivity : float
        Ply thermal conductivity along the fibres [W/(m K)].
    transverse_conductivity : float
        Ply thermal conductivity across the fibres [W/(m K)].
    matrix_reference_temperature_c : float
        Temperature of the lamina data [°C].
    matrix_modulus_decay : float
        θ_E [K]: E_T and G_LT scale by exp(−(T − T_ref)/θ_E).
    matrix_loss_growth : float
        θ_η [K]: the matrix loss factors scale by exp(+(T − T_ref)/θ_η).
    allowable_temperature_c : float
        Matrix critical temperature [°C]: the shaft must stay below it (thermal runaway when
        the self-heating has no equilibrium below it).
    """

    rotorcraft_mass: RotorcraftMass = 6838.0
    rotor_radius: RotorRadius = 7.315
    emissivity: Fraction = 0.97
    solar_absorptivity: Fraction | None = None
    solar_constant: SolarConstant = 1353.0
    solar_fraction: Fraction = 1.0
    solar_zenith_deg: Zenith = 0.0
    sky_temperature_c: Celsius = 11.85  # 285 K
    air_density: AirDensity = 1.225
    ambient_temperature_c: AmbientCelsius = 25.6
    solar_area_fraction: Fraction = 0.69
    boom_convection: BoomConvection = "hilpert"
    shaft_convection: ShaftConvection = "becker"
    fibre_conductivity: Conductivity = 5.0
    transverse_conductivity: Conductivity = 0.5
    matrix_reference_temperature_c: Celsius = 20.0
    matrix_modulus_decay: TemperatureScale = 40.0
    matrix_loss_growth: TemperatureScale = 60.0
    allowable_temperature_c: Celsius = 100.0
