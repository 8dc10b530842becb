"""Operating point and static loads of the design file: ``[operating]`` and ``[loads]``.

Speeds in [rad/s] inside; ``speed_rpm`` [rev/min] is converted by :attr:`Operating.speed_rad_s`.
Power [W], torque [N m], eccentricity [m], forces [N], moments [N m], line loads [N/m] and load
factors [g].
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from flexshaft.design.fields import (
    ZERO3,
    FrozenModel,
    ImbalancePlacement,
    Name,
    Problems,
    check_interval,
    format_number,
    format_value,
)
from flexshaft.design.quantities import (
    MAX_LINE_LOADS,
    MAX_POINT_LOADS,
    MAX_TORQUE,
    Eccentricity,
    Force,
    ForcePerLength,
    LoadFactor,
    Moment,
    Power,
    Station,
    quantity,
)
from flexshaft.units import rpm_to_rad_s

__all__ = ["MAX_SPEED_RPM", "LineLoad", "Loads", "Operating", "PointLoad"]

#: Highest shaft speed a design (or the CLI ``--speed-rpm``) may ask for [rev/min]. Tail-rotor
#: drivelines run at 3,000-8,000 rev/min and a 0.1 m shaft at 10^6 rev/min would have a surface
#: speed of 5 km/s; far larger values only overflow the gyroscopic matrix Ω G to inf/nan.
MAX_SPEED_RPM = 1.0e6
MainRotorSpeed = quantity(
    "rpm", "main-rotor speed, up to 5000 rev/min (helicopter main rotors turn at 150-500)", gt=0.0, le=5000.0
)
SpeedRpm = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        ge=0.0,
        le=MAX_SPEED_RPM,
        description=("shaft speed from 0 to 1e6 rev/min (a 0.1 m shaft at 1e6 rev/min has a surface speed of 5 km/s)"),
        json_schema_extra={"unit": "rev/min"},
    ),
]
SpeedRadS = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        ge=0.0,
        le=rpm_to_rad_s(MAX_SPEED_RPM),
        description="shaft speed from 0 to 1e6 rev/min expressed in rad/s",
        json_schema_extra={"unit": "rad/s"},
    ),
]


class Operating(FrozenModel):
    """Operating point: exactly one of ``speed_rpm`` [rev/min] or ``speed`` [rad/s]; power [W].

    Attributes
    ----------
    speed_rpm : float or None
        Shaft speed at the operating point [rev/min]; give this or ``speed``.
    speed : float or None
        Shaft speed at the operating point [rad/s]; give this or ``speed_rpm``.
    power : float
        Power transmitted to the tail rotor [W]; the shaft carries the torque P/Ω (0 at rest).
    main_rotor_speed_rpm : float or None
        Main-rotor speed at the operating point [rev/min] (it is geared to the shaft, so it
        scales with the shaft speed); with ``main_rotor_blades`` it draws the main rotor's
        1/rev and N/rev excitation lines on the Campbell diagram, against which the tailboom
        modes are placed.
    main_rotor_blades : int or None
        Number of main-rotor blades N.
    """

    speed_rpm: SpeedRpm | None = None
    speed: SpeedRadS | None = None
    power: Power
    main_rotor_speed_rpm: MainRotorSpeed | None = None
    main_rotor_blades: (
        Annotated[int, Field(strict=True, ge=1, le=12, description=("number of main-rotor blades N, 1 to 12"))] | None
    ) = None

    def main_rotor_frequencies(self) -> dict[str, float]:
        """The main rotor's excitation frequencies at the operating point [Hz]: 1/rev and N/rev
        (empty when the main rotor is not given)."""
        if self.main_rotor_speed_rpm is None:
            return {}
        once = self.main_rotor_speed_rpm / 60.0
        out = {"1/rev": once}
        if self.main_rotor_blades and self.main_rotor_blades > 1:
            out[f"{self.main_rotor_blades}/rev"] = self.main_rotor_blades * once
        return out

    @model_validator(mode="after")
    def _check(self) -> Operating:
        problems = Problems()
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
                f"must be 0 when the speed is 0, the torque P/Ω would be infinite (got {format_value(self.power)})",
            )
        elif self.power > MAX_TORQUE * self.speed_rad_s:
            problems.add(
                ("power",),
                f"gives a torque P/Ω = {format_number(self.power / self.speed_rad_s)} N m at "
                f"Ω = {format_number(self.speed_rad_s)} rad/s (got {format_value(self.power)}; allowed: a torque of "
                f"at most {MAX_TORQUE:g} N m, i.e. power <= {format_number(MAX_TORQUE * self.speed_rad_s)} W)",
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


class PointLoad(FrozenModel):
    """Static point force [N] and moment [N m] (x, y, z) on the end mass, boom or shaft at x [m].

    Attributes
    ----------
    name : str
        Unique name of the load.
    on : {"end_mass", "boom", "shaft"}
        Where it acts: at the end mass's centre of mass, or on the boom or the shaft at ``x``.
    x : float or None
        Station [m] on the boom or shaft; omitted for ``on = "end_mass"``.
    force : tuple of 3 floats
        Force components (x, y, z) [N].
    moment : tuple of 3 floats
        Moment components about x, y, z [N m].
    """

    name: Name
    on: Literal["end_mass", "boom", "shaft"]
    x: Station | None = None
    force: tuple[Force, Force, Force]
    moment: tuple[Moment, Moment, Moment] = ZERO3

    @model_validator(mode="after")
    def _check(self) -> PointLoad:
        problems = Problems()
        if self.on == "end_mass" and self.x is not None:
            problems.add(("x",), f'must be omitted for on = "end_mass" (got {format_value(self.x)})')
        elif self.on != "end_mass" and self.x is None:
            problems.add(("x",), f"required key is missing (the station [m] on the {self.on})")
        problems.raise_if_any()
        return self


class LineLoad(FrozenModel):
    """Uniform static line load [N/m] (x, y, z) on the boom or shaft between x_start and x_end [m].

    Attributes
    ----------
    name : str
        Unique name of the load.
    on : {"boom", "shaft"}
        The member it acts on.
    x_start : float
        Station where the load begins [m].
    x_end : float
        Station where it ends [m]; greater than ``x_start``.
    force_per_length : tuple of 3 floats
        Force per unit length (x, y, z) [N/m].
    """

    name: Name
    on: Literal["boom", "shaft"]
    x_start: Station
    x_end: Station
    force_per_length: tuple[ForcePerLength, ForcePerLength, ForcePerLength]

    @model_validator(mode="after")
    def _check(self) -> LineLoad:
        problems = Problems()
        check_interval(problems, self.x_start, self.x_end)
        problems.raise_if_any()
        return self


class Loads(FrozenModel):
    """Imbalance (eccentricity [m]), manoeuvre load factor [g] and static external loads.

    Attributes
    ----------
    eccentricity : float
        Mass eccentricity e_c of the shaft [m]: the rotating imbalance force e_c m_s Ω² (m_s
        the shaft mass) is shared equally among the bays between bearings.
    imbalance_placement : {"mid_bay", "distributed", "worst"}
        Where each bay's imbalance acts: a point force at mid-bay, spread along the bay, or the
        worst in/anti-phase pattern of the mid-bay forces at each speed.
    load_factor : tuple of 3 floats
        Load factor (x, y, z) [g]: every mass m carries the static inertial force m·n·g, e.g.
        ``[0.0, -3.5, 0.0]`` loads the driveline 3.5 g downwards (gravity and manoeuvre).
    point : tuple of tables
        Static point loads (``[[loads.point]]``).
    line : tuple of tables
        Static uniform line loads (``[[loads.line]]``).
    """

    eccentricity: Eccentricity = 0.0
    imbalance_placement: ImbalancePlacement = "mid_bay"
    load_factor: tuple[LoadFactor, LoadFactor, LoadFactor] = ZERO3
    point: tuple[PointLoad, ...] = Field(default=(), max_length=MAX_POINT_LOADS)
    line: tuple[LineLoad, ...] = Field(default=(), max_length=MAX_LINE_LOADS)
