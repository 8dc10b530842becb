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


def quantity(
    unit: str,
    description: str,
    *,
    ge: float | None = None,
    gt: float | None = None,
    le: float | None = None,
    lt: float | None = None,
) -> Any:
    """A strict, finite float field type with its unit and plausible range.

    Parameters
    ----------
    unit
        SI unit shown in messages and in the JSON schema, e.g. ``"N/m"`` (``"-"``: none).
    description
        What the quantity is and why its range is what it is (one sentence).
    ge, gt, le, lt
        The bounds (pydantic constraints).
    """
    return Annotated[
        float,
        Field(
            strict=True,
            allow_inf_nan=False,
            ge=ge,
            gt=gt,
            le=le,
            lt=lt,
            description=description,
            json_schema_extra={"unit": unit},
        ),
    ]


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

Station = quantity(
    "m",
    "station along the driveline axis within ±1000 m: a tail-rotor driveline is under "
    "20 m long, the longest line shafts about 100 m",
    ge=-MAX_ABS_STATION,
    le=MAX_ABS_STATION,
)
Coordinate = quantity("m", "offset within ±1000 m (the largest station)", ge=-MAX_ABS_STATION, le=MAX_ABS_STATION)
MemberLength = quantity("m", "member length from 1 mm to 1000 m (the largest station)", ge=1e-3, le=MAX_ABS_STATION)
Diameter = quantity(
    "m", "diameter from 1 mm (a spindle) to 10 m (ten times the largest marine shaft)", ge=1e-3, le=10.0
)
SemiAxis = quantity("m", "semi-axis of the boom section from 1 mm to 10 m", ge=1e-3, le=10.0)
WallThickness = quantity("m", "wall thickness from 10 µm (a tenth of one ply) to 1 m", ge=1e-5, le=1.0)
Clearance = quantity("m", "distance between the shaft and boom axes from 0 to 10 m", ge=0.0, le=10.0)

# ------------------------------------------------------------------------------------------------
# Materials

Modulus = quantity(
    "Pa",
    "elastic modulus from 1 kPa (a soft foam) to 1e16 Pa (5e4 times steel: the rigid-member "
    "idealisation; real materials stop at 1.2e12, diamond)",
    ge=1e3,
    le=1e16,
)
Density = quantity(
    "kg/m^3",
    "density from 1e-6 kg/m³ (the massless-member idealisation of a Jeffcott rotor) to "
    "1e5 kg/m³ (4 times osmium); zero or subnormal densities make the mass matrix singular",
    ge=1e-6,
    le=1e5,
)
PoissonRatio = quantity(
    "-", "Poisson ratio from 0 to 1 (a ply's ν_LT by the rule of mixtures is at most 0.5)", ge=0.0, le=1.0
)
Strength = quantity(
    "Pa",
    "strength from 1 kPa to 100 GPa (the ideal strength of graphene, 130 GPa; carbon fibres reach 7 GPa)",
    ge=1e3,
    le=1e11,
)
TsaiWuInteraction = quantity(
    "1/Pa^2", "Tsai-Wu F12; |F12| < sqrt(F11 F22) <= 1/(1 kPa)² by the strength bounds", ge=-1e-6, le=1e-6
)


# ------------------------------------------------------------------------------------------------
# Inertia, stiffness, damping, control

Mass = quantity("kg", "lumped mass from 0 to 100 t (the heaviest helicopter weighs 56 t)", ge=0.0, le=1e5)
Inertia = quantity("kg m^2", "mass moment of inertia from 0 to 1e7 kg m² (100 t at 10 m)", ge=0.0, le=1e7)
Stiffness = quantity(
    "N/m or N m/rad",
    "bearing stiffness from 0 to 1e12 N/m (N m/rad for beta, gamma): 1e12 is rigid for "
    "any shaft; above it the eigen-solution loses digits",
    ge=0.0,
    le=1e12,
)
NegativeStiffness = quantity(
    "N/m", "open-loop negative stiffness k_s of a magnet from 0 to 1e12 N/m, like a bearing stiffness", ge=0.0, le=1e12
)
Damping = quantity(
    "N s/m or N m s/rad",
    "viscous damping from 0 to 1e9 N s/m (N m s/rad for beta, gamma; a squeeze-film damper gives 1e4-1e5)",
    ge=0.0,
    le=1e9,
)
ProportionalGain = quantity(
    "N/m",
    "proportional gain from 0 to 1e12 (N/m, or A/m with a current gain k_i), like a bearing stiffness",
    ge=0.0,
    le=1e12,
)
DerivativeGain = quantity("N s/m", "derivative gain from 0 to 1e9 (N s/m, or A s/m), like a damper", ge=0.0, le=1e9)
IntegralGain = quantity(
    "N/(m s)",
    "integral gain from 0 to 1e15 (N/(m s), or A/(m s)): a corner K_I/K_p up to 1000 rad/s at the largest K_p",
    ge=0.0,
    le=1e15,
)
ControllerCoefficient = quantity(
    "-",
    "transfer-function coefficient (SI, powers of s in rad/s) within ±1e100: C(iω) and its realization stay finite",
    ge=-MAX_CONTROLLER_COEFFICIENT,
    le=MAX_CONTROLLER_COEFFICIENT,
)
FilterFrequency = quantity(
    "Hz",
    "corner frequency from 1 mHz to 10 MHz (digital bearing controllers sample at "
    "10-50 kHz); lower corners overflow 1/ω",
    ge=1e-3,
    le=1e7,
)
CurrentGain = quantity("N/A", "actuator current gain k_i up to 1e6 N/A (real magnets: 10-1000 N/A)", gt=0.0, le=1e6)
AirGap = quantity("m", "nominal magnetic air gap from 1 µm to 0.1 m (real bearings: 0.3-1 mm)", ge=1e-6, le=0.1)
Current = quantity("A", "bias current up to 10 kA", gt=0.0, le=1e4)
CoilTurns = quantity("-", "coil turns up to 1e5", gt=0.0, le=1e5)
PoleArea = quantity("m^2", "pole face area up to 10 m²", gt=0.0, le=10.0)
FluxDensity = quantity("T", "saturation flux density up to 10 T (iron-cobalt saturates at 2.4 T)", gt=0.0, le=10.0)
BackupGap = quantity("m", "radial clearance of the auxiliary bearing up to 0.1 m", gt=0.0, le=0.1)

# ------------------------------------------------------------------------------------------------
# Loads and operating point

Force = quantity(
    "N", "force component within ±1e9 N (2e5 times the 5 kN thrust of the baseline tail rotor)", ge=-1e9, le=1e9
)
ForceCapacity = quantity("N", "largest force of an actuator, above 0 and at most 1e9 N", gt=0.0, le=1e9)
Moment = quantity("N m", "moment component within ±1e9 N m", ge=-1e9, le=1e9)
ForcePerLength = quantity("N/m", "line load component within ±1e9 N/m", ge=-1e9, le=1e9)
LoadFactor = quantity("g", "load factor component within ±100 g (crash cases reach 20-30 g)", ge=-100.0, le=100.0)
Eccentricity = quantity(
    "m", "mass eccentricity from 0 to 10 mm (balance grade G40 at 5000 rpm is 76 µm)", ge=0.0, le=1e-2
)
Power = quantity("W", "transmitted power from 0 to 1 GW (the largest gas turbines give 0.6 GW)", ge=0.0, le=1e9)
SafetyFactor = quantity("-", "required safety factor above 0 and at most 100", gt=0.0, le=100.0)
Deflection = quantity("m", "deflection limit above 0 and at most 10 m", gt=0.0, le=10.0)
