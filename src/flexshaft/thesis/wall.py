"""Thesis study 3: the wall thickness at a fixed outer diameter. The safety factor with and
without imbalance, the shaft's first lateral natural frequency and the spin-up peak against the
wall (on the sweep engine), and the forced response of a few walls over speed (thesis figure 3.5).

The frequency is the shaft's own first lateral mode (:func:`shaft_first_lateral_frequency`): the
lowest lateral mode whose kinetic energy the shaft's bending holds for the most part. On a
driveline with a tailboom the lowest modes are the boom's (about 5 Hz on the embedded designs,
with the shaft carrying under 2 % of their energy): they barely move with the wall, and are not
what thesis eq. 3.3 (ω ∝ √(EI/m) of the tube) describes."""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.labelled import LabelledArrays
from flexshaft.analyses.modal import modes
from flexshaft.analyses.response import imbalance_response, orbit_amplitude
from flexshaft.analyses.spinup import actuator_receptance, clustered_receptance, spinup_curves, spinup_speeds
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import with_overrides
from flexshaft.resolution import REPORT, SLOW_START
from flexshaft.sweep.run import run_sweep
from flexshaft.sweep.study import Output, Study, Variable
from flexshaft.thesis.strength import STRENGTH_OUTPUTS, strength_outputs

__all__ = [
    "FORCED_WALLS",
    "SHAFT_MODE_SHARE",
    "forced_response",
    "quietest_spinup_wall",
    "shaft_first_lateral_frequency",
    "wall_thickness_study",
]

#: Share of a mode's kinetic energy in the shaft's lateral DOFs that makes it the shaft's mode.
SHAFT_MODE_SHARE = 0.5


def shaft_first_lateral_frequency(model, max_modes: int = 48) -> float:
    """Damped natural frequency at rest [Hz] of the shaft's first lateral mode: the lowest
    lateral mode with more than :data:`SHAFT_MODE_SHARE` of its kinetic energy in the shaft's
    bending (v, w, β, γ; :class:`~flexshaft.analyses.classify.EnergyShares`); NaN when none of
    the lowest ``max_modes`` modes is one.

    The modes are searched 12 at a time, doubling up to ``max_modes``."""
    n = 12
    while True:
        m = modes(model, 0.0, n)
        shaft = (m.kind == "lateral") & (m.shares.shaft_lateral > SHAFT_MODE_SHARE)
        if shaft.any():
            return float(m.frequencies[np.flatnonzero(shaft)[0]])
        if n >= max_modes or m.frequencies.size < n:
            return float("nan")
        n = min(2 * n, max_modes)


def _wall_outputs(point) -> dict:
    """The shaft's first lateral frequency always; the spin-up peak when the design has actuators and the safety
    factors when the shaft is laminated (NaN otherwise, e.g. a plain isotropic shaft)."""
    nan = float("nan")
    out = {
        "spinup_peak_deflection": nan,
        "safety_factor_static": nan,
        "safety_factor": nan,
        "safety_factor_no_imbalance": nan,
    }
    model = point.model
    out["natural_frequency_1"] = shaft_first_lateral_frequency(model)
    if model.actuators:
        laws = [a.controller for a in model.actuators]
        # 100 even speeds and 17 more around each of the 3 largest peaks: within 0.5 % of the
        # true peak on the study's walls, where 200 even speeds fell up to 2.7 % short
        speeds = spinup_speeds(model, point.axes.get("n_speeds", 100))
        rec = clustered_receptance(model, laws, speeds, n_peaks=3, n_fine=17)
        out["spinup_peak_deflection"] = float(spinup_curves(rec, laws).shaft_peak.max())
    if model.shaft.laminate is not None:
        out.update(strength_outputs(point))
        # without imbalance the loads are the static ones: the same model, the static result
        out["safety_factor_no_imbalance"] = out["safety_factor_static"]
    return out


def wall_thickness_study(walls=None, design=None, **run):
    """Safety factor with/without imbalance, the shaft's first lateral frequency and the
    spin-up peak vs wall (study 3);
    ``walls`` [m], default 10 from 1.5 to 6 mm."""
    walls = np.linspace(0.0015, 0.006, 10) if walls is None else walls
    study = Study(
        "wall thickness at fixed outer diameter",
        (Variable(path="shaft.wall_thickness", name="wall_thickness", values=walls, units="m"),),
        STRENGTH_OUTPUTS
        + (
            Output("safety_factor_no_imbalance", "1"),
            Output("natural_frequency_1", "Hz", "the shaft's first lateral natural frequency at rest"),
            Output("spinup_peak_deflection", "m", "peak shaft orbit during spin-up"),
        ),
        _wall_outputs,
        base=design,
    )
    return run_sweep(study, **run)


#: Walls of the thesis's forced-response view (figure 3.5) [m].
FORCED_WALLS = (0.001, 0.004)


def quietest_spinup_wall(wall) -> tuple[float, float] | None:
    """(wall [m], peak shaft orbit [m]) of the wall study's smallest spin-up peak under the
    design's gains; None without actuators (all NaN)."""
    peaks = np.asarray(wall["spinup_peak_deflection"].values, dtype=float)
    if not np.isfinite(peaks).any():
        return None
    i = int(np.nanargmin(peaks))
    return float(wall.wall_thickness.values[i]), float(peaks[i])


def forced_response(design, walls, n_speeds: int):
    """Largest shaft orbit [m] vs speed (the spin-up scan's range of the report resolution,
    :data:`~flexshaft.resolution.REPORT`) for a few walls [m] (thesis figure 3.5)."""
    peaks = []
    speeds = None
    for wall in walls:
        model = build_model(with_overrides(design, {"shaft.wall_thickness": float(wall)}))
        speeds = np.linspace(SLOW_START, REPORT.scan_top, n_speeds) * max(model.speed, 1.0)
        if model.actuators:
            rec = actuator_receptance(model, speeds)
            peaks.append(spinup_curves(rec, [a.controller for a in model.actuators]).shaft_peak)
        else:
            q = imbalance_response(model, speeds, imbalance_loads(model))
            dm = model.dofs
            n = np.arange(dm.n_shaft_nodes)
            peaks.append(orbit_amplitude(q[dm.shaft(n, "v")], q[dm.shaft(n, "w")]).max(axis=(0, 1)))
    return LabelledArrays(
        {
            "shaft_peak": (
                ("wall_thickness", "speed"),
                np.array(peaks),
                {"units": "m", "long_name": "largest shaft orbit over the nodes"},
            )
        },
        coords={
            "wall_thickness": ("wall_thickness", np.asarray(walls, float), {"units": "m"}),
            "speed": ("speed", speeds, {"units": "rad/s", "long_name": "spin speed"}),
        },
        attrs={"title": "forced response vs wall thickness (thesis figure 3.5)"},
    )
