"""Bearings of the design file: contact (hanger) bearings and active magnetic bearings.

A contact bearing is a spring and damper per direction to the boom (or ground) at a station; an
active bearing adds the actuator's magnet (negative stiffness, saturation), its controller (PID
or a transfer function, amplifier lag) and its sensor station. Stiffness [N/m], damping
[N s/m], gains as in :mod:`flexshaft.design.quantities`.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import Field, model_validator

from flexshaft.design.fields import BearingDirection, Coefficients, FrozenModel, Name, Problems, format_value
from flexshaft.design.quantities import (
    AirGap,
    BackupGap,
    Clearance,
    CoilTurns,
    Coordinate,
    Current,
    CurrentGain,
    Damping,
    DerivativeGain,
    FilterFrequency,
    FluxDensity,
    ForceCapacity,
    IntegralGain,
    Mass,
    NegativeStiffness,
    PoleArea,
    ProportionalGain,
    Station,
    Stiffness,
)

__all__ = ["ActiveBearing", "Bearing", "ContactBearing", "Controller"]


class _BearingBase(FrozenModel):
    """Keys shared by both kinds of bearing.

    Attributes
    ----------
    name : str
        Unique name of the bearing (results and messages use it).
    x : float
        Shaft station of the bearing [m]; on the shaft.
    x_boom : float or None
        Boom station the bearing is mounted on [m]; defaults to ``x``. Only with a tailboom.
    offset : float or None
        Height h of the shaft axis above the boom's neutral axis at the mount [m]; defaults to
        the boom's vertical semi-axis there plus ``[tailboom] shaft_clearance``. Only with a
        tailboom (without one the bearing joins the shaft to the ground).
    mass : float
        Installed mass of the part [kg] (bearing, housing and bracket; magnet, rotor sleeve and
        sensors), for the mass breakdown of ``flexshaft compare`` only (not in the dynamics); 0
        when omitted.
    """

    name: Name
    x: Station
    x_boom: Station | None = None
    offset: Clearance | None = None
    mass: Mass = 0.0

    @property
    def boom_x(self) -> float:
        """Boom station [m] the bearing attaches to (``x_boom``, defaulting to ``x``)."""
        return self.x if self.x_boom is None else self.x_boom


class ContactBearing(_BearingBase):
    """Hanger (contact) bearing: springs and dashpots between shaft point x and boom point.

    Attributes
    ----------
    kind : {"contact"}
        Selects this kind of bearing.
    stiffness : dict of str to float
        Spring stiffness per relative-displacement direction ``u``, ``v``, ``w``, ``beta``,
        ``gamma`` [N/m; N m/rad for beta and gamma]; an omitted direction is free, e.g.
        ``{ v = 1.0e8, w = 1.0e8 }``.
    damping : dict of str to float or None
        Viscous damping per direction [N s/m; N m s/rad for beta and gamma]; omitted: none.
    role : {"hanger", "damper", "gearbox"}
        What the part is in the driveline: a bearing that supports the shaft (default), a shaft
        damper (spring and viscous damper to the boom), or the bearing of a gearbox that ends the
        driveline (not a driveline part). Only the part count and mass breakdown use it.
    """

    kind: Literal["contact"]
    role: Literal["hanger", "damper", "gearbox"] = "hanger"
    stiffness: dict[BearingDirection, Stiffness]
    damping: dict[BearingDirection, Damping] | None = None

    def stiffness_of(self, direction: BearingDirection) -> float:
        """Stiffness in one direction [N/m for u, v, w; N m/rad for beta, gamma]; omitted = 0."""
        return self.stiffness.get(direction, 0.0)

    def damping_of(self, direction: BearingDirection) -> float:
        """Viscous damping in one direction [N s/m; N m s/rad]; omitted = 0."""
        return 0.0 if self.damping is None else self.damping.get(direction, 0.0)


class Controller(FrozenModel):
    """Transfer function C(s) = numerator(s)/denominator(s), coefficients highest power first.

    Attributes
    ----------
    numerator : tuple of float
        Coefficients of the numerator polynomial in s (SI, s in rad/s), highest power first;
        C(s) gives the actuator current per metre of displacement (A/m; N/m with the default
        k_i = 1 N/A). At most 21 coefficients.
    denominator : tuple of float
        Coefficients of the denominator, highest power first; the leading one non-zero and the
        degree at least the numerator's (C(s) proper).
    """

    numerator: Coefficients
    denominator: Coefficients

    @model_validator(mode="after")
    def _check(self) -> Controller:
        problems = Problems()
        if self.denominator[0] == 0.0:
            problems.add(
                ("denominator",), f"leading coefficient must be non-zero (got {format_value(list(self.denominator))})"
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
    """Active magnetic bearing on the lateral relative displacement d (see docs/magnetic-bearings.md).

    Force on the shaft ``f = k_s d_a + k_i i`` (``d_a`` at the magnet, station ``x``), current
    ``i = −A(s) C(s) d_s`` (``d_s`` measured at ``x + sensor_offset``), amplifier lag
    ``A(s) = 1/(1 + s/ω_a)``. The thesis's ideal PD bearing ``f = −kp d − kd ḋ`` is the default
    case: ``ks = 0``, ``ki = 1``, no lag, collocated sensor.

    Controller C(s) (one of):

    * PD / PID: ``kp`` [N/m per k_i, i.e. A/m], ``kd`` [A s/m] (default 0), ``integral_gain``
      K_I [A/(m s)] (default 0), ``derivative_cutoff`` f_d [Hz] (default: ideal derivative):
      ``C(s) = kp + K_I/s + kd s/(1 + s/(2π f_d))``;
    * ``controller``: any proper transfer function (coefficients, highest power first).

    Magnet (defaults give the ideal actuator):

    * ``ks`` k_s [N/m] (default 0) and ``ki`` k_i [N/A] (default 1), given directly, or
    * computed from the magnet geometry (:mod:`flexshaft.elements.magnetic`): ``coil_turns``,
      ``pole_area`` [m²], ``bias_current`` [A], ``air_gap`` [m], ``pole_angle`` [deg]
      (default 22.5, an 8-pole stator);
    * ``saturation_flux_density`` B_sat [T] with ``pole_area`` gives the saturation force
      ``B_sat² A_a cos α/μ0`` of the built actuator (``Actuator.saturation_force``).

    ``amplifier_bandwidth`` [Hz] (default: ideal amplifier), ``sensor_offset`` [m] along the
    shaft from the magnet (default 0, collocated), ``air_gap`` g_0 [m] (nominal magnetic gap).

    Limits checked by the requirements verdict: ``gap``, the radial clearance of the auxiliary
    (backup) bearing [m], and ``force_capacity``, the largest force the actuator can produce
    [N] (when omitted, the saturation force of the magnet if its geometry is given).

    Attributes
    ----------
    kind : {"active"}
        Selects this kind of bearing.
    kp : float or None
        Proportional gain K_p [A/m] (N/m with the default k_i = 1); required unless
        ``controller`` is given.
    kd : float or None
        Derivative gain K_d [A s/m] (N s/m with k_i = 1); 0 when omitted without a controller.
    integral_gain : float or None
        Integral gain K_I [A/(m s)]; omitted: 0.
    derivative_cutoff : float or None
        Corner f_d of the derivative filter [Hz]; omitted: an ideal derivative.
    controller : table or None
        Any proper transfer function C(s) (``[bearings.controller]``); replaces ``kp``, ``kd``,
        ``integral_gain`` and ``derivative_cutoff``.
    gap : float or None
        Radial clearance of the auxiliary (backup) bearing [m], the limit of the actuator orbit
        in the requirements verdict; omitted: not checked.
    force_capacity : float or None
        Largest force the actuator can produce [N]; omitted: the magnet's saturation force when
        its geometry is given, else not checked.
    ks : float or None
        Negative (open-loop) stiffness k_s of the magnet [N/m]; omitted: 0, or computed from
        the magnet geometry.
    ki : float or None
        Current gain k_i of the magnet [N/A]; omitted: 1, or computed from the magnet geometry.
    amplifier_bandwidth : float or None
        Bandwidth f_a of the first-order current amplifier [Hz]; omitted: an ideal amplifier.
    sensor_offset : float
        Position of the displacement sensor along the shaft from the magnet [m]; 0 is
        collocated.
    air_gap : float or None
        Nominal magnetic air gap g_0 [m] (magnet geometry).
    bias_current : float or None
        Bias current i_0 [A] (magnet geometry).
    coil_turns : float or None
        Turns N of each coil [-] (magnet geometry).
    pole_area : float or None
        Pole face area A_a [m²] (magnet geometry, saturation force).
    pole_angle : float
        Angle α between a pole and the force axis [deg]; 22.5 is an 8-pole stator.
    saturation_flux_density : float or None
        Saturation flux density B_sat of the magnet iron [T]; with ``pole_area`` it gives the
        saturation force B_sat² A_a cos α/μ0.
    """

    kind: Literal["active"]
    kp: ProportionalGain | None = None
    kd: DerivativeGain | None = None
    integral_gain: IntegralGain | None = None
    derivative_cutoff: FilterFrequency | None = None
    controller: Controller | None = None
    gap: BackupGap | None = None
    force_capacity: ForceCapacity | None = None
    ks: NegativeStiffness | None = None
    ki: CurrentGain | None = None
    amplifier_bandwidth: FilterFrequency | None = None
    sensor_offset: Coordinate = 0.0
    air_gap: AirGap | None = None
    bias_current: Current | None = None
    coil_turns: CoilTurns | None = None
    pole_area: PoleArea | None = None
    pole_angle: Annotated[
        float,
        Field(
            strict=True,
            allow_inf_nan=False,
            ge=0.0,
            lt=90.0,
            description=("angle of the poles to the control axis, 0 to 90 deg"),
            json_schema_extra={"unit": "deg"},
        ),
    ] = 22.5
    saturation_flux_density: FluxDensity | None = None

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
            for field in ("kp", "kd", "integral_gain", "derivative_cutoff"):
                value = getattr(self, field)
                if value is not None:
                    problems.add((field,), f"must be omitted when a controller is given (got {format_value(value)})")
        elif self.kp is None:
            problems.add(("kp",), "required key is missing (give kp [N/m], or a controller)")
        if self.uses_magnet_geometry:
            for field in ("coil_turns", "pole_area", "bias_current", "air_gap"):
                if getattr(self, field) is None:
                    problems.add(
                        (field,),
                        "required key is missing (k_s and k_i from the magnet geometry need coil_turns, "
                        "pole_area, bias_current and air_gap)",
                    )
            for field in ("ks", "ki"):
                value = getattr(self, field)
                if value is not None:
                    problems.add(
                        (field,),
                        f"must be omitted when coil_turns/bias_current give the magnet geometry "
                        f"(it is computed from them; got {format_value(value)})",
                    )
        if self.saturation_flux_density is not None and self.pole_area is None:
            problems.add(
                ("pole_area",),
                "required key is missing (the saturation force B_sat² A_a cos α/μ0 needs pole_area with "
                "saturation_flux_density)",
            )
        problems.raise_if_any()
        return self

    @property
    def uses_magnet_geometry(self) -> bool:
        """True when k_s and k_i are computed from the magnet (coil_turns or bias_current given)."""
        return self.coil_turns is not None or self.bias_current is not None

    @property
    def sensor_x(self) -> float:
        """Shaft station of the displacement sensor, ``x + sensor_offset`` [m]."""
        return self.x + self.sensor_offset

    @property
    def sensor_boom_x(self) -> float:
        """Boom station the sensor is referenced to, ``boom_x + sensor_offset`` [m]."""
        return self.boom_x + self.sensor_offset

    @property
    def derivative_cutoff_rad_s(self) -> float | None:
        """Derivative-filter corner ω_d = 2π f_d [rad/s] (None: ideal derivative)."""
        return None if self.derivative_cutoff is None else 2.0 * math.pi * self.derivative_cutoff

    @property
    def amplifier_bandwidth_rad_s(self) -> float | None:
        """Amplifier bandwidth ω_a = 2π f_a [rad/s] (None: ideal amplifier)."""
        return None if self.amplifier_bandwidth is None else 2.0 * math.pi * self.amplifier_bandwidth

    @property
    def pole_angle_rad(self) -> float:
        """Pole angle α [rad]."""
        return math.radians(self.pole_angle)

    def transfer_function(self) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """(numerator, denominator) of the controller C(s), highest power first.

        PD gives ``(kd, kp)/(1)``; a PID ``kp + K_I/s + kd s/(1 + s/ω_d)`` is brought to one
        fraction over ``s (1 + s/ω_d)`` (over ``s`` without a filter, then one degree improper:
        the ideal derivative; over ``1 + s/ω_d`` without integral action).
        """
        if self.controller is not None:
            return self.controller.numerator, self.controller.denominator
        assert self.kp is not None and self.kd is not None
        kp, kd, k_int = self.kp, self.kd, self.integral_gain or 0.0
        wd = self.derivative_cutoff_rad_s
        if wd is None:
            return ((kd, kp), (1.0,)) if k_int == 0.0 else ((kd, kp, k_int), (1.0, 0.0))
        if k_int == 0.0:
            return (kd + kp / wd, kp), (1.0 / wd, 1.0)
        return (kd + kp / wd, kp + k_int / wd, k_int), (1.0 / wd, 1.0, 0.0)


Bearing = Annotated[ContactBearing | ActiveBearing, Field(discriminator="kind")]
