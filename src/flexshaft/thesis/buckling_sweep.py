"""Thesis study 5: the torsional-buckling safety factor of the laminated shaft against its wall
thickness (the shear-deformable shell of :func:`flexshaft.analyses.shaft_buckling.shaft_buckling`),
on the sweep engine."""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.shaft_buckling import shaft_buckling
from flexshaft.design import baseline_design
from flexshaft.sweep.run import run_sweep
from flexshaft.sweep.study import Output, Study, SweepError, Variable

__all__ = ["buckling_study"]


def _buckling_outputs(point) -> dict:
    result = shaft_buckling(point.model, compare_classical=False)
    return {
        "critical_torque": float(min(result.result.torque_positive, result.result.torque_negative)),
        "buckling_safety_factor": result.safety_factor,
    }


def buckling_study(walls=None, design=None, **run):
    """Torsional buckling safety factor vs wall thickness [m] (study 5; shear-deformable shell;
    default 10 walls from 1.5 to 6 mm).

    Raises
    ------
    SweepError
        When the design's shaft is not one laminated tube (the laminated-shell model's domain;
        a metal segment's buckling is part of the run's metal strength check).
    """
    walls = np.linspace(0.0015, 0.006, 10) if walls is None else walls
    base = design if design is not None else baseline_design()
    if base.segmented or base.materials[base.shaft.material].kind != "lamina":
        raise SweepError(
            f"study 'torsional buckling vs wall thickness': the shaft of {base.name!r} is not one "
            "laminated tube; the laminated-shell buckling model does not apply (a metal segment's "
            "buckling is checked by `flexshaft run`)"
        )
    study = Study(
        "torsional buckling vs wall thickness",
        (Variable(path="shaft.wall_thickness", name="wall_thickness", values=walls, units="m"),),
        (Output("critical_torque", "N m", "smaller of the two senses"), Output("buckling_safety_factor", "1")),
        _buckling_outputs,
        base=design,
    )
    return run_sweep(study, **run)
