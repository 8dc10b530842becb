"""The drive train at the shaft's ends on the twist DOF θ: tail rotor (aft) and gearbox (forward).

Everything is reflected to the shaft's speed (φ_shaft = n φ_rotor, kinetic and strain energy
kept; :mod:`flexshaft.design.drivetrain`):

* **Tail rotor** (``[tail_rotor]``): inertia ``J_r = J_tr/n²``, drive stiffness
  ``k_r = 1/(1/k_input + n²/k_hub)`` and aerodynamic damping ``c_r`` (to ground). With a finite
  ``k_r`` the rotor has a twist DOF of its own, the extra DOF ``"tail_rotor"``
  (:attr:`~flexshaft.assembly.dofs.DofMap.extra`)::

      M[r, r] += J_r,   K[(a, r), (a, r)] += k_r [[1, −1], [−1, 1]],   C[r, r] += c_r

  with a the shaft's aft twist θ. A rigid drive (both stiffnesses omitted) puts ``J_r`` and
  ``c_r`` on θ_a itself. The mean torque and the rotor's torque oscillations act on the rotor's
  DOF (:attr:`DriveTrain.rotor_dof`).
* **Gearbox** (``[main_gearbox]``): ``M[f, f] += J_g``, ``K[f, f] += k_g`` on the forward twist
  θ_f (the main rotor and engines behind k_g are an infinite inertia); a rigid gearbox holds θ_f.

Without either table the model is the one of before (no extra DOF, no new term), bit for bit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flexshaft.assembly.dofs import DofMap

__all__ = ["TAIL_ROTOR_DOF", "DriveTrain", "drive_extra_dofs", "drive_terms", "gearbox_holds_twist"]

#: Name of the tail rotor's extra DOF (its twist reflected to the shaft) in the DOF map.
TAIL_ROTOR_DOF = "tail_rotor"


@dataclass(frozen=True)
class DriveTrain:
    """The torsional ends of a model, every value reflected to the shaft's speed.

    Attributes
    ----------
    rotor_dof : int or None
        Global DOF of the tail rotor's twist (its extra DOF; the shaft's aft θ for a rigid
        drive); None without a tail rotor.
    rotor_inertia : float
        J_tr/n² [kg m²] (0 without a tail rotor).
    rotor_stiffness : float
        Drive stiffness k_r from the shaft's aft end to the rotor [N m/rad] (inf: rigid).
    rotor_damping : float
        Aerodynamic damping c_r of the rotor to ground [N m s/rad].
    gearbox_ratio : float or None
        n = shaft speed / tail-rotor speed [-].
    blades : int or None
        Number of tail-rotor blades.
    torque_oscillation : tuple of 2 floats
        The rotor's 1/rev and N/rev torque oscillation amplitudes, fractions of its mean
        torque [-].
    gearbox_dof : int or None
        Global DOF of the shaft's forward twist carrying the gearbox (None: no elastic gearbox).
    gearbox_inertia : float
        J_g [kg m²] on the forward twist (0 when rigid or absent).
    gearbox_stiffness : float or None
        k_g [N m/rad] to the infinite inertia ahead (None: rigid or absent).
    """

    rotor_dof: int | None = None
    rotor_inertia: float = 0.0
    rotor_stiffness: float = math.inf
    rotor_damping: float = 0.0
    gearbox_ratio: float | None = None
    blades: int | None = None
    torque_oscillation: tuple[float, float] = (0.0, 0.0)
    gearbox_dof: int | None = None
    gearbox_inertia: float = 0.0
    gearbox_stiffness: float | None = None

    @property
    def has_rotor(self) -> bool:
        """True when a tail rotor is modelled."""
        return self.rotor_dof is not None

    @property
    def elastic_rotor(self) -> bool:
        """True when the tail rotor has a twist DOF of its own (finite drive stiffness)."""
        return self.has_rotor and math.isfinite(self.rotor_stiffness)


def drive_extra_dofs(design) -> tuple[str, ...]:
    """The extra DOFs the design's drive train needs: ``("tail_rotor",)`` for a tail rotor with
    a finite drive stiffness, else none."""
    rotor = getattr(design, "tail_rotor", None)
    return (TAIL_ROTOR_DOF,) if rotor is not None and math.isfinite(rotor.reflected_stiffness) else ()


def gearbox_holds_twist(design) -> bool:
    """True when a rigid ``[main_gearbox]`` holds the shaft's forward twist."""
    gearbox = getattr(design, "main_gearbox", None)
    return gearbox is not None and gearbox.rigid


def drive_terms(design, dm: DofMap, parts: dict) -> DriveTrain:
    """Append the drive train's mass, stiffness and damping blocks to ``parts`` (lists of
    ``(blocks, dofs)`` for ``"M"``, ``"K"``, ``"C"``) and describe it.

    ``dm`` must carry :func:`drive_extra_dofs` (``build_model`` builds it so).
    """
    rotor, gearbox = getattr(design, "tail_rotor", None), getattr(design, "main_gearbox", None)
    fields: dict = {}
    if rotor is not None:
        aft = dm.shaft(-1, "theta")
        J = rotor.reflected_inertia
        k = rotor.reflected_stiffness
        c = rotor.reflected_damping(float(design.operating.power), float(design.operating.speed_rad_s))
        dof = dm.extra_dof(TAIL_ROTOR_DOF) if math.isfinite(k) else aft
        parts["M"].append((np.array([[[J]]]), np.array([[dof]])))
        if c > 0.0:
            parts["C"].append((np.array([[[c]]]), np.array([[dof]])))
        if math.isfinite(k):
            parts["K"].append((k * np.array([[[1.0, -1.0], [-1.0, 1.0]]]), np.array([[aft, dof]])))
        fields.update(
            rotor_dof=int(dof),
            rotor_inertia=float(J),
            rotor_stiffness=float(k),
            rotor_damping=float(c),
            gearbox_ratio=float(rotor.gearbox_ratio),
            blades=int(rotor.blades),
            torque_oscillation=(float(rotor.torque_oscillation_1p), float(rotor.torque_oscillation_np)),
        )
    if gearbox is not None and not gearbox.rigid:
        fore = dm.shaft(0, "theta")
        if gearbox.polar_inertia > 0.0:
            parts["M"].append((np.array([[[float(gearbox.polar_inertia)]]]), np.array([[fore]])))
        parts["K"].append((np.array([[[float(gearbox.stiffness)]]]), np.array([[fore]])))
        fields.update(
            gearbox_dof=int(fore),
            gearbox_inertia=float(gearbox.polar_inertia),
            gearbox_stiffness=float(gearbox.stiffness),
        )
    return DriveTrain(**fields)
