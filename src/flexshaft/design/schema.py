"""The design-file schema: one pydantic model tree, the single source of truth for inputs.

The annotated example ``baseline.toml`` next to this module defines the file format; every
table of it is a model here, every key a field. All models forbid unknown keys and are frozen.
Quantities are SI floats [m, kg, s, N, Pa, W]; the only unit conversions are ``speed_rpm``
[rev/min] and the layup angles [deg], exposed as :attr:`Operating.speed_rad_s` and
:attr:`Shaft.ply_angles_deg`.

Constraints that involve several fields are checked in ``model_validator(mode="after")``
hooks that report every problem at once through :func:`_raise_problems`; the error carries the
sub-paths so that :mod:`flexshaft.design.io` can name each offending field. Cross-table checks
on :class:`Design` (material references, bearings on the shaft, ...) run only once every table
validates on its own.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence
from typing import Annotated, Any, Literal, Union

from pydantic import BaseModel, ConfigDict, Field, StrictBool, field_validator, model_validator
from pydantic_core import PydanticCustomError

from flexshaft.design.units import LayupError, parse_layup_degrees, rpm_to_rad_s

__all__ = [
    "ActiveBearing",
    "Bearing",
    "BearingDirection",
    "ContactBearing",
    "Controller",
    "Design",
    "Disk",
    "DofName",
    "EndMass",
    "ImbalancePlacement",
    "Isotropic",
    "Lamina",
    "LineLoad",
    "Loads",
    "Material",
    "Mesh",
    "Operating",
    "PointLoad",
    "Shaft",
    "Tailboom",
    "PROBLEMS_ERROR_TYPE",
    "LAYUP_ERROR_TYPE",
    "format_value",
]

# ------------------------------------------------------------------------------------------------
# Shared field types. Floats are strict (no "3" -> 3.0, no true -> 1.0; integers are accepted)
# and finite (no nan, inf).

Finite = Annotated[float, Field(strict=True, allow_inf_nan=False)]
Positive = Annotated[float, Field(strict=True, allow_inf_nan=False, gt=0.0)]
NonNegative = Annotated[float, Field(strict=True, allow_inf_nan=False, ge=0.0)]
LossFactor = Annotated[float, Field(strict=True, allow_inf_nan=False, ge=0.0, lt=1.0)]
Vector3 = tuple[Finite, Finite, Finite]
NonNegativeVector3 = tuple[NonNegative, NonNegative, NonNegative]
SemiAxes = tuple[Positive, Positive]
Name = Annotated[str, Field(strict=True, min_length=1)]
ElementCount = Annotated[int, Field(strict=True, ge=1, le=2000)]
Coefficients = Annotated[tuple[Finite, ...], Field(min_length=1, max_length=21)]

#: Degree-of-freedom names of a shaft node, in the order of DESIGN.md §1.
DofName = Literal["u", "v", "w", "theta", "beta", "gamma"]
#: Relative-displacement directions of a bearing (DESIGN.md §2.2.3); no twist (theta).
BearingDirection = Literal["u", "v", "w", "beta", "gamma"]
#: Where the imbalance force of each bay is applied (DESIGN.md §2.4).
ImbalancePlacement = Literal["mid_bay", "distributed", "worst"]

#: pydantic error type carrying several (sub-path, message) problems from one model validator.
PROBLEMS_ERROR_TYPE = "flexshaft_problems"
#: pydantic error type of an unparsable layup string.
LAYUP_ERROR_TYPE = "flexshaft_layup"

Path = tuple[Union[str, int], ...]
_ZERO3 = (0.0, 0.0, 0.0)


def format_value(value: Any, limit: int = 60) -> str:
    """Render a user value TOML-like and short, for error messages."""
    if value is None:
        text = "nothing"
    elif isinstance(value, bool):
        text = "true" if value else "false"
    elif isinstance(value, float):
        text = repr(value)
    elif isinstance(value, int):
        digits = str(abs(value)) if abs(value) < 10**40 else ""
        text = str(value) if digits else f"an integer with {len(str(abs(value)))} digits"
    elif isinstance(value, str):
        shown = value if len(value) <= limit else value[: limit - 3] + "..."
        text = '"' + shown.encode("unicode_escape").decode("ascii").replace('"', '\\"') + '"'
    elif isinstance(value, (list, tuple)):
        parts: list[str] = []
        length = 2
        for item in value:
            part = format_value(item, limit=20)
            if length + len(part) > limit:
                parts.append("...")
                break
            parts.append(part)
            length += len(part) + 2
        text = "[" + ", ".join(parts) + "]"
    elif isinstance(value, dict):
        keys = ", ".join(format_value(str(k), limit=20) for k in list(value)[:6])
        more = ", ..." if len(value) > 6 else ""
        text = "a table {" + keys + more + "}" if value else "an empty table"
    else:
        text = f"{type(value).__name__} {value!s}"
    return text if len(text) <= limit + 40 else text[: limit + 37] + "..."


def _g(value: float) -> str:
    """Short rendering of a computed number."""
    return f"{value:.6g}"


class _Problems:
    """Collects (sub-path, message) pairs and raises them as one pydantic error."""

    def __init__(self) -> None:
        self.items: list[tuple[Path, str]] = []

    def add(self, path: Path, message: str) -> None:
        self.items.append((path, message))

    def raise_if_any(self) -> None:
        if self.items:
            summary = "; ".join(
                ".".join(str(part) for part in path) + ": " + message for path, message in self.items
            )
            raise PydanticCustomError(
                PROBLEMS_ERROR_TYPE, "{summary}", {"summary": summary, "problems": tuple(self.items)}
            )


def _check_unique(problems: _Problems, prefix: Path, names: Sequence[str]) -> None:
    counts = Counter(names)
    for index, name in enumerate(names):
        if counts[name] > 1 and names.index(name) != index:
            message = f"duplicate name (got {format_value(name)}; names must be unique)"
            problems.add(prefix + (index, "name"), message)


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


# ------------------------------------------------------------------------------------------------
# Materials


class Lamina(_Model):
    """Orthotropic unidirectional ply with hysteretic (complex) moduli.

    Moduli are storage values [Pa]; ``loss_*`` are loss factors η, so the complex modulus is
    E' (1 + iη). Strengths are positive magnitudes [Pa]. ``F12`` is the Tsai-Wu interaction
    coefficient [1/Pa²]; when omitted the analysis uses −½·sqrt(F11·F22).
    """

    kind: Literal["lamina"]
    density: Positive
    E_L: Positive
    E_T: Positive
    G_LT: Positive
    nu_LT: NonNegative
    loss_E_L: LossFactor = 0.0
    loss_E_T: LossFactor = 0.0
    loss_G_LT: LossFactor = 0.0
    X_t: Positive
    X_c: Positive
    Y_t: Positive
    Y_c: Positive
    S: Positive
    F12: Finite | None = None

    @model_validator(mode="after")
    def _check(self) -> Lamina:
        problems = _Problems()
        limit = math.sqrt(self.E_L / self.E_T)
        if not self.nu_LT < limit:
            problems.add(
                ("nu_LT",),
                f"must be less than sqrt(E_L/E_T) = {_g(limit)} for a positive-definite ply "
                f"stiffness (got {format_value(self.nu_LT)})",
            )
        if self.F12 is not None:
            bound = math.sqrt(1.0 / (self.X_t * self.X_c * self.Y_t * self.Y_c))
            if not abs(self.F12) < bound:
                problems.add(
                    ("F12",),
                    f"|F12| must be less than sqrt(F11*F22) = {_g(bound)} 1/Pa^2 for a closed "
                    f"Tsai-Wu envelope (got {format_value(self.F12)})",
                )
        problems.raise_if_any()
        return self

    @property
    def nu_TL(self) -> float:
        """Minor Poisson ratio ν_TL = ν_LT E_T / E_L [-]."""
        return self.nu_LT * self.E_T / self.E_L


class Isotropic(_Model):
    """Isotropic material: moduli [Pa], density [kg/m³], structural loss factor [-]."""

    kind: Literal["isotropic"]
    E: Positive
    G: Positive
    density: Positive
    loss_factor: LossFactor = 0.0

    @model_validator(mode="after")
    def _check(self) -> Isotropic:
        problems = _Problems()
        if not self.poisson_ratio <= 0.5:
            problems.add(
                ("G",),
                f"gives Poisson ratio E/(2G) - 1 = {_g(self.poisson_ratio)}, outside (-1, 0.5] "
                f"(got {format_value(self.G)}; allowed: G >= E/3 = {_g(self.E / 3.0)} Pa)",
            )
        problems.raise_if_any()
        return self

    @property
    def poisson_ratio(self) -> float:
        """ν = E/(2G) − 1 [-]."""
        return self.E / (2.0 * self.G) - 1.0


Material = Annotated[Union[Lamina, Isotropic], Field(discriminator="kind")]


# ------------------------------------------------------------------------------------------------
# Shaft and tailboom


class Shaft(_Model):
    """One-piece drive shaft: geometry [m], material reference, layup [deg], end conditions."""

    x_start: Finite
    x_end: Finite
    outer_diameter: Positive
    wall_thickness: Positive
    material: Name
    layup: str | None = None
    fixed_start: tuple[DofName, ...] = ()
    fixed_end: tuple[DofName, ...] = ()
    shear_deformation: StrictBool = False

    @field_validator("layup", mode="after")
    @classmethod
    def _parse_layup(cls, layup: str | None) -> str | None:
        if layup is not None:
            try:
                parse_layup_degrees(layup)
            except LayupError as error:
                raise PydanticCustomError(LAYUP_ERROR_TYPE, "{reason}", {"reason": str(error)}) from None
        return layup

    @model_validator(mode="after")
    def _check(self) -> Shaft:
        problems = _Problems()
        if not self.x_start < self.x_end:
            problems.add(
                ("x_end",),
                f"must be greater than x_start = {_g(self.x_start)} m (got {format_value(self.x_end)})",
            )
        if not self.wall_thickness < self.outer_diameter / 2.0:
            problems.add(
                ("wall_thickness",),
                f"must be less than outer_diameter/2 = {_g(self.outer_diameter / 2.0)} m "
                f"(got {format_value(self.wall_thickness)})",
            )
        for field in ("fixed_start", "fixed_end"):
            dofs: tuple[str, ...] = getattr(self, field)
            if len(set(dofs)) != len(dofs):
                problems.add((field,), f"lists a degree of freedom twice (got {format_value(list(dofs))})")
        problems.raise_if_any()
        return self

    @property
    def ply_angles_deg(self) -> tuple[float, ...]:
        """Ply angles [deg] from the shaft axis, inner ply first; empty for isotropic shafts."""
        return () if self.layup is None else parse_layup_degrees(self.layup)

    @property
    def inner_diameter(self) -> float:
        """D_i = D_o − 2t [m]."""
        return self.outer_diameter - 2.0 * self.wall_thickness

    @property
    def length(self) -> float:
        """x_end − x_start [m]."""
        return self.x_end - self.x_start


class EndMass(_Model):
    """Lumped tail mass [kg] at ``offset`` (x, y, z) [m] from the boom tip, own inertia [kg m²]."""

    mass: NonNegative
    offset: Vector3
    inertia: NonNegativeVector3 = _ZERO3


class Tailboom(_Model):
    """Tapered thin-walled elliptical cantilever from the fuselage (x = 0) to ``length`` [m].

    Semi-axes are [vertical, lateral] [m], tapering linearly from root to tip.
    """

    length: Positive
    root_semi_axes: SemiAxes
    tip_semi_axes: SemiAxes
    wall_thickness: Positive
    material: Name
    shaft_clearance: NonNegative
    end_mass: EndMass | None = None

    @model_validator(mode="after")
    def _check(self) -> Tailboom:
        problems = _Problems()
        smallest = min(*self.root_semi_axes, *self.tip_semi_axes)
        if not self.wall_thickness < smallest:
            problems.add(
                ("wall_thickness",),
                f"must be less than the smallest semi-axis {_g(smallest)} m "
                f"(got {format_value(self.wall_thickness)})",
            )
        problems.raise_if_any()
        return self

    def semi_axes_at(self, x: float) -> tuple[float, float]:
        """Linearly tapered (vertical, lateral) semi-axes [m] at station ``x`` [m]."""
        fraction = x / self.length
        return (
            self.root_semi_axes[0] + fraction * (self.tip_semi_axes[0] - self.root_semi_axes[0]),
            self.root_semi_axes[1] + fraction * (self.tip_semi_axes[1] - self.root_semi_axes[1]),
        )

    def shaft_offset_at(self, x: float) -> float:
        """Default shaft-to-boom neutral-axis offset h = vertical semi-axis + clearance [m]."""
        return self.semi_axes_at(x)[0] + self.shaft_clearance


# ------------------------------------------------------------------------------------------------
# Bearings and disks


class _BearingBase(_Model):
    name: Name
    x: Finite
    x_boom: Finite | None = None
    offset: NonNegative | None = None

    @property
    def boom_x(self) -> float:
        """Boom station [m] the bearing attaches to (``x_boom``, defaulting to ``x``)."""
        return self.x if self.x_boom is None else self.x_boom


class ContactBearing(_BearingBase):
    """Hanger (contact) bearing: springs and dashpots between shaft point x and boom point."""

    kind: Literal["contact"]
    stiffness: dict[BearingDirection, NonNegative]
    damping: dict[BearingDirection, NonNegative] | None = None

    def stiffness_of(self, direction: BearingDirection) -> float:
        """Stiffness in one direction [N/m for u, v, w; N m/rad for beta, gamma]; omitted = 0."""
        return self.stiffness.get(direction, 0.0)

    def damping_of(self, direction: BearingDirection) -> float:
        """Viscous damping in one direction [N s/m; N m s/rad]; omitted = 0."""
        return 0.0 if self.damping is None else self.damping.get(direction, 0.0)


class Controller(_Model):
    """Transfer function C(s) = numerator(s)/denominator(s), coefficients highest power first."""

    numerator: Coefficients
    denominator: Coefficients

    @model_validator(mode="after")
    def _check(self) -> Controller:
        problems = _Problems()
        if self.denominator[0] == 0.0:
            problems.add(
                ("denominator",),
                f"leading coefficient must be non-zero (got {format_value(list(self.denominator))})",
            )
        elif self.numerator_degree > len(self.denominator) - 1:
            problems.add(
                ("numerator",),
                f"degree {self.numerator_degree} exceeds the denominator degree "
                f"{len(self.denominator) - 1}; C(s) must be proper (got {format_value(list(self.numerator))})",
            )
        problems.raise_if_any()
        return self

    @property
    def numerator_degree(self) -> int:
        """Degree of the numerator after dropping leading zeros (−1 for C = 0)."""
        nonzero = [index for index, value in enumerate(self.numerator) if value != 0.0]
        return len(self.numerator) - 1 - nonzero[0] if nonzero else -1


class ActiveBearing(_BearingBase):
    """Active magnetic bearing on the lateral relative displacement d.

    Either a PD law f = −kp d − kd ḋ (kp [N/m], kd [N s/m], kd defaults to 0) or a general
    ``controller`` transfer function C(s) [N/m] replacing kp and kd.
    """

    kind: Literal["active"]
    kp: NonNegative | None = None
    kd: NonNegative | None = None
    controller: Controller | None = None

    @model_validator(mode="before")
    @classmethod
    def _default_kd(cls, data: Any) -> Any:
        if isinstance(data, dict) and data.get("controller") is None and data.get("kd") is None:
            return {**data, "kd": 0.0}
        return data

    @model_validator(mode="after")
    def _check(self) -> ActiveBearing:
        problems = _Problems()
        if self.controller is not None:
            for field in ("kp", "kd"):
                value = getattr(self, field)
                if value is not None:
                    problems.add(
                        (field,),
                        f"must be omitted when a controller is given (got {format_value(value)})",
                    )
        elif self.kp is None:
            problems.add(("kp",), "required key is missing (give kp [N/m], or a controller)")
        problems.raise_if_any()
        return self

    def transfer_function(self) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """(numerator, denominator) of C(s), highest power first; PD gives (kd, kp)/(1)."""
        if self.controller is not None:
            return self.controller.numerator, self.controller.denominator
        assert self.kp is not None and self.kd is not None
        return (self.kd, self.kp), (1.0,)


Bearing = Annotated[Union[ContactBearing, ActiveBearing], Field(discriminator="kind")]


class Disk(_Model):
    """Rigid disk on the shaft at ``x`` [m]: mass [kg], diametral and polar inertia [kg m²]."""

    name: Name
    x: Finite
    mass: NonNegative
    diametral_inertia: NonNegative = 0.0
    polar_inertia: NonNegative = 0.0


# ------------------------------------------------------------------------------------------------
# Operating point, loads, mesh


class Operating(_Model):
    """Operating point: exactly one of ``speed_rpm`` [rev/min] or ``speed`` [rad/s]; power [W]."""

    speed_rpm: NonNegative | None = None
    speed: NonNegative | None = None
    power: NonNegative

    @model_validator(mode="after")
    def _check(self) -> Operating:
        problems = _Problems()
        if (self.speed_rpm is None) == (self.speed is None):
            given = "both are given" if self.speed_rpm is not None else "neither is given"
            problems.add(
                ("speed_rpm",),
                f"give exactly one of speed_rpm [rev/min] or speed [rad/s] ({given}; "
                f"got speed_rpm = {format_value(self.speed_rpm)}, speed = {format_value(self.speed)})",
            )
        elif self.speed_rad_s == 0.0 and self.power > 0.0:
            problems.add(
                ("power",),
                f"must be 0 when the speed is 0, the torque P/Ω would be infinite "
                f"(got {format_value(self.power)})",
            )
        problems.raise_if_any()
        return self

    @property
    def speed_rad_s(self) -> float:
        """Shaft speed Ω [rad/s]."""
        if self.speed is not None:
            return self.speed
        assert self.speed_rpm is not None
        return rpm_to_rad_s(self.speed_rpm)

    @property
    def torque(self) -> float:
        """Transmitted torque T = P/Ω [N m] (0 at standstill)."""
        return 0.0 if self.speed_rad_s == 0.0 else self.power / self.speed_rad_s


class PointLoad(_Model):
    """Static point force [N] and moment [N m] (x, y, z) on the end mass, boom or shaft at x [m]."""

    name: Name
    on: Literal["end_mass", "boom", "shaft"]
    x: Finite | None = None
    force: Vector3
    moment: Vector3 = _ZERO3

    @model_validator(mode="after")
    def _check(self) -> PointLoad:
        problems = _Problems()
        if self.on == "end_mass" and self.x is not None:
            problems.add(("x",), f'must be omitted for on = "end_mass" (got {format_value(self.x)})')
        elif self.on != "end_mass" and self.x is None:
            problems.add(("x",), f'required key is missing (the station [m] on the {self.on})')
        problems.raise_if_any()
        return self


class LineLoad(_Model):
    """Uniform static line load [N/m] (x, y, z) on the boom or shaft between x_start and x_end [m]."""

    name: Name
    on: Literal["boom", "shaft"]
    x_start: Finite
    x_end: Finite
    force_per_length: Vector3

    @model_validator(mode="after")
    def _check(self) -> LineLoad:
        problems = _Problems()
        if not self.x_start < self.x_end:
            problems.add(
                ("x_end",),
                f"must be greater than x_start = {_g(self.x_start)} m (got {format_value(self.x_end)})",
            )
        problems.raise_if_any()
        return self


class Loads(_Model):
    """Imbalance (eccentricity [m]), manoeuvre load factor [g] and static external loads."""

    eccentricity: NonNegative = 0.0
    imbalance_placement: ImbalancePlacement = "mid_bay"
    load_factor: Vector3 = _ZERO3
    point: tuple[PointLoad, ...] = ()
    line: tuple[LineLoad, ...] = ()


class Mesh(_Model):
    """Approximate element counts; nodes are always placed at bearings and disks."""

    shaft_elements: ElementCount = 36
    boom_elements: ElementCount = 24


# ------------------------------------------------------------------------------------------------
# The design


class Design(_Model):
    """A complete driveline design, as read from a TOML design file."""

    name: str = Field(strict=True)
    materials: dict[str, Material]
    shaft: Shaft
    tailboom: Tailboom | None = None
    bearings: tuple[Bearing, ...] = Field(min_length=1)
    disks: tuple[Disk, ...] = ()
    operating: Operating
    loads: Loads = Loads()
    mesh: Mesh = Mesh()

    @model_validator(mode="after")
    def _check(self) -> Design:
        problems = _Problems()
        self._check_materials(problems)
        self._check_bearings(problems)
        self._check_disks(problems)
        self._check_loads(problems)
        problems.raise_if_any()
        return self

    # -- cross-table checks ----------------------------------------------------------------------

    def _material_reference(self, problems: _Problems, path: Path, name: str) -> Lamina | Isotropic | None:
        material = self.materials.get(name)
        if material is None:
            allowed = ", ".join(format_value(key) for key in self.materials) or "none defined"
            message = f"names no material in [materials] (got {format_value(name)}; allowed: {allowed})"
            problems.add(path, message)
        return material

    def _check_materials(self, problems: _Problems) -> None:
        shaft_material = self._material_reference(problems, ("shaft", "material"), self.shaft.material)
        if isinstance(shaft_material, Lamina) and self.shaft.layup is None:
            problems.add(
                ("shaft", "layup"),
                f"required key is missing (the shaft material {format_value(self.shaft.material)} is a lamina)",
            )
        elif isinstance(shaft_material, Isotropic) and self.shaft.layup is not None:
            problems.add(
                ("shaft", "layup"),
                f"must be omitted for the isotropic material {format_value(self.shaft.material)} "
                f"(got {format_value(self.shaft.layup)})",
            )
        if self.tailboom is not None:
            boom_material = self._material_reference(
                problems, ("tailboom", "material"), self.tailboom.material
            )
            if isinstance(boom_material, Lamina):
                problems.add(
                    ("tailboom", "material"),
                    f'must name an isotropic material (got {format_value(self.tailboom.material)}, kind = "lamina")',
                )

    def _shaft_range(self) -> str:
        return f"[{_g(self.shaft.x_start)}, {_g(self.shaft.x_end)}] m"

    def _on_shaft(self, x: float) -> bool:
        return self.shaft.x_start <= x <= self.shaft.x_end

    def _on_boom(self, x: float) -> bool:
        return self.tailboom is not None and 0.0 <= x <= self.tailboom.length

    def _boom_range(self) -> str:
        assert self.tailboom is not None
        return f"[0, {_g(self.tailboom.length)}] m"

    def _check_bearings(self, problems: _Problems) -> None:
        _check_unique(problems, ("bearings",), [bearing.name for bearing in self.bearings])
        for index, bearing in enumerate(self.bearings):
            if not self._on_shaft(bearing.x):
                problems.add(
                    ("bearings", index, "x"),
                    f"{format_value(bearing.x)} is outside the shaft {self._shaft_range()}",
                )
            if self.tailboom is None:
                for field in ("x_boom", "offset"):
                    value = getattr(bearing, field)
                    if value is not None:
                        problems.add(
                            ("bearings", index, field),
                            f"must be omitted when the design has no [tailboom] (got {format_value(value)})",
                        )
            elif not self._on_boom(bearing.boom_x) and (
                bearing.x_boom is not None or self._on_shaft(bearing.x)  # else reported as off the shaft
            ):
                field = "x" if bearing.x_boom is None else "x_boom"
                note = "" if bearing.x_boom is not None else " (x_boom defaults to x; give x_boom)"
                problems.add(
                    ("bearings", index, field),
                    f"boom station {format_value(bearing.boom_x)} is outside the tailboom "
                    f"{self._boom_range()}{note}",
                )

    def _check_disks(self, problems: _Problems) -> None:
        _check_unique(problems, ("disks",), [disk.name for disk in self.disks])
        for index, disk in enumerate(self.disks):
            if not self._on_shaft(disk.x):
                problems.add(
                    ("disks", index, "x"), f"{format_value(disk.x)} is outside the shaft {self._shaft_range()}"
                )

    def _check_station(self, problems: _Problems, path: Path, on: str, x: float) -> None:
        if on == "shaft" and not self._on_shaft(x):
            problems.add(path, f"{format_value(x)} is outside the shaft {self._shaft_range()}")
        elif on == "boom" and self.tailboom is not None and not self._on_boom(x):
            problems.add(path, f"{format_value(x)} is outside the tailboom {self._boom_range()}")

    def _check_loads(self, problems: _Problems) -> None:
        _check_unique(problems, ("loads", "point"), [load.name for load in self.loads.point])
        _check_unique(problems, ("loads", "line"), [load.name for load in self.loads.line])
        for index, point in enumerate(self.loads.point):
            path: Path = ("loads", "point", index)
            if point.on == "end_mass" and (self.tailboom is None or self.tailboom.end_mass is None):
                problems.add(path + ("on",), 'is "end_mass" but the design has no [tailboom.end_mass]')
            elif point.on == "boom" and self.tailboom is None:
                problems.add(path + ("on",), 'is "boom" but the design has no [tailboom]')
            elif point.x is not None:
                self._check_station(problems, path + ("x",), point.on, point.x)
        for index, line in enumerate(self.loads.line):
            path = ("loads", "line", index)
            if line.on == "boom" and self.tailboom is None:
                problems.add(path + ("on",), 'is "boom" but the design has no [tailboom]')
                continue
            self._check_station(problems, path + ("x_start",), line.on, line.x_start)
            self._check_station(problems, path + ("x_end",), line.on, line.x_end)

    # -- convenience -----------------------------------------------------------------------------

    @property
    def shaft_material(self) -> Lamina | Isotropic:
        """The material the shaft is made of."""
        return self.materials[self.shaft.material]

    @property
    def tailboom_material(self) -> Isotropic | None:
        """The (isotropic) tailboom material, or None without a tailboom."""
        if self.tailboom is None:
            return None
        material = self.materials[self.tailboom.material]
        assert isinstance(material, Isotropic)
        return material

    def bearing(self, name: str) -> ContactBearing | ActiveBearing:
        """The bearing called ``name``."""
        for bearing in self.bearings:
            if bearing.name == name:
                return bearing
        raise KeyError(name)
