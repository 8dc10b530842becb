"""Thesis study 2: the Tsai-Wu safety factor over the two ply angles of (α/−α/β/−β)s, without
imbalance, on the sweep engine."""

from __future__ import annotations

import numpy as np

from flexshaft.design import with_overrides
from flexshaft.sweep.run import run_sweep
from flexshaft.sweep.study import Point, Study, Variable
from flexshaft.thesis.strength import STRENGTH_OUTPUTS, strength_outputs

__all__ = ["two_angle_layup", "two_angle_study"]


def two_angle_layup(angles) -> dict:
    """``(α/−α/β/−β)s`` [deg] from a pair (α, β)."""
    a, b = (f"{float(x):g}" for x in angles)
    return {"shaft.layup": f"({a}/-{a}/{b}/-{b})s".replace("--", "")}


def two_angle_study(alphas=None, betas=None, design=None, **run):
    """Safety factor over (α/−α/β/−β)s, no imbalance (thesis study 2); ``alphas`` and ``betas``
    [deg], default every 15° from 0° to 90°."""
    alphas = np.arange(0.0, 91.0, 15.0) if alphas is None else alphas
    betas = np.arange(0.0, 91.0, 15.0) if betas is None else betas
    study = Study(
        "two ply angles (a/-a/b/-b)s",
        (Variable("alpha", alphas, units="deg"), Variable("beta", betas, units="deg")),
        STRENGTH_OUTPUTS,
        _two_angle_strength,
        base=design,
        fixed={"loads.eccentricity": 0.0},
    )
    return run_sweep(study, **run)


def _two_angle_strength(point) -> dict:
    design = with_overrides(point.design, two_angle_layup((point.axes["alpha"], point.axes["beta"])))
    return strength_outputs(Point(point.index, point.values, point.axes, design))
