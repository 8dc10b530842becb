"""The torsional ends of the driveline: ``[tail_rotor]`` (aft) and ``[main_gearbox]`` (forward).

The shaft's twist θ is driven at the forward end by the main (or intermediate) gearbox's tail
take-off and drives the tail rotor through the tail gearbox (and, on some helicopters, an
intermediate gearbox and a short shaft) at the aft end. Both ends enter the model on the twist
DOF θ of the end nodes (docs/model.md, "Torsional ends"):

* **Aft end.** The tail rotor, polar inertia J_tr about its own axis, turns at Ω/n (n the
  overall gear ratio ``gearbox_ratio`` = shaft speed / tail-rotor speed). Reflected to the
  shaft (kinetic and strain energy kept: φ_shaft = n φ_rotor) it is an inertia ``J_tr/n²`` on a
  twist DOF of its own, joined to the shaft's aft θ by the series spring
  ``1/k = 1/k_input + n²/k_hub`` (``input_stiffness`` at the shaft side, ``hub_stiffness`` at
  the rotor side; both omitted: a rigid drive, the inertia sits on the shaft's aft θ). The
  rotor's aerodynamic torque resists the speed: ``aerodynamic_damping`` dQ/dΩ at the rotor,
  reflected as ``c/n²`` to ground.
* **Forward end.** Everything ahead of the tail take-off (main rotor, engines) is taken as an
  infinite inertia: the main rotor's reflected inertia, of order 10⁴ kg m² × (Ω_mr/Ω)² ≈
  36 kg m² for an AH-64-class helicopter, is a thousand times the shaft's own polar inertia.
  The gearbox's reflected inertia ``polar_inertia`` sits on the shaft's forward θ, tied to that
  infinite inertia by its torsional ``stiffness`` (the gear meshes and shafts between). An
  omitted ``stiffness`` is a rigid gearbox: the forward θ is held, the limit of an infinitely
  stiff or infinitely inertial gearbox, which is what ``fixed_start = ["theta"]`` says.

Every default below is marked: "assumed" values are this module's choices, not data.
"""

from __future__ import annotations

import math
from typing import Annotated

from pydantic import Field

from flexshaft.design.fields import FrozenModel
from flexshaft.design.quantities import Inertia, quantity_field

__all__ = ["DEFAULT_TORQUE_OSCILLATION_1P", "DEFAULT_TORQUE_OSCILLATION_NP", "MainGearbox", "TailRotor"]

#: Tail-rotor 1/rev torque oscillation as a fraction of the mean tail-rotor torque (assumed: a
#: rotor out of track or balance; no published value was found for this helicopter class).
DEFAULT_TORQUE_OSCILLATION_1P = 0.05
#: Tail-rotor N/rev (blade-passage) torque oscillation as a fraction of the mean torque
#: (assumed: each blade passing the fin and the main-rotor wake; no published value found).
DEFAULT_TORQUE_OSCILLATION_NP = 0.10

GearRatio = Annotated[
    float,
    quantity_field(
        "-", "overall gear ratio shaft speed / rotor speed from 0.01 to 100 (tail drives: 2-5)", ge=0.01, le=100.0
    ),
]
TorsionalStiffness = Annotated[
    float,
    quantity_field(
        "N m/rad",
        "torsional stiffness above 0 and at most 1e12 N m/rad (omit the key for a rigid connection)",
        gt=0.0,
        le=1e12,
    ),
]
PositiveInertia = Annotated[
    float, quantity_field("kg m^2", "polar inertia above 0 and at most 1e7 kg m²", gt=0.0, le=1e7)
]
TorqueFraction = Annotated[
    float,
    quantity_field("-", "torque oscillation amplitude as a fraction of the mean torque, from 0 to 10", ge=0.0, le=10.0),
]
TorsionalDamping = Annotated[
    float, quantity_field("N m s/rad", "torsional damping dQ/dΩ from 0 to 1e9 N m s/rad", ge=0.0, le=1e9)
]
BladeCount = Annotated[int, Field(strict=True, ge=1, le=12, description="number of tail-rotor blades N, 1 to 12")]


class TailRotor(FrozenModel):
    """The tail rotor at the shaft's aft end, driven through a gear ratio (``[tail_rotor]``).

    Attributes
    ----------
    blades : int
        Number of blades N: the N/rev blade-passage excitation.
    polar_inertia : float
        Polar inertia J_tr of the rotor (blades and hub) about its own axis [kg m²]; reflected
        to the shaft as J_tr/n².
    gearbox_ratio : float
        Overall gear ratio n = shaft speed / tail-rotor speed [-] (through every gearbox
        between the shaft's aft end and the rotor): the rotor turns at Ω/n.
    input_stiffness : float or None
        Torsional stiffness between the shaft's aft end and the tail gearbox's gears, at the
        shaft side [N m/rad] (gearbox input shaft, any intermediate gearbox and connecting
        shaft); omitted: rigid.
    hub_stiffness : float or None
        Torsional stiffness of the tail-rotor shaft and hub, at the rotor side [N m/rad];
        reflected to the shaft as k_hub/n², in series with ``input_stiffness``; omitted: rigid.
    aerodynamic_damping : float or None
        dQ/dΩ of the rotor's aerodynamic torque at the rotor [N m s/rad], reflected as c/n²
        (a viscous damper from the rotor to ground). Omitted: ``2 Q/Ω_tr`` from the operating
        point (Q = P n/Ω the mean rotor torque, Ω_tr = Ω/n): the torque of a rotor at fixed
        pitch grows as Ω² (assumed).
    torque_oscillation_1p : float
        Amplitude of the rotor's 1/rev torque oscillation as a fraction of its mean torque [-]
        (assumed default 0.05).
    torque_oscillation_np : float
        Amplitude of its N/rev (blade-passage) torque oscillation, a fraction of the mean
        torque [-] (assumed default 0.10).
    """

    blades: BladeCount
    polar_inertia: PositiveInertia
    gearbox_ratio: GearRatio
    input_stiffness: TorsionalStiffness | None = None
    hub_stiffness: TorsionalStiffness | None = None
    aerodynamic_damping: TorsionalDamping | None = None
    torque_oscillation_1p: TorqueFraction = DEFAULT_TORQUE_OSCILLATION_1P
    torque_oscillation_np: TorqueFraction = DEFAULT_TORQUE_OSCILLATION_NP

    @property
    def reflected_inertia(self) -> float:
        """J_tr/n²: the rotor's inertia seen on the shaft's twist [kg m²]."""
        return self.polar_inertia / self.gearbox_ratio**2

    @property
    def reflected_stiffness(self) -> float:
        """The drive's stiffness at the shaft side, ``1/(1/k_input + n²/k_hub)`` [N m/rad]
        (``math.inf`` when both are rigid; a rigid part adds no compliance)."""
        compliance = 0.0
        if self.input_stiffness is not None:
            compliance += 1.0 / self.input_stiffness
        if self.hub_stiffness is not None:
            compliance += self.gearbox_ratio**2 / self.hub_stiffness
        return math.inf if compliance == 0.0 else 1.0 / compliance

    def reflected_damping(self, power: float, speed: float) -> float:
        """The aerodynamic damping at the shaft side [N m s/rad] at power P [W] and shaft speed
        Ω [rad/s]: ``aerodynamic_damping/n²`` when given, else ``2 P/Ω²`` (the reflection of
        ``2 Q_tr/Ω_tr``; 0 at rest)."""
        if self.aerodynamic_damping is not None:
            return self.aerodynamic_damping / self.gearbox_ratio**2
        return 0.0 if speed <= 0.0 else 2.0 * power / speed**2

    def speed(self, shaft_speed: float) -> float:
        """Tail-rotor speed Ω/n [rad/s] at shaft speed Ω [rad/s]."""
        return shaft_speed / self.gearbox_ratio


class MainGearbox(FrozenModel):
    """The gearbox that drives the shaft's forward end (``[main_gearbox]``).

    Attributes
    ----------
    polar_inertia : float
        Reflected polar inertia of the gearbox's tail take-off at the shaft [kg m²] (its gears
        and shafts, each J_i (Ω_i/Ω)²), on the shaft's forward twist; 0 when omitted.
    stiffness : float or None
        Torsional stiffness at the shaft from that inertia to the main rotor and engines, taken
        as an infinite inertia [N m/rad]; omitted: a rigid gearbox (the forward twist is held,
        as ``shaft.fixed_start = ["theta"]`` holds it).
    """

    polar_inertia: Inertia = 0.0
    stiffness: TorsionalStiffness | None = None

    @property
    def rigid(self) -> bool:
        """True when the forward twist is held (no ``stiffness``)."""
        return self.stiffness is None
