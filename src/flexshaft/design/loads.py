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
    quantity_field,
)
from flexshaft.units import rad_s_to_rpm, rpm_to_rad_s

__all__ = ["MAX_SPEED_RPM", "LineLoad", "Loads", "Operating", "PointLoad"]

#: Highest shaft speed a design (or the CLI ``--speed-rpm``) may ask for [rev/min]. Tail-rotor
#: drivelines run at 3,000-8,000 rev/min and a 0.1 m shaft at 10^6 rev/min would have a surface
#: speed of 5 km/s; far larger values only overflow the gyroscopic matrix Ω G to inf/nan.
MAX_SPEED_RPM = 1.0e6
MainRotorSpeed = Annotated[
    float,
    quantity_field(
        "rpm", "main-rotor speed, up to 5000 rev/min (helicopter main rotors turn at 150-500)", gt=0.0, le=5000.0
    ),
]
BalanceGrade = Annotated[
    float,
    quantity_field(
        "mm/s",
        "ISO 21940-11 balance grade G above 0 and at most 4000 mm/s (the standard's coarsest is G 4000)",
        gt=0.0,
        le=4000.0,
    ),
]
SpeedFraction = Annotated[
    float,
    quantity_field(
        "-", "fraction of the operating speed above 0 and at most 10 (a speed range is a few % wide)", gt=0.0, le=10.0
    ),
]
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
    speed_range : tuple of 2 floats or None
        The operating speed range as fractions (lowest, highest) of the operating speed [-]
        (e.g. ``[0.95, 1.05]``); omitted: the operating speed alone. The torsional separation
        margins are taken over it, and a ``balance_grade`` is converted at its highest speed
        (the maximum service speed of ISO 21940-11).
    """

    speed_rpm: SpeedRpm | None = None
    speed: SpeedRadS | None = None
    power: Power
    main_rotor_speed_rpm: MainRotorSpeed | None = None
    main_rotor_blades: (
        Annotated[int, Field(strict=True, ge=1, le=12, description=("number of main-rotor blades N, 1 to 12"))] | None
    ) = None
    speed_range: tuple[SpeedFraction, SpeedFraction] | None = None

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
        if self.speed_range is not None and not self.speed_range[0] <= 1.0 <= self.speed_range[1]:
            problems.add(
                ("speed_range",),
                "must bracket the operating speed, lowest <= 1 <= highest (fractions of the operating "
                f"speed; got {format_value(list(self.speed_range))})",
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
    def rpm(self) -> float:
        """Shaft speed [rpm]: ``speed_rpm`` as written, else ``speed`` converted."""
        return self.speed_rpm if self.speed_rpm is not None else rad_s_to_rpm(self.speed_rad_s)

    @property
    def speed_limits(self) -> tuple[float, float]:
        """The lowest and highest operating speeds [rad/s] of :attr:`speed_range` (both the
        operating speed when it is omitted)."""
        low, high = (1.0, 1.0) if self.speed_range is None else self.speed_range
        return low * self.speed_rad_s, high * self.speed_rad_s

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
        Mass eccentricity e_c of the rotor [m] (the permissible residual specific unbalance
        e_per of ISO 21940-11): the rotating imbalance force e_c m Ω², m the mass of the whole
        balanced rotor (tubes, disks, coupling hubs: :func:`flexshaft.assembly.balance.rotating_mass`),
        is shared equally among the bays between bearings. Give this or ``balance_grade``.
    balance_grade : float or None
        Balance grade G of ISO 21940-11 [mm/s] (e.g. 6.3 for G 6.3) instead of
        ``eccentricity``: e_c = G/Ω_max with Ω_max the highest operating speed
        (``[operating] speed_range``); ``eccentricity`` is then 0 or omitted.
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
    balance_grade: BalanceGrade | None = None
    imbalance_placement: ImbalancePlacement = "mid_bay"
    load_factor: tuple[LoadFactor, LoadFactor, LoadFactor] = ZERO3
    point: tuple[PointLoad, ...] = Field(default=(), max_length=MAX_POINT_LOADS)
    line: tuple[LineLoad, ...] = Field(default=(), max_length=MAX_LINE_LOADS)

    @model_validator(mode="after")
    def _check(self) -> Loads:
        problems = Problems()
        if self.balance_grade is not None and self.eccentricity != 0.0:
            problems.add(
                ("balance_grade",),
                "give at most one of eccentricity [m] and balance_grade [mm/s] (eccentricity 0 or omitted) "
                f"(got eccentricity = {format_value(self.eccentricity)}, "
                f"balance_grade = {format_value(self.balance_grade)})",
            )
        problems.raise_if_any()
        return self
