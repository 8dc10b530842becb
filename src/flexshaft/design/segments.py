"""Segmented shafts and flexible couplings of the design file (``[[shaft.segments]]``, ``[[couplings]]``).

A driveline may be one tube (the ``[shaft]`` table alone: one segment) or several. Two
independent tables describe it:

* ``[[shaft.segments]]``: zones of the shaft with their own tube. Each gives its stations
  ``x_start`` and ``x_end`` [m] (the zones tile ``[shaft.x_start, shaft.x_end]`` without gap or
  overlap) and may override the tube of ``[shaft]``: ``outer_diameter`` [m],
  ``wall_thickness`` [m], ``material`` and ``layup`` [deg]. A segment that names its own
  ``material`` does not inherit the ``[shaft]`` layup (it gives one for a lamina, none for an
  isotropic metal). Two zones that meet without a coupling are bonded (a stepped tube).
* ``[[couplings]]``: flexible (disc or diaphragm) couplings. Each cuts the shaft at its
  station ``x`` [m] (strictly inside the shaft) into two pieces joined by the coupling:
  angular (bending) stiffness in both bending planes [N m/rad], axial [N/m], torsional
  [N m/rad] and lateral (radial) [N/m] stiffness, each a number or ``"rigid"``; hub mass [kg]
  and inertias [kg m²]; and the allowable misalignment angle [deg] of the verdict.

The shaft tables' ``[shaft]`` values are the defaults of every segment, so an existing design
file (no segments, no couplings) is one segment with the same numbers as before.
"""

from __future__ import annotations

from typing import Annotated, Final, Literal

from pydantic import Field, field_validator, model_validator
from pydantic_core import PydanticCustomError

from flexshaft.design.fields import LAYUP_ERROR_TYPE, FrozenModel, Name, Problems, check_interval
from flexshaft.design.layup import parse_layup
from flexshaft.design.quantities import (
    MAX_LAYUP_LENGTH,
    Diameter,
    Inertia,
    Mass,
    Station,
    Stiffness,
    WallThickness,
    quantity_field,
)

__all__ = [
    "MAX_COUPLINGS",
    "MAX_SEGMENTS",
    "RIGID",
    "Coupling",
    "CouplingStiffness",
    "ShaftSegment",
    "Tube",
    "check_layup",
]

#: The value of a coupling stiffness that makes the joint rigid in that direction.
RIGID: Final = "rigid"
#: Most entries of ``[[shaft.segments]]`` and of ``[[couplings]]``.
MAX_SEGMENTS = 256
MAX_COUPLINGS = 255

#: A coupling stiffness: a number [N/m or N m/rad] in [0, 1e12], or ``"rigid"``.
CouplingStiffness = Stiffness | Literal["rigid"]
#: A torsional stiffness must carry the torque: > 0 or ``"rigid"``.
TorsionalStiffness = (
    Annotated[
        float,
        quantity_field(
            "N m/rad", "torsional stiffness above 0 and at most 1e12 N m/rad (it carries the torque)", gt=0.0, le=1e12
        ),
    ]
    | Literal["rigid"]
)
#: An allowable misalignment angle [deg], in (0, 90).
Angle = Annotated[float, quantity_field("deg", "misalignment angle above 0 and below 90 deg", gt=0.0, lt=90.0)]
#: A layup string, as ``[shaft] layup``.
Layup = Annotated[
    str,
    Field(
        strict=True,
        max_length=MAX_LAYUP_LENGTH,
        description=f"ply layup in degrees, e.g. (55/-55/0/0)s; at most {MAX_LAYUP_LENGTH} characters",
    ),
]


def check_layup(layup: str | None) -> str | None:
    """Validate a layup string with the package's one parser (pydantic error with the reason)."""
    if layup is not None:
        try:
            parse_layup(layup)
        except ValueError as error:  # "<reason>; allowed: <forms>"
            reason, _, allowed = str(error).partition("; allowed: ")
            raise PydanticCustomError(LAYUP_ERROR_TYPE, "{reason}", {"reason": reason, "allowed": allowed}) from None
    return layup


class ShaftSegment(FrozenModel):
    """One zone of a segmented shaft, ``[[shaft.segments]]``: stations [m] and optional tube overrides.

    Attributes
    ----------
    name : str
        Unique name of the segment (results and messages use it).
    x_start : float
        Forward end [m]: ``shaft.x_start`` for the first segment, the previous segment's
        ``x_end`` for the others.
    x_end : float
        Aft end [m]; greater than ``x_start``; the last segment ends at ``shaft.x_end``.
    outer_diameter : float or None
        Outer diameter D_o [m]; omitted: the ``[shaft]`` value.
    wall_thickness : float or None
        Wall thickness t [m], less than D_o/2; omitted: the ``[shaft]`` value.
    material : str or None
        Name of a ``[materials.<name>]`` table; omitted: the ``[shaft]`` material (and layup).
    layup : str or None
        Ply angles [deg], inner ply first, as in ``[shaft]``; required for a lamina material of
        its own, omitted for an isotropic one; omitted with no material: the ``[shaft]`` layup.
    """

    name: Name
    x_start: Station
    x_end: Station
    outer_diameter: Diameter | None = None
    wall_thickness: WallThickness | None = None
    material: Name | None = None
    layup: Layup | None = None

    @field_validator("layup", mode="after")
    @classmethod
    def _parse_layup(cls, layup: str | None) -> str | None:
        return check_layup(layup)

    @model_validator(mode="after")
    def _check(self) -> ShaftSegment:
        problems = Problems()
        check_interval(problems, self.x_start, self.x_end)
        problems.raise_if_any()
        return self


class Tube(FrozenModel):
    """A segment with every value resolved (the ``[shaft]`` defaults filled in)."""

    name: str
    x_start: float
    x_end: float
    outer_diameter: float
    wall_thickness: float
    material: str
    layup: str | None

    @property
    def length(self) -> float:
        """x_end − x_start [m]."""
        return self.x_end - self.x_start

    @property
    def inner_diameter(self) -> float:
        """D_o − 2t [m]."""
        return self.outer_diameter - 2.0 * self.wall_thickness

    @property
    def ply_angles_deg(self) -> tuple[float, ...]:
        """Ply angles [deg], inner ply first; empty for an isotropic tube."""
        return () if self.layup is None else parse_layup(self.layup)


class Coupling(FrozenModel):
    """Flexible coupling joining the two shaft pieces at station ``x`` [m].

    Stiffness between the two coupling flanges (each a number or ``"rigid"``):
    ``angular_stiffness`` [N m/rad] about each bending axis (the disc pack's bending),
    ``axial_stiffness`` [N/m], ``torsional_stiffness`` [N m/rad] (> 0: it carries the torque)
    and ``lateral_stiffness`` [N/m] (radial; default rigid: a disc coupling is a hinge, not a
    slider). The hub (flanges, disc pack, bolts) is ``mass`` [kg] with ``diametral_inertia``
    and ``polar_inertia`` [kg m²], shared equally by the two flanges. ``allowable_angle_deg``
    [deg] is the continuous misalignment the coupling is rated for (checked by the verdict).

    Attributes
    ----------
    name : str
        Unique name of the coupling (results and messages use it).
    x : float
        Station of the joint [m], strictly inside the shaft; no bearing or disk at it.
    angular_stiffness : float or "rigid"
        Bending stiffness between the flanges about each bending axis [N m/rad].
    axial_stiffness : float or "rigid"
        Axial stiffness between the flanges [N/m].
    torsional_stiffness : float or "rigid"
        Torsional stiffness between the flanges [N m/rad]; greater than 0.
    lateral_stiffness : float or "rigid"
        Radial (lateral) stiffness between the flanges [N/m]; default rigid.
    mass : float
        Hub mass [kg] (flanges, disc pack, bolts), half on each flange; also its mass in the
        mass breakdown.
    diametral_inertia : float
        Hub diametral moment of inertia [kg m²].
    polar_inertia : float
        Hub polar moment of inertia [kg m²].
    allowable_angle_deg : float or None
        Allowable continuous misalignment angle [deg], in (0, 90); omitted: not checked.
    """

    name: Name
    x: Station
    angular_stiffness: CouplingStiffness
    axial_stiffness: CouplingStiffness
    torsional_stiffness: TorsionalStiffness
    lateral_stiffness: CouplingStiffness = RIGID
    mass: Mass = 0.0
    diametral_inertia: Inertia = 0.0
    polar_inertia: Inertia = 0.0
    allowable_angle_deg: Angle | None = None
