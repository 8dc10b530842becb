"""Thesis study 4: the proportional gain K_p of the active bearings. The Tsai-Wu safety factor and
the actuator's relative orbit at the operating speed against K_p, on the sweep engine."""

from __future__ import annotations

from functools import partial

import numpy as np

from flexshaft.analyses.reactions import actuator_response
from flexshaft.analyses.response import imbalance_response
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.sweep.run import run_sweep
from flexshaft.sweep.study import Output, Study, Variable
from flexshaft.thesis.strength import STRENGTH_OUTPUTS, strength_outputs

__all__ = ["gain_paths", "proportional_gain_study"]


def _actuator_outputs(point) -> dict:
    model = point.model
    q = imbalance_response(model, [model.speed], imbalance_loads(model))
    worst_disp = 0.0
    for c in range(q.shape[1]):
        disp, _ = actuator_response(model, q[:, c], np.array([model.speed]))
        worst_disp = max(worst_disp, max(float(d[0]) for d in disp.values()))
    if model.shaft.laminate is None:  # ply strength needs a laminated shaft (as in the wall study)
        strength = {o.name: float("nan") for o in STRENGTH_OUTPUTS}
    else:  # the imbalance response solved once for both
        strength = strength_outputs(point, imbalance=q[:, :, 0])
    return {**strength, "actuator_displacement": worst_disp}


def gain_paths(design) -> tuple[str, ...]:
    """The design-file paths of the proportional gain K_p of every active bearing with a PD law
    (``bearings[i].kp``; a bearing given by a ``controller`` transfer function has none): the
    thesis baseline's bearings 1 and 2."""
    return tuple(f"bearings[{i}].kp" for i, b in enumerate(design.bearings) if b.kind == "active" and b.kp is not None)


def _gains(paths: tuple[str, ...], kp: float) -> dict:
    return dict.fromkeys(paths, kp)


def proportional_gain_study(kps=None, design=None, **run):
    """Safety factor and actuator displacement at the operating speed vs K_p (study 4).

    ``kps`` [N/m] (default 13 from 1e5 to 1e8) is applied to every active bearing with a PD law
    (:func:`gain_paths`; the baseline's bearings 1 and 2, the thesis's study).

    Raises
    ------
    ValueError
        When the design has no such bearing (before any point is computed).
    """
    from flexshaft.design import baseline_design

    paths = gain_paths(baseline_design() if design is None else design)
    if not paths:
        raise ValueError(
            'the K_p study needs an active bearing (kind = "active") with a proportional gain kp; the design has none'
        )
    kps = np.logspace(5, 8, 13) if kps is None else kps
    study = Study(
        "proportional gain",
        (Variable("kp", kps, overrides=partial(_gains, paths), units="N/m"),),
        STRENGTH_OUTPUTS + (Output("actuator_displacement", "m", "relative orbit at the actuator, operating speed"),),
        _actuator_outputs,
        base=design,
    )
    return run_sweep(study, **run)
