"""Structural components of the design file: the shaft, the tailboom, bearings and disks.

Geometry in [m], masses [kg], inertias [kg m²], stiffness [N/m, N m/rad], damping [N s/m,
N m s/rad]. The shaft layup is kept as the user's string; it is parsed (and refused with the
reason when malformed) by :func:`flexshaft.laminate.parse_layup`, the one layup parser of the
package, and expanded to ply angles [deg] by :attr:`Shaft.ply_angles_deg`.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

from pydantic import Field, StrictBool, field_validator, model_validator
from pydantic_core import PydanticCustomError

from flexshaft.design.fields import (
    LAYUP_ERROR_TYPE,
    ZERO3,
    BearingDirection,
    Coefficients,
    DofName,
    Finite,
    FrozenModel,
    Name,
    NonNegative,
    NonNegativeVector3,
    Positive,
    Problems,
    SemiAxes,
    Vector3,
    format_number,
    format_value,
)
from flexshaft.laminate import parse_layup

__all__ = [
    "ActiveBearing",
    "Bearing",
    "ContactBearing",
    "Controller",
    "Disk",
    "EndMass",
    "Shaft",
    "Tailboom",
]

# ------------------------------------------------------------------------------------------------
# Shaft and tailboom


class Shaft(FrozenModel):
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
                parse_layup(layup)
            except ValueError as error:  # "<reason>; allowed: <forms>"
                reason, _, allowed = str(error).partition("; allowed: ")
                context = {"reason": reason, "allowed": allowed}
                raise PydanticCustomError(LAYUP_ERROR_TYPE, "{reason}", context) from None
        return layup

    @model_validator(mode="after")
    def _check(self) -> Shaft:
        problems = Problems()
        if not self.x_start < self.x_end:
            problems.add(
                ("x_end",),
                f"must be greater than x_start = {format_number(self.x_start)} m (got {format_value(self.x_end)})",
            )
        if not self.wall_thickness < self.outer_diameter / 2.0:
            problems.add(
                ("wall_thickness",),
                f"must be less than outer_diameter/2 = {format_number(self.outer_diameter / 2.0)} m "
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
        return () if self.layup is None else parse_layup(self.layup)

    @property
    def inner_diameter(self) -> float:
        """D_i = D_o − 2t [m]."""
        return self.outer_diameter - 2.0 * self.wall_thickness

    @property
    def length(self) -> float:
        """x_end − x_start [m]."""
        return self.x_end - self.x_start


class EndMass(FrozenModel):
    """Lumped tail mass [kg] at ``offset`` (x, y, z) [m] from the boom tip, own inertia [kg m²]."""

    mass: NonNegative
    offset: Vector3
    inertia: NonNegativeVector3 = ZERO3


class Tailboom(FrozenModel):
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
        problems = Problems()
        smallest = min(*self.root_semi_axes, *self.tip_semi_axes)
        if not self.wall_thickness < smallest:
            problems.add(
                ("wall_thickness",),
                f"must be less than the smallest semi-axis {format_number(smallest)} m "
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


class _BearingBase(FrozenModel):
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


class Controller(FrozenModel):
    """Transfer function C(s) = numerator(s)/denominator(s), coefficients highest power first."""

    numerator: Coefficients
    denominator: Coefficients

    @model_validator(mode="after")
    def _check(self) -> Controller:
        problems = Problems()
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
    ``controller`` transfer function C(s) [N/m] replacing kp and kd. Optional limits checked by
    the requirements verdict: ``gap``, the radial clearance of the auxiliary (backup) bearing
    [m], and ``force_capacity``, the largest force the actuator can produce [N].
    """

    kind: Literal["active"]
    kp: NonNegative | None = None
    kd: NonNegative | None = None
    controller: Controller | None = None
    gap: Positive | None = None
    force_capacity: Positive | None = None

    @model_validator(mode="before")
    @classmethod
    def _default_kd(cls, data: Any) -> Any:
        if isinstance(data, dict) and data.get("controller") is None and data.get("kd") is None:
            return {**data, "kd": 0.0}
        return data

    @model_validator(mode="after")
    def _check(self) -> ActiveBearing:
        problems = Problems()
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


class Disk(FrozenModel):
    """Rigid disk on the shaft at ``x`` [m]: mass [kg], diametral and polar inertia [kg m²]."""

    name: Name
    x: Finite
    mass: NonNegative
    diametral_inertia: NonNegative = 0.0
    polar_inertia: NonNegative = 0.0
