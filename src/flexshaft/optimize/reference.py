"""A verification problem with a known Pareto front, run through the optimizer's own engine.

ZDT1 (Zitzler, Deb & Thiele 2000) on real design paths, so that candidates go through the same
design overrides, schema validation, sweep batches and evaluation cache as a driveline search;
only the output function is analytic. With the variables normalised to u in [0, 1]:

* u1 = wall thickness from 1 mm to 4 mm; u2, u3 = the two active bearings' K_d from 0 to
  2000 N s/m; u4 = log10 K_p of the first from 1e5 to 1e7 N/m; n = the integer repeat count of
  the 0° plies in the layup ``(55/-55/0_{n})s``, 1 to 5;
* g = 1 + 3 (u2 + u3 + u4) + (n − 3)², objectives f1 = u1 and f2 = g (1 − √(f1/g));
* constraints: ``margin_lower`` = u1 − 0.1 >= 0, and ``margin_probe`` = 1, not evaluated (NaN)
  where u3 > 0.9, which must count as violated.

The Pareto front is f2 = 1 − √f1 for f1 in [0.1, 1] (u2 = u3 = u4 = 0, n = 3); its hypervolume
up to the reference point (1.1, 1.1) is 0.1·0.9 + (2/3)(1 − 0.1^1.5) + 0.1·1.1
(:data:`ZDT1_HYPERVOLUME`).
"""

from __future__ import annotations

import math

import numpy as np

from flexshaft.optimize.problem import DesignProblem
from flexshaft.optimize.variables import DesignVariable, Objective

__all__ = ["ZDT1_HYPERVOLUME", "ZDT1_REFERENCE", "zdt1_front", "zdt1_outputs", "zdt1_problem"]

#: Reference point of the hypervolume (f1, f2).
ZDT1_REFERENCE = (1.1, 1.1)
#: Hypervolume of the exact constrained front up to :data:`ZDT1_REFERENCE`.
ZDT1_HYPERVOLUME = 0.1 * 0.9 + (2.0 / 3.0) * (1.0 - 0.1**1.5) + 0.1 * 1.1

_OUTPUTS = (
    ("f1", "1", "ZDT1 first objective"),
    ("f2", "1", "ZDT1 second objective"),
    ("margin_lower", "1", "u1 - 0.1 (>= 0)"),
    ("margin_probe", "1", "1, or NaN (not evaluated) where u3 > 0.9"),
)


def _unit(value: float, lower: float, upper: float) -> float:
    return (value - lower) / (upper - lower)


def zdt1_outputs(point) -> dict[str, float]:
    """Sweep output function of the ZDT1 problem (reads the point's design)."""
    d = point.design
    u1 = _unit(d.shaft.wall_thickness, 0.001, 0.004)
    u2 = _unit(d.bearings[1].kd, 0.0, 2000.0)
    u3 = _unit(d.bearings[2].kd, 0.0, 2000.0)
    u4 = _unit(math.log10(d.bearings[1].kp), 5.0, 7.0)
    n_zero = sum(1 for angle in d.shaft.ply_angles_deg if angle == 0.0) // 2  # symmetric layup
    g = 1.0 + 3.0 * (u2 + u3 + u4) + (n_zero - 3) ** 2
    f1 = u1
    return {
        "f1": f1,
        "f2": g * (1.0 - math.sqrt(f1 / g)),
        "margin_lower": u1 - 0.1,
        "margin_probe": float("nan") if u3 > 0.9 else 1.0,
    }


def zdt1_problem(base=None, fidelity: str = "screening") -> DesignProblem:
    """The ZDT1 verification problem on the Table 3.1 baseline (or ``base``)."""
    variables = (
        DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall_thickness", units="m"),
        DesignVariable("bearings[1].kd", 0.0, 2000.0, name="kd_1", units="N s m-1"),
        DesignVariable("bearings[2].kd", 0.0, 2000.0, name="kd_2", units="N s m-1"),
        DesignVariable("bearings[1].kp", 1e5, 1e7, log=True, name="kp_1", units="N m-1"),
        DesignVariable("layup.n", 1, 5, integer=True, name="zero_plies"),
    )
    return DesignProblem(
        variables,
        base=base,
        objectives=(Objective("f1", "min", "f1"), Objective("f2", "min", "f2")),
        constraints=("margin_lower", "margin_probe"),
        layup="(55/-55/0_{n})s",
        evaluate=zdt1_outputs,
        outputs=_OUTPUTS,
        fidelity=fidelity,
        name="ZDT1 verification problem",
    )


def zdt1_front(f1: np.ndarray) -> np.ndarray:
    """The exact front f2(f1) = 1 − √f1."""
    return 1.0 - np.sqrt(np.asarray(f1, dtype=float))
