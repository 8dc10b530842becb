"""Thesis study 1: the Tsai-Wu safety factor against the ply angle α of (α/−α/−α/α), without
imbalance, with the critical ply's stresses (thesis Table 3.3), on the sweep engine."""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.response import static_response
from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly.loads import external_static_load, torque_load
from flexshaft.sweep.run import run_sweep
from flexshaft.sweep.study import Output, Study, Variable
from flexshaft.thesis.strength import STRENGTH_OUTPUTS

__all__ = [
    "DOMINANT_STRESS_CODES",
    "critical_ply_outputs",
    "critical_ply_outputs_thesis_loads",
    "one_angle_layup",
    "ply_angle_study",
]


def _angle(a: float) -> str:
    return f"{float(a):g}"


def one_angle_layup(alpha: float) -> dict:
    """``(α/−α/−α/α)`` [deg] as a layup override."""
    a = _angle(alpha)
    return {"shaft.layup": f"({a}/-{a}/-{a}/{a})".replace("--", "")}


#: Codes of the ``dominant_stress`` output (a float, so that it fits the results array).
DOMINANT_STRESS_CODES = {0: "sigma1", 1: "sigma2", 2: "tau12"}

_CRITICAL = (
    Output("sigma1", "Pa", "fibre-direction stress of the critical ply (thesis Table 3.3)"),
    Output("sigma2", "Pa", "transverse stress of the critical ply"),
    Output("tau12", "Pa", "in-plane shear stress of the critical ply"),
    Output("critical_ply_angle", "deg", "angle of the critical ply"),
    Output("critical_x", "m", "axial station of the critical point"),
    Output("dominant_stress", "1", "largest Tsai-Wu share: 0 sigma1, 1 sigma2, 2 tau12"),
)


def critical_ply_outputs(point, added_loads: bool = True) -> dict:
    """Static Tsai-Wu safety factor and the critical ply's stresses (thesis Table 3.3).

    The imbalance is not applied (study 1 runs with ``loads.eccentricity = 0``), so
    ``safety_factor`` equals ``safety_factor_static``. ``added_loads``: include the two loads
    flexshaft adds to the thesis's (the spinning wall's centrifugal hoop stress and the
    laminate's thermal residual stress, :func:`~flexshaft.analyses.shaft_strength.shaft_safety_factor`);
    False leaves both out: the thesis's own load set (external loads and torque, free hoop).
    """
    model = point.model
    q = static_response(model, external_static_load(model) + torque_load(model))
    r = (
        shaft_safety_factor(model, q)
        if added_loads
        else shaft_safety_factor(model, q, speed=0.0, thermal_residual=False)
    )
    code = {v: k for k, v in DOMINANT_STRESS_CODES.items()}[str(r.dominant_stress)]
    return {
        "safety_factor_static": r.safety_factor,
        "safety_factor": r.safety_factor,
        "sigma1": r.stresses[0],
        "sigma2": r.stresses[1],
        "tau12": r.stresses[2],
        "critical_ply_angle": r.ply_angle_deg,
        "critical_x": r.x,
        "dominant_stress": float(code),
    }


def critical_ply_outputs_thesis_loads(point) -> dict:
    """:func:`critical_ply_outputs` with the thesis's loads only (no centrifugal hoop stress, no
    thermal residual stress)."""
    return critical_ply_outputs(point, added_loads=False)


def ply_angle_study(angles=None, design=None, *, added_loads: bool = True, **run):
    """Safety factor vs the ply angle α of (α/−α/−α/α), no imbalance (thesis study 1), with
    the critical ply's σ1, σ2, τ12 (Table 3.3), its angle, station and dominant stress.

    The optimum on the assumed baseline is a narrow peak near 45° (docs/studies.md): use a
    step of 1° or finer there before concluding on it. ``angles`` [deg], default every 5° from 5°.
    ``added_loads=False`` leaves out the loads flexshaft adds to the thesis's (the centrifugal
    hoop stress of the spinning wall and the thermal residual stress of the cured laminate):
    the thesis's own load set (docs/thesis-reproduction.md, the loads flexshaft adds).
    """
    if not isinstance(added_loads, bool):
        raise ValueError(f"added_loads must be True or False (got {added_loads!r})")
    angles = np.arange(5.0, 90.0, 5.0) if angles is None else angles
    study = Study(
        "ply angle (a/-a/-a/a)",
        (Variable("alpha", angles, overrides=one_angle_layup, units="deg", long_name="ply angle"),),
        STRENGTH_OUTPUTS + _CRITICAL,
        critical_ply_outputs if added_loads else critical_ply_outputs_thesis_loads,
        base=design,
        fixed={"loads.eccentricity": 0.0},
    )
    return run_sweep(study, **run)
