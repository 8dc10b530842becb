"""Structural components of the design file: the shaft, the tailboom and disks (bearings in
:mod:`flexshaft.design.bearings`, re-exported here).

Geometry in [m], masses [kg], inertias [kg m²], stiffness [N/m, N m/rad], damping [N s/m,
N m s/rad]. The shaft layup is kept as the user's string; it is parsed (and refused with the
reason when malformed) by :func:`flexshaft.design.layup.parse_layup`, the one layup parser of the
package, and expanded to ply angles [deg] by :attr:`Shaft.ply_angles_deg`.
"""

from __future__ import annotations

from typing import Annotated

from pydantic import Field, StrictBool, field_validator, model_validator

from flexshaft.design.bearings import ActiveBearing, Bearing, ContactBearing, Controller  # re-exported
from flexshaft.design.fields import (
    ZERO3,
    DofName,
    FrozenModel,
    Name,
    Problems,
    SemiAxes,
    check_interval,
    check_unique,
    format_number,
    format_value,
)
from flexshaft.design.layup import parse_layup
from flexshaft.design.quantities import (
    MAX_LAYUP_LENGTH,
    MIN_SHAFT_LENGTH,
    Clearance,
    Coordinate,
    Diameter,
    Inertia,
    Mass,
    MemberLength,
    Station,
    WallThickness,
)
from flexshaft.design.segments import MAX_SEGMENTS, ShaftSegment, Tube, check_layup

#: The ply layup as written in the design file (parsed by :func:`~flexshaft.design.layup.parse_layup`).
Layup = Annotated[
    str,
    Field(
        strict=True,
        max_length=MAX_LAYUP_LENGTH,
        description=f"ply layup in degrees, e.g. (55/-55/0/0)s; at most {MAX_LAYUP_LENGTH} characters",
    ),
]

__all__ = ["ActiveBearing", "Bearing", "ContactBearing", "Controller", "Disk", "EndMass", "Shaft", "Tailboom"]

# ------------------------------------------------------------------------------------------------
# Shaft and tailboom


class Shaft(FrozenModel):
    """Drive shaft: geometry [m], material reference, layup [deg], end conditions.

    One tube, or the zones of ``segments`` (:class:`~flexshaft.design.segments.ShaftSegment`)
    whose missing values default to this table's; :attr:`tubes` gives every zone resolved.

    Attributes
    ----------
    x_start : float
        Station of the forward end [m] on the driveline axis (x = 0 at the boom root).
    x_end : float
        Station of the aft end [m]; greater than ``x_start``.
    outer_diameter : float
        Outer diameter D_o [m].
    wall_thickness : float
        Wall thickness t [m]; less than D_o/2 (a tube of inner diameter D_o − 2t).
    material : str
        Name of a ``[materials.<name>]`` table: a lamina (``layup`` required) or an isotropic
        material (``layup`` omitted).
    layup : str or None
        Ply angles [deg] from the shaft axis, inner ply first, in stacking notation such as
        ``"(55/-55/0/0)s"`` (groups, repeats, ``s`` for symmetric, ``±45``).
    fixed_start : tuple of str
        Degrees of freedom held at the forward end node: any of ``u``, ``v``, ``w``, ``theta``,
        ``beta``, ``gamma`` (e.g. ``["theta"]``: a drive coupling that holds the twist only).
    fixed_end : tuple of str
        Degrees of freedom held at the aft end node.
    shear_deformation : bool
        Timoshenko shear deformation in the shaft elements; false gives Euler-Bernoulli
        elements, as in the thesis.
    segments : tuple of table
        ``[[shaft.segments]]``: zones of a segmented shaft, each with ``name``, ``x_start`` and
        ``x_end`` [m] (tiling the shaft in order) and optionally its own ``outer_diameter``,
        ``wall_thickness``, ``material`` and ``layup`` (defaults: this table's); omitted: one
        tube (docs/segmented-driveline.md).
    """

    x_start: Station
    x_end: Station
    outer_diameter: Diameter
    wall_thickness: WallThickness
    material: Name
    layup: Layup | None = None
    fixed_start: tuple[DofName, ...] = Field(default=(), max_length=6)
    fixed_end: tuple[DofName, ...] = Field(default=(), max_length=6)
    shear_deformation: StrictBool = False
    segments: tuple[ShaftSegment, ...] = Field(default=(), max_length=MAX_SEGMENTS)

    @field_validator("layup", mode="after")
    @classmethod
    def _parse_layup(cls, layup: str | None) -> str | None:
        return check_layup(layup)

    @model_validator(mode="after")
    def _check(self) -> Shaft:
        problems = Problems()
        if check_interval(problems, self.x_start, self.x_end) and not self.x_end - self.x_start >= MIN_SHAFT_LENGTH:
            problems.add(
                ("x_end",),
                f"gives a shaft length x_end - x_start = {format_number(self.x_end - self.x_start)} m "
                f"(got {format_value(self.x_end)}; allowed: at least {MIN_SHAFT_LENGTH:g} m)",
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
        if self.segments:
            self._check_segments(problems)
        problems.raise_if_any()
        return self

    def _check_segments(self, problems: Problems) -> None:
        """The segments tile [x_start, x_end] in order, with unique names and thin walls."""
        check_unique(problems, ("segments",), [segment.name for segment in self.segments])
        tol = 1e-9 * max(1.0, abs(self.x_end - self.x_start))
        expected, what = self.x_start, "shaft.x_start"
        for index, segment in enumerate(self.segments):
            if abs(segment.x_start - expected) > tol:
                problems.add(
                    ("segments", index, "x_start"),
                    f"must equal {what} = {format_number(expected)} m: the segments tile the shaft in order, "
                    f"without gap or overlap (got {format_value(segment.x_start)})",
                )
            expected, what = segment.x_end, f"the x_end of segment {format_value(segment.name)}"
        if self.segments and abs(self.segments[-1].x_end - self.x_end) > tol:
            problems.add(
                ("segments", len(self.segments) - 1, "x_end"),
                f"must equal shaft.x_end = {format_number(self.x_end)} m: the last segment ends the shaft "
                f"(got {format_value(self.segments[-1].x_end)})",
            )
        for index, tube in enumerate(self.tubes):
            if not tube.wall_thickness < tube.outer_diameter / 2.0:
                problems.add(
                    ("segments", index, "wall_thickness"),
                    f"must be less than outer_diameter/2 = {format_number(tube.outer_diameter / 2.0)} m "
                    f"(got {format_value(tube.wall_thickness)})",
                )

    @property
    def tubes(self) -> tuple[Tube, ...]:
        """Every zone of the shaft with the ``[shaft]`` defaults filled in (one without segments).

        A segment that names its own material takes its own layup (none for a metal); one that
        does not inherits both from ``[shaft]``.
        """
        if not self.segments:
            return (
                Tube(
                    name="shaft",
                    x_start=self.x_start,
                    x_end=self.x_end,
                    outer_diameter=self.outer_diameter,
                    wall_thickness=self.wall_thickness,
                    material=self.material,
                    layup=self.layup,
                ),
            )
        return tuple(
            Tube(
                name=s.name,
                x_start=s.x_start,
                x_end=s.x_end,
                outer_diameter=self.outer_diameter if s.outer_diameter is None else s.outer_diameter,
                wall_thickness=self.wall_thickness if s.wall_thickness is None else s.wall_thickness,
                material=self.material if s.material is None else s.material,
                layup=s.layup if (s.material is not None or s.layup is not None) else self.layup,
            )
            for s in self.segments
        )

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
    """Lumped tail mass [kg] at ``offset`` (x, y, z) [m] from the boom tip, own inertia [kg m²].

    Attributes
    ----------
    mass : float
        Mass of the tail (tail gearbox, tail rotor, fin) [kg], rigidly attached to the boom tip.
    offset : tuple of 3 floats
        Position (x, y, z) of its centre of mass from the boom's tip node [m].
    inertia : tuple of 3 floats
        Its own moments of inertia (I_xx, I_yy, I_zz) about its centre of mass [kg m²].
    """

    mass: Mass
    offset: tuple[Coordinate, Coordinate, Coordinate]
    inertia: tuple[Inertia, Inertia, Inertia] = ZERO3


class Tailboom(FrozenModel):
    """Tapered thin-walled elliptical cantilever from the fuselage (x = 0) to ``length`` [m].

    Semi-axes are [vertical, lateral] [m], tapering linearly from root to tip.

    Attributes
    ----------
    length : float
        Length of the boom from its clamped root at the fuselage (x = 0) to its tip [m].
    root_semi_axes : tuple of 2 floats
        Semi-axes (vertical, lateral) of the elliptical section at the root [m].
    tip_semi_axes : tuple of 2 floats
        Semi-axes (vertical, lateral) at the tip [m]; they vary linearly along the boom.
    wall_thickness : float
        Equivalent skin thickness [m]; less than the smallest semi-axis.
    material : str
        Name of an isotropic ``[materials.<name>]`` table.
    shaft_clearance : float
        Gap between the boom's top and the shaft axis [m]: a bearing's offset h defaults to the
        vertical semi-axis at its station plus this clearance.
    end_mass : table or None
        The lumped tail mass at the tip (``[tailboom.end_mass]``); none when omitted.
    """

    length: MemberLength
    root_semi_axes: SemiAxes
    tip_semi_axes: SemiAxes
    wall_thickness: WallThickness
    material: Name
    shaft_clearance: Clearance
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
# Disks


class Disk(FrozenModel):
    """Rigid disk on the shaft at ``x`` [m]: mass [kg], diametral and polar inertia [kg m²].

    Attributes
    ----------
    name : str
        Unique name of the disk.
    x : float
        Shaft station of the disk [m]; on the shaft (a node is placed there).
    mass : float
        Mass [kg].
    diametral_inertia : float
        Moment of inertia about a diameter through its centre, I_d [kg m²].
    polar_inertia : float
        Moment of inertia about the shaft axis, I_p [kg m²]; enters the gyroscopic matrix.
    """

    name: Name
    x: Station
    mass: Mass
    diametral_inertia: Inertia = 0.0
    polar_inertia: Inertia = 0.0
