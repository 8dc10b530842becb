"""Materials of the design file: ``[materials.<name>]`` tables, an orthotropic ply or an isotropic metal.

Moduli are storage values [Pa], loss factors are dimensionless, densities [kg/m³], thermal
expansion coefficients [1/K], temperatures [°C] (converted to kelvin by the properties that
carry the SI name). The ``kind`` key selects the model (``"lamina"`` or ``"isotropic"``).
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import Field, model_validator

from flexshaft.design.fields import FrozenModel, LossFactor, Problems, format_number, format_value
from flexshaft.design.quantities import Density, Modulus, PoissonRatio, Strength, TsaiWuInteraction, quantity_field
from flexshaft.design.temperature_table import TemperatureTable
from flexshaft.units import ZERO_CELSIUS, celsius_to_kelvin

__all__ = [
    "DEFAULT_ALPHA_L",
    "DEFAULT_ALPHA_T",
    "DEFAULT_FIBRE_MISALIGNMENT_DEG",
    "DEFAULT_NU_23",
    "DEFAULT_SHEAR_CORRECTION",
    "DEFAULT_STRESS_FREE_TEMPERATURE_C",
    "Isotropic",
    "Lamina",
    "Material",
]

#: Transverse Poisson ratio nu_23 [-] behind the default G_23 = E_T / (2 (1 + nu_23)) = E_T / 3.
DEFAULT_NU_23 = 0.5
#: Default transverse shear correction factor k [-] of first-order shear deformation theory
#: (Reissner 1945, Mindlin 1951: 5/6 is exact for the energy of a homogeneous section).
DEFAULT_SHEAR_CORRECTION = 5.0 / 6.0

#: Thermal expansion along the fibres [1/K] (assumed): carbon fibre dominates, alpha_1 ~ alpha_f
#: of T700S, -0.38e-6 1/K (Toray T700S data sheet), the soft matrix adding nothing (Schapery 1968).
DEFAULT_ALPHA_L = -0.4e-6
#: Thermal expansion across the fibres [1/K] (assumed): Schapery's (1968) estimate
#: alpha_2 = (1 + nu_m) alpha_m V_m + (1 + nu_f) alpha_f2 V_f - alpha_1 nu_12 with a polyurethane
#: matrix alpha_m ~ 180e-6 1/K, nu_m 0.48, V_m 0.4 and a carbon fibre alpha_f2 ~ 10e-6 1/K,
#: nu_f 0.2, V_f 0.6: 114e-6 1/K, rounded to 110e-6.
DEFAULT_ALPHA_T = 110e-6
#: Stress-free temperature of the laminate [°C] (assumed): the cure temperature of an MDI/TDI
#: polyurethane cured with an aromatic diamine, about 100 °C; residual ply stresses grow as the
#: shaft cools below it.
DEFAULT_STRESS_FREE_TEMPERATURE_C = 100.0
#: Initial fibre misalignment of the kink-band strength [deg] (assumed): the middle of the 1-3 deg
#: usually quoted for aligned polymer-matrix composites after Budiansky & Fleck (1993) (docs/model.md).
#: Equal to :data:`flexshaft.strength.DEFAULT_FIBRE_MISALIGNMENT_DEG` (tests/test_kinking.py).
DEFAULT_FIBRE_MISALIGNMENT_DEG = 2.0
#: Plausible bounds of a thermal expansion coefficient [1/K]: catches values given in ppm/K.
_ALPHA_LIMIT = 1e-3

ShearCorrection = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        gt=0.0,
        le=1.0,
        description=("first-order shear correction factor k in (0, 1]"),
        json_schema_extra={"unit": "-"},
    ),
]
Celsius = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        gt=-ZERO_CELSIUS,
        le=400.0,
        description=("temperature above absolute zero and at most 400 °C (polymer matrices decompose near 300 °C)"),
        json_schema_extra={"unit": "degC"},
    ),
]
FibreMisalignment = Annotated[
    float,
    quantity_field(
        "deg",
        "initial fibre misalignment from 0 to 10 deg (1-3 deg in aligned composites; the kink-band "
        "formula is a small-angle one)",
        ge=0.0,
        le=10.0,
    ),
]
ShearYieldStrain = Annotated[
    float,
    quantity_field(
        "-",
        "shear yield strain gamma_y above 0 and at most 10 (elastomer matrices yield at far larger strains than "
        "epoxies)",
        gt=0.0,
        le=10.0,
    ),
]
#: Thermal expansion [1/K]: finite here; the range (±1e-3 1/K, with a hint for values in ppm/K)
#: is checked by :meth:`Lamina._check`. The JSON schema shows the range of
#: :data:`~flexshaft.design.quantities.ExpansionCoefficient`.
_Expansion = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        description=(
            "thermal expansion coefficient within ±1e-3 1/K (polymers 2e-4; a value in ppm/K needs the factor 1e-6)"
        ),
        json_schema_extra={"unit": "1/K", "minimum": -_ALPHA_LIMIT, "maximum": _ALPHA_LIMIT},
    ),
]


class Lamina(FrozenModel):
    """Orthotropic unidirectional ply with hysteretic (complex) moduli.

    Moduli are storage values [Pa]; ``loss_*`` are loss factors η, so the complex modulus is
    E' (1 + iη). Strengths are positive magnitudes [Pa]. ``F12`` is the Tsai-Wu interaction
    coefficient [1/Pa²]; when omitted the analysis uses −½·sqrt(F11·F22).

    Out-of-plane and thermal properties (all optional, defaults documented here):

    * ``G_13`` [Pa], transverse shear modulus in the fibre-thickness plane; default ``G_LT``
      (transversely isotropic ply: the 1-3 plane is equivalent to the 1-2 plane).
    * ``G_23`` [Pa], transverse shear modulus across the fibres; default
      ``E_T / (2 (1 + nu_23))`` with nu_23 = 0.5, i.e. ``E_T / 3`` (carbon/epoxy plies measure
      nu_23 = 0.4-0.5; a nearly incompressible elastomer matrix pushes nu_23 towards 1, where
      ``G_23 = E_T / 4``: give ``G_23`` for such a ply). Must exceed
      ``E_T / (4 (1 - nu_LT nu_TL))`` (nu_23 < 1 - 2 nu_LT nu_TL, a positive-definite ply).
    * ``shear_correction`` [-], first-order shear deformation factor k in (0, 1]; default 5/6
      (Reissner 1945; exact energy of a homogeneous section).
    * ``alpha_L``, ``alpha_T`` [1/K], thermal expansion along and across the fibres; defaults
      :data:`DEFAULT_ALPHA_L` = -0.4e-6 and :data:`DEFAULT_ALPHA_T` = 110e-6 (carbon/polyurethane,
      assumed, Schapery estimate); within ±1e-3 1/K.
    * ``stress_free_temperature_c`` [°C], where the cured laminate carries no residual stress;
      default 100 °C (cure temperature, assumed).

    Compressive strength (fibre kinking; docs/model.md, forced response and strength): the ply
    check with kinking (``shaft_safety_factor(..., kinking=True)``) uses
    min(``X_c``, G_LT / (1 + φ/γ_y)) (Budiansky & Fleck 1993), with

    * ``fibre_misalignment_deg`` [deg], the initial fibre misalignment φ; default 2°
      (:data:`DEFAULT_FIBRE_MISALIGNMENT_DEG`, assumed: the middle of the 1-3° usually quoted for
      aligned polymer-matrix composites);
    * ``shear_yield_strain`` [-], γ_y of the ply in longitudinal shear; omitted: S / G_LT (the
      ply's shear strength taken as its shear yield stress, assumed: an upper bound of γ_y,
      hence of the kink-band strength).

    Temperature dependence: ``temperature_table`` (:class:`TemperatureTable`) lists the storage
    moduli and loss factors over temperature; the lamina's own keys are its properties at
    ``[thermal] matrix_reference_temperature_c``. Omitted: the assumed exponential law of the
    ``[thermal]`` table (:mod:`flexshaft.thermal.matrix`).

    Attributes
    ----------
    kind : {"lamina"}
        Selects the orthotropic ply.
    density : float
        Ply density [kg/m³].
    E_L : float
        Storage modulus along the fibres [Pa].
    E_T : float
        Storage modulus across the fibres [Pa].
    G_LT : float
        In-plane shear storage modulus [Pa].
    nu_LT : float
        Major Poisson ratio [-]; less than sqrt(E_L/E_T).
    loss_E_L : float
        Loss factor η of E_L [-]: the complex modulus is E_L (1 + iη).
    loss_E_T : float
        Loss factor η of E_T [-].
    loss_G_LT : float
        Loss factor η of G_LT [-].
    X_t : float
        Tensile strength along the fibres [Pa].
    X_c : float
        Compressive strength along the fibres [Pa] (a positive magnitude).
    Y_t : float
        Tensile strength across the fibres [Pa].
    Y_c : float
        Compressive strength across the fibres [Pa] (a positive magnitude).
    S : float
        In-plane shear strength [Pa].
    F12 : float or None
        Tsai-Wu interaction coefficient [1/Pa²]; omitted: −½·sqrt(F11·F22).
    G_13 : float or None
        Transverse shear modulus in the fibre-thickness plane [Pa]; omitted: ``G_LT``.
    G_23 : float or None
        Transverse shear modulus across the fibres [Pa]; omitted: E_T/3 (ν_23 = 0.5).
    shear_correction : float
        Transverse shear correction factor k of first-order shear deformation theory [-].
    alpha_L : float
        Thermal expansion coefficient along the fibres [1/K].
    alpha_T : float
        Thermal expansion coefficient across the fibres [1/K].
    stress_free_temperature_c : float
        Temperature at which the cured laminate carries no residual stress [°C].
    fibre_misalignment_deg : float
        Initial fibre misalignment φ of the kink-band compressive strength [deg].
    shear_yield_strain : float or None
        Shear yield strain γ_y of the ply in longitudinal shear [-]; omitted: S / G_LT.
    temperature_table : table or None
        Storage moduli and loss factors over temperature (``[materials.<name>.temperature_table]``);
        omitted: the ``[thermal]`` matrix law.
    """

    kind: Literal["lamina"]
    density: Density
    E_L: Modulus
    E_T: Modulus
    G_LT: Modulus
    nu_LT: PoissonRatio
    loss_E_L: LossFactor = 0.0
    loss_E_T: LossFactor = 0.0
    loss_G_LT: LossFactor = 0.0
    X_t: Strength
    X_c: Strength
    Y_t: Strength
    Y_c: Strength
    S: Strength
    F12: TsaiWuInteraction | None = None
    G_13: Modulus | None = None
    G_23: Modulus | None = None
    shear_correction: ShearCorrection = DEFAULT_SHEAR_CORRECTION
    alpha_L: _Expansion = DEFAULT_ALPHA_L
    alpha_T: _Expansion = DEFAULT_ALPHA_T
    stress_free_temperature_c: Celsius = DEFAULT_STRESS_FREE_TEMPERATURE_C
    fibre_misalignment_deg: FibreMisalignment = DEFAULT_FIBRE_MISALIGNMENT_DEG
    shear_yield_strain: ShearYieldStrain | None = None
    temperature_table: TemperatureTable | None = None

    @model_validator(mode="after")
    def _check(self) -> Lamina:
        problems = Problems()
        if self.G_23 is not None:
            lower = self.E_T / (4.0 * (1.0 - self.nu_LT * self.nu_TL))
            if not self.G_23 > lower:
                problems.add(
                    ("G_23",),
                    f"must exceed E_T/(4 (1 - nu_LT nu_TL)) = {format_number(lower)} Pa, i.e. nu_23 = "
                    f"E_T/(2 G_23) - 1 < 1 - 2 nu_LT nu_TL, for a positive-definite transversely isotropic "
                    f"ply (got {format_value(self.G_23)})",
                )
        for name in ("alpha_L", "alpha_T"):
            value = getattr(self, name)
            if not abs(value) <= _ALPHA_LIMIT:
                problems.add(
                    (name,),
                    f"must be a thermal expansion coefficient in 1/K within [-{_ALPHA_LIMIT:g}, {_ALPHA_LIMIT:g}] "
                    f"(got {format_value(value)}; a value in ppm/K needs the factor 1e-6)",
                )
        limit = math.sqrt(self.E_L / self.E_T)
        if not self.nu_LT < limit:
            problems.add(
                ("nu_LT",),
                f"must be less than sqrt(E_L/E_T) = {format_number(limit)} for a positive-definite ply "
                f"stiffness (got {format_value(self.nu_LT)})",
            )
        if self.F12 is not None:
            bound = math.sqrt(1.0 / (self.X_t * self.X_c * self.Y_t * self.Y_c))
            if not abs(self.F12) < bound:
                problems.add(
                    ("F12",),
                    f"|F12| must be less than sqrt(F11*F22) = {format_number(bound)} 1/Pa^2 for a closed "
                    f"Tsai-Wu envelope (got {format_value(self.F12)})",
                )
        problems.raise_if_any()
        return self

    @property
    def nu_TL(self) -> float:
        """Minor Poisson ratio ν_TL = ν_LT E_T / E_L [-]."""
        return self.nu_LT * self.E_T / self.E_L

    @property
    def transverse_shear_moduli(self) -> tuple[float, float]:
        """(G_13, G_23) [Pa] with the defaults filled in (G_LT and E_T/(2 (1 + nu_23)), nu_23 = 0.5)."""
        G_23 = self.E_T / (2.0 * (1.0 + DEFAULT_NU_23)) if self.G_23 is None else self.G_23
        return (self.G_LT if self.G_13 is None else self.G_13, G_23)

    @property
    def stress_free_temperature(self) -> float:
        """Stress-free temperature [K]."""
        return celsius_to_kelvin(self.stress_free_temperature_c)

    @property
    def fibre_misalignment(self) -> float:
        """Initial fibre misalignment φ [rad]."""
        return math.radians(self.fibre_misalignment_deg)


class Isotropic(FrozenModel):
    """Isotropic material: moduli [Pa], density [kg/m³], structural loss factor [-].

    Attributes
    ----------
    kind : {"isotropic"}
        Selects the isotropic material.
    E : float
        Young's modulus [Pa].
    G : float
        Shear modulus [Pa]; above E/3 (Poisson ratio E/(2G) − 1 below 0.5).
    density : float
        Density [kg/m³].
    loss_factor : float
        Structural (hysteretic) loss factor η [-]: both moduli are complex, E(1 + iη).
    yield_strength, ultimate_strength, fatigue_strength : float, optional
        Strengths [Pa] for the metal strength check of a shaft segment
        (:mod:`flexshaft.analyses.metal_strength`): S_y, S_ut and S_e, the fully reversed
        (rotating-bending) fatigue strength of the part at its design life with the surface, size
        and reliability factors already applied; yield and fatigue strengths at most the ultimate.
    """

    kind: Literal["isotropic"]
    E: Modulus
    G: Modulus
    density: Density
    loss_factor: LossFactor = 0.0
    yield_strength: Strength | None = None
    ultimate_strength: Strength | None = None
    fatigue_strength: Strength | None = None

    @model_validator(mode="after")
    def _check(self) -> Isotropic:
        problems = Problems()
        if not self.poisson_ratio < 0.5:  # the laminate and shell formulas divide by 1 - 2ν (or need ν < 0.5)
            problems.add(
                ("G",),
                f"gives Poisson ratio E/(2G) - 1 = {format_number(self.poisson_ratio)}, outside (-1, 0.5) "
                f"(got {format_value(self.G)}; allowed: G > E/3 = {format_number(self.E / 3.0)} Pa)",
            )
        if self.ultimate_strength is not None:
            for name in ("yield_strength", "fatigue_strength"):
                value = getattr(self, name)
                if value is not None and not value <= self.ultimate_strength:
                    problems.add(
                        (name,),
                        f"must not exceed ultimate_strength = {format_number(self.ultimate_strength)} Pa "
                        f"(got {format_value(value)})",
                    )
        problems.raise_if_any()
        return self

    @property
    def poisson_ratio(self) -> float:
        """ν = E/(2G) − 1 [-]."""
        return self.E / (2.0 * self.G) - 1.0


Material = Annotated[Lamina | Isotropic, Field(discriminator="kind")]
