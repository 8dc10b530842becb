"""Torsional buckling of a model's shaft under its transmitted torque (thesis §2.7, §3.2.4).

One function for every caller (the run, the wall-thickness study): the laminated tube between
the shaft's ends (simply supported), mid-surface radius (D_o − t)/2, the shear-deformable shell
of :mod:`flexshaft.buckling` by default with the classical shell beside it for comparison, and
the safety factor T_cr/T in the weaker sense against the torque P/Ω.
"""

from __future__ import annotations

from dataclasses import dataclass

from flexshaft.assembly.model import Model
from flexshaft.buckling import BucklingResult, ShellTheory, buckling_safety_factor, torsional_buckling_torque

__all__ = ["ShaftBuckling", "shaft_buckling"]


@dataclass(frozen=True)
class ShaftBuckling:
    """Buckling of the shaft: the governing result and the classical comparison.

    Attributes
    ----------
    result : BucklingResult
        The shell model used for the verdict (``theory``).
    classical : BucklingResult or None
        The classical (Kirchhoff-Love) shell, for comparison (None when ``result`` is it).
    torque : float
        Transmitted torque P/Ω [N m].
    safety_factor : float
        T_cr/|T| in the weaker sense [-] (inf without torque).
    """

    result: BucklingResult
    classical: BucklingResult | None
    torque: float
    safety_factor: float

    def __repr__(self) -> str:
        r = self.result
        return (
            f"ShaftBuckling({r.theory} shell: T_cr {r.critical_torque:.4g} N m "
            f"({r.governing}), T {self.torque:.4g} N m, safety factor {self.safety_factor:.3g})"
        )

    def to_dict(self) -> dict:
        """Plain numbers for JSON and the verdict [N m, -]; a wave number None is the crimping limit."""
        r = self.result
        out = {
            "critical_torque_positive_Nm": float(r.torque_positive),
            "critical_torque_negative_Nm": float(r.torque_negative),
            "wave_number_positive": r.n_positive,
            "wave_number_negative": r.n_negative,
            "governing_positive": r.governing_positive,
            "governing_negative": r.governing_negative,
            "global_torque_positive_Nm": float(r.global_torque_positive),
            "global_torque_negative_Nm": float(r.global_torque_negative),
            "crimping_torque_positive_Nm": float(r.crimping_torque_positive),
            "crimping_torque_negative_Nm": float(r.crimping_torque_negative),
            "theory": r.theory,
            "torque_Nm": float(self.torque),
            "safety_factor": float(self.safety_factor),
        }
        if self.classical is not None:
            c = self.classical
            out["classical_critical_torque_Nm"] = float(min(c.torque_positive, c.torque_negative))
            out["classical_safety_factor"] = (
                float(buckling_safety_factor(c, self.torque)) if self.torque > 0 else float("inf")
            )
        return out


def shaft_buckling(model: Model, theory: ShellTheory = "shear", compare_classical: bool = True) -> ShaftBuckling:
    """Critical torsional buckling torque and safety factor of the model's laminated shaft.

    Parameters
    ----------
    model : Model
        With a laminated (lamina) shaft.
    theory : {"shear", "classical"}
        Shell model of the verdict's number.
    compare_classical : bool
        Also solve the classical shell (skipped when ``theory`` is classical).

    Raises
    ------
    ValueError
        When the shaft is not laminated.
    """
    laminate = model.shaft.laminate
    if laminate is None:
        raise ValueError("laminated-shell buckling needs a lamina shaft material")
    design = model.design
    wall = design.shaft.wall_thickness if design is not None else laminate.thickness
    radius = (model.shaft.outer_diameter - wall) / 2
    length = float(model.dofs.shaft_x[-1] - model.dofs.shaft_x[0])
    result = torsional_buckling_torque(laminate, radius, length, theory=theory)
    classical = None
    if compare_classical and theory != "classical":
        classical = torsional_buckling_torque(laminate, radius, length, theory="classical")
    torque = model.power / model.speed if model.speed > 0 else 0.0
    safety = float(buckling_safety_factor(result, torque)) if torque > 0 else float("inf")
    return ShaftBuckling(result, classical, float(torque), safety)
