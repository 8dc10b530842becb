"""Plausible physical ranges of the numbers of a design file, one annotated type per quantity.

Every float of the schema is strict (no ``"3"``, no ``true``), finite and bounded on both sides
by a range that contains every real driveline with a wide margin, and the usual idealisations
(a rigid member at 1e16 Pa, a massless shaft at 1e-6 kg/m³), but keeps the arithmetic of the
analyses in double precision: products such as E·I, k·L³, ω²·M or L⁴ stay far from overflow
(1.8e308) and from underflow to zero. A value outside its range is refused with the
field, the value and the range (:mod:`flexshaft.design.io`). The bounds and the reason for
each are listed in ``docs/limits.md``; the bounds, the unit and a one-line reason are also in
the generated JSON schema (``Design.model_json_schema()``: ``minimum``/``maximum``, ``unit``,
``description``).

Checks that involve several fields (the wall thinner than the radius, the torque P/Ω, a
bearing stiffness against the shaft's element stiffness, ...) are made by the models and by
:func:`flexshaft.assembly.build.build_model`.
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import Field
from pydantic.fields import FieldInfo

__all__ = [
    "MAX_ABS_STATION",
    "MAX_CONTROLLER_COEFFICIENT",
    "MAX_NAME_LENGTH",
    "MAX_DESIGN_NAME_LENGTH",
    "MAX_LAYUP_LENGTH",
    "MAX_BEARINGS",
    "MAX_DISKS",
    "MAX_POINT_LOADS",
    "MAX_LINE_LOADS",
    "MAX_MATERIALS",
    "MAX_TORQUE",
    "MIN_SHAFT_LENGTH",
    "quantity",
    "quantity_field",
    "Station",
    "Coordinate",
    "MemberLength",
    "Diameter",
    "SemiAxis",
    "WallThickness",
    "Clearance",
    "Modulus",
    "Density",
    "PoissonRatio",
    "Strength",
    "TsaiWuInteraction",
    "Mass",
    "Inertia",
    "Stiffness",
    "NegativeStiffness",
    "Damping",
    "ProportionalGain",
    "DerivativeGain",
    "IntegralGain",
    "ControllerCoefficient",
    "FilterFrequency",
    "CurrentGain",
    "AirGap",
    "Current",
    "CoilTurns",
    "PoleArea",
    "FluxDensity",
    "BackupGap",
    "Force",
    "ForceCapacity",
    "Moment",
    "ForcePerLength",
    "LoadFactor",
    "Eccentricity",
    "Power",
    "SafetyFactor",
    "Deflection",
]


def quantity_field(
    unit: str,
    description: str,
    *,
    ge: float | None = None,
    gt: float | None = None,
    le: float | None = None,
    lt: float | None = None,
) -> FieldInfo:
    """The field of a strict, finite float with its unit and plausible range.

    A quantity type is spelled ``Annotated[float, quantity_field(...)]`` so that a static type
    checker sees a ``float`` (the design models type check against it) and pydantic sees the
    constraints.

    Parameters
    ----------
    unit
        SI unit shown in messages and in the JSON schema, e.g. ``"N/m"`` (``"-"``: none).
    description
        What the quantity is and why its range is what it is (one sentence).
    ge, gt, le, lt
        The bounds (pydantic constraints).
    """
    field: FieldInfo = Field(
        strict=True,
        allow_inf_nan=False,
        ge=ge,
        gt=gt,
        le=le,
        lt=lt,
        description=description,
        json_schema_extra={"unit": unit},
    )
    return field


def quantity(
    unit: str,
    description: str,
    *,
    ge: float | None = None,
    gt: float | None = None,
    le: float | None = None,
    lt: float | None = None,
) -> Any:
    """``Annotated[float, quantity_field(...)]`` built at run time (same arguments).

    A type built by a call is opaque to a static type checker (mypy refuses it as an
    annotation): the schema's own types use the ``Annotated`` spelling; this form is kept for
    code that builds a field type on the fly.
    """
    return Annotated[float, quantity_field(unit, description, ge=ge, gt=gt, le=le, lt=lt)]


# ------------------------------------------------------------------------------------------------
# Counts and sizes (see docs/limits.md for the measured costs behind them)

#: Largest |station| along the shaft or boom axis [m].
MAX_ABS_STATION = 1000.0
#: Shortest shaft x_end - x_start [m].
MIN_SHAFT_LENGTH = 1e-3
#: Largest transmitted torque P/Ω [N m] (the largest marine shafts carry about 1e7 N m).
MAX_TORQUE = 1e9
#: Largest |coefficient| of a controller polynomial (the realization and C(iω) stay finite).
MAX_CONTROLLER_COEFFICIENT = 1e100
#: Longest ``name`` of the design (a title line) and of a component or material (an identifier).
MAX_DESIGN_NAME_LENGTH = 256
MAX_NAME_LENGTH = 64
#: Longest layup string (the parser also caps the expansion at 1000 plies).
MAX_LAYUP_LENGTH = 2000
#: Most entries of each table array.
MAX_BEARINGS = 64
MAX_DISKS = 256
MAX_POINT_LOADS = 256
MAX_LINE_LOADS = 256
MAX_MATERIALS = 64

# ------------------------------------------------------------------------------------------------
# Geometry

Station = Annotated[
    float,
    quantity_field(
        "m",
        "station along the driveline axis within ±1000 m: a tail-rotor driveline is under "
        "20 m long, the longest line shafts about 100 m",
        ge=-MAX_ABS_STATION,
        le=MAX_ABS_STATION,
    ),
]
Coordinate = Annotated[
    float, quantity_field("m", "offset within ±1000 m (the largest station)", ge=-MAX_ABS_STATION, le=MAX_ABS_STATION)
]
MemberLength = Annotated[
    float, quantity_field("m", "member length from 1 mm to 1000 m (the largest station)", ge=1e-3, le=MAX_ABS_STATION)
]
Diameter = Annotated[
    float,
    quantity_field(
        "m", "diameter from 1 mm (a spindle) to 10 m (ten times the largest marine shaft)", ge=1e-3, le=10.0
    ),
]
SemiAxis = Annotated[float, quantity_field("m", "semi-axis of the boom section from 1 mm to 10 m", ge=1e-3, le=10.0)]
WallThickness = Annotated[
    float, quantity_field("m", "wall thickness from 10 µm (a tenth of one ply) to 1 m", ge=1e-5, le=1.0)
]
Clearance = Annotated[
    float, quantity_field("m", "distance between the shaft and boom axes from 0 to 10 m", ge=0.0, le=10.0)
]

# ------------------------------------------------------------------------------------------------
# Materials

Modulus = Annotated[
    float,
    quantity_field(
        "Pa",
        "elastic modulus from 1 kPa (a soft foam) to 1e16 Pa (5e4 times steel: the rigid-member "
        "idealisation; real materials stop at 1.2e12, diamond)",
        ge=1e3,
        le=1e16,
    ),
]
Density = Annotated[
    float,
    quantity_field(
        "kg/m^3",
        "density from 1e-6 kg/m³ (the massless-member idealisation of a Jeffcott rotor) to "
        "1e5 kg/m³ (4 times osmium); zero or subnormal densities make the mass matrix singular",
        ge=1e-6,
        le=1e5,
    ),
]
PoissonRatio = Annotated[
    float,
    quantity_field(
        "-", "Poisson ratio from 0 to 1 (a ply's ν_LT by the rule of mixtures is at most 0.5)", ge=0.0, le=1.0
    ),
]
Strength = Annotated[
    float,
    quantity_field(
        "Pa",
        "strength from 1 kPa to 100 GPa (the ideal strength of graphene, 130 GPa; carbon fibres reach 7 GPa)",
        ge=1e3,
        le=1e11,
    ),
]
TsaiWuInteraction = Annotated[
    float,
    quantity_field(
        "1/Pa^2", "Tsai-Wu F12; |F12| < sqrt(F11 F22) <= 1/(1 kPa)² by the strength bounds", ge=-1e-6, le=1e-6
    ),
]


# ------------------------------------------------------------------------------------------------
# Inertia, stiffness, damping, control

Mass = Annotated[
    float, quantity_field("kg", "lumped mass from 0 to 100 t (the heaviest helicopter weighs 56 t)", ge=0.0, le=1e5)
]
Inertia = Annotated[
    float, quantity_field("kg m^2", "mass moment of inertia from 0 to 1e7 kg m² (100 t at 10 m)", ge=0.0, le=1e7)
]
Stiffness = Annotated[
    float,
    quantity_field(
        "N/m or N m/rad",
        "bearing stiffness from 0 to 1e12 N/m (N m/rad for beta, gamma): 1e12 is rigid for "
        "any shaft; above it the eigen-solution loses digits",
        ge=0.0,
        le=1e12,
    ),
]
NegativeStiffness = Annotated[
    float,
    quantity_field(
        "N/m",
        "open-loop negative stiffness k_s of a magnet from 0 to 1e12 N/m, like a bearing stiffness",
        ge=0.0,
        le=1e12,
    ),
]
Damping = Annotated[
    float,
    quantity_field(
        "N s/m or N m s/rad",
        "viscous damping from 0 to 1e9 N s/m (N m s/rad for beta, gamma; a squeeze-film damper gives 1e4-1e5)",
        ge=0.0,
        le=1e9,
    ),
]
ProportionalGain = Annotated[
    float,
    quantity_field(
        "N/m",
        "proportional gain from 0 to 1e12 (N/m, or A/m with a current gain k_i), like a bearing stiffness",
        ge=0.0,
        le=1e12,
    ),
]
DerivativeGain = Annotated[
    float, quantity_field("N s/m", "derivative gain from 0 to 1e9 (N s/m, or A s/m), like a damper", ge=0.0, le=1e9)
]
IntegralGain = Annotated[
    float,
    quantity_field(
        "N/(m s)",
        "integral gain from 0 to 1e15 (N/(m s), or A/(m s)): a corner K_I/K_p up to 1000 rad/s at the largest K_p",
        ge=0.0,
        le=1e15,
    ),
]
ControllerCoefficient = Annotated[
    float,
    quantity_field(
        "-",
        "transfer-function coefficient (SI, powers of s in rad/s) within ±1e100: C(iω) and its realization stay finite",
        ge=-MAX_CONTROLLER_COEFFICIENT,
        le=MAX_CONTROLLER_COEFFICIENT,
    ),
]
FilterFrequency = Annotated[
    float,
    quantity_field(
        "Hz",
        "corner frequency from 1 mHz to 10 MHz (digital bearing controllers sample at "
        "10-50 kHz); lower corners overflow 1/ω",
        ge=1e-3,
        le=1e7,
    ),
]
CurrentGain = Annotated[
    float, quantity_field("N/A", "actuator current gain k_i up to 1e6 N/A (real magnets: 10-1000 N/A)", gt=0.0, le=1e6)
]
AirGap = Annotated[
    float, quantity_field("m", "nominal magnetic air gap from 1 µm to 0.1 m (real bearings: 0.3-1 mm)", ge=1e-6, le=0.1)
]
Current = Annotated[float, quantity_field("A", "bias current up to 10 kA", gt=0.0, le=1e4)]
CoilTurns = Annotated[float, quantity_field("-", "coil turns up to 1e5", gt=0.0, le=1e5)]
PoleArea = Annotated[float, quantity_field("m^2", "pole face area up to 10 m²", gt=0.0, le=10.0)]
FluxDensity = Annotated[
    float, quantity_field("T", "saturation flux density up to 10 T (iron-cobalt saturates at 2.4 T)", gt=0.0, le=10.0)
]
BackupGap = Annotated[
    float, quantity_field("m", "radial clearance of the auxiliary bearing up to 0.1 m", gt=0.0, le=0.1)
]

# ------------------------------------------------------------------------------------------------
# Loads and operating point

Force = Annotated[
    float,
    quantity_field(
        "N", "force component within ±1e9 N (2e5 times the 5 kN thrust of the baseline tail rotor)", ge=-1e9, le=1e9
    ),
]
ForceCapacity = Annotated[
    float, quantity_field("N", "largest force of an actuator, above 0 and at most 1e9 N", gt=0.0, le=1e9)
]
Moment = Annotated[float, quantity_field("N m", "moment component within ±1e9 N m", ge=-1e9, le=1e9)]
ForcePerLength = Annotated[float, quantity_field("N/m", "line load component within ±1e9 N/m", ge=-1e9, le=1e9)]
LoadFactor = Annotated[
    float, quantity_field("g", "load factor component within ±100 g (crash cases reach 20-30 g)", ge=-100.0, le=100.0)
]
Eccentricity = Annotated[
    float,
    quantity_field("m", "mass eccentricity from 0 to 10 mm (balance grade G40 at 5000 rpm is 76 µm)", ge=0.0, le=1e-2),
]
Power = Annotated[
    float,
    quantity_field("W", "transmitted power from 0 to 1 GW (the largest gas turbines give 0.6 GW)", ge=0.0, le=1e9),
]
SafetyFactor = Annotated[float, quantity_field("-", "required safety factor above 0 and at most 100", gt=0.0, le=100.0)]
Deflection = Annotated[float, quantity_field("m", "deflection limit above 0 and at most 10 m", gt=0.0, le=10.0)]
