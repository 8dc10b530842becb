"""The Tsai-Wu safety factor of a sweep point at its operating point: the output the thesis's
strength studies share (ply angle, two angles, wall thickness, proportional gain)."""

from __future__ import annotations

from flexshaft.analyses.response import imbalance_response, static_response
from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly.balance import design_eccentricity
from flexshaft.assembly.loads import external_static_load, imbalance_loads, torque_load
from flexshaft.sweep.study import Output

__all__ = ["STRENGTH_OUTPUTS", "strength_outputs"]


def strength_outputs(point, imbalance=None) -> dict:
    """Tsai-Wu safety factor, static (external loads + torque) and with the imbalance
    response at the operating speed (worst load case). ``imbalance``: that response
    (ndof, n_cases) [m, rad] when the caller has already solved it (the gain study's actuator
    outputs need it too)."""
    model = point.model
    q_static = static_response(model, external_static_load(model) + torque_load(model))
    static = shaft_safety_factor(model, q_static).safety_factor
    # no imbalance (neither an eccentricity nor a balance grade, or at rest): the total is the static
    if design_eccentricity(model.design) == 0.0 or model.speed == 0.0:
        return {"safety_factor_static": static, "safety_factor": static}
    q_imb = (
        imbalance_response(model, [model.speed], imbalance_loads(model))[:, :, 0] if imbalance is None else imbalance
    )
    total = min(shaft_safety_factor(model, q_static, q_imb[:, c]).safety_factor for c in range(q_imb.shape[1]))
    return {"safety_factor_static": static, "safety_factor": total}


#: The outputs of :func:`strength_outputs`.
STRENGTH_OUTPUTS = (
    Output("safety_factor_static", "1", "Tsai-Wu safety factor, static loads and torque"),
    Output("safety_factor", "1", "Tsai-Wu safety factor with the imbalance at the operating speed"),
)
