"""The main job: every analysis of one design at its operating point (``flexshaft run``).

Returns plain data (:class:`RunResults`) that the report, the JSON output and notebooks use.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from flexshaft.analyses import imbalance_response, modes, static_response
from flexshaft.analyses.campbell import Campbell, campbell
from flexshaft.analyses.response import actuator_response, bearing_reactions, worst_case_orbits
from flexshaft.analyses.shaft_strength import StrengthResult, shaft_safety_factor
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load, imbalance_loads, torque_load
from flexshaft.assembly.model import Model
from flexshaft.analyses.summary import model_summary, modes_table

__all__ = ["RunResults", "run_analysis"]


@dataclass
class RunResults:
    """Everything ``flexshaft run`` computes, in SI units."""

    model: Model
    summary: dict
    modes_at_rest: list
    modes_at_speed: list
    mode_shapes: object  # Modes at the operating speed
    campbell: Campbell
    speeds: np.ndarray  # spin-up speeds [rad/s]
    shaft_peak: np.ndarray  # max orbit over shaft nodes at each speed [m]
    shaft_envelope: np.ndarray  # (n_shaft_nodes, n_speeds) orbit amplitude [m]
    actuator_displacement: dict  # name -> (n_speeds,) relative orbit [m]
    actuator_force: dict  # name -> (n_speeds,) [N]
    static_displacement: np.ndarray
    strength_static: StrengthResult | None
    strength_total: StrengthResult | None
    imbalance_at_speed: np.ndarray
    buckling: object = None
    stability: object = None  # StabilityResult of the design (viscous equivalent)
    shaft_comparison: dict = field(default_factory=dict)  # label -> {model: StabilityResult}
    gain_map: object = None  # StabilityMap over (K_p, K_d)
    thermal: object = None  # dict from flexshaft.studies.thermal.thermal_results
    design_studies: object = None  # flexshaft.studies.chapter3.DesignStudies
    notes: list = field(default_factory=list)
    verdict: object = None  # flexshaft.studies.verdict.Verdict against the design's [requirements]
    bearing_reactions: dict = field(default_factory=dict)  # name -> analyses.response.BearingReaction
    imbalance_spinup: object = None  # HarmonicResponse (ndof, ncases, n_speeds) over `speeds`


def run_analysis(design, n_speeds: int = 400, n_campbell: int = 60, progress: Callable[[str], None] | None = None,
                 studies: str | None = "report") -> RunResults:
    """Analyse a design: modes, Campbell, spin-up imbalance response, static loads, strength,
    thermal, whirl stability, and the verdict against the design's ``[requirements]``.

    Parameters
    ----------
    n_speeds : int
        Spin-up speeds from 2 % to 110 % of the operating speed.
    n_campbell : int
        Campbell speeds from 0 to 125 % of the operating speed.
    progress : callable or None
        Called with a short label before each step.
    studies : {"report", "full"} or None
        Resolution of the thesis chapter-3 design studies; None skips them.
    """
    step = progress or (lambda label: None)
    step("assembling the model")
    model = build_model(design)
    speed = model.speed
    step("natural frequencies")
    m0 = modes(model, 0.0, 10)
    mw = modes(model, speed, 10)
    step("Campbell diagram")
    top = max(speed, 1.0) * 1.25
    camp = campbell(model, np.linspace(0.0, top, n_campbell), n_modes=12)
    step("imbalance response over speed")
    speeds = np.linspace(0.02, 1.10, n_speeds) * max(speed, 1.0)
    Q1 = imbalance_loads(model)
    q = imbalance_response(model, speeds, Q1)  # (ndof, ncases, nspeeds)
    amp, case = worst_case_orbits(model, q)
    idx = np.arange(speeds.size)
    q_worst = q[:, case, idx]
    envelope = amp[:, case, idx]
    disp, force = actuator_response(model, q_worst, speeds)
    step("static loads and strength")
    q_static = static_response(model, external_static_load(model) + torque_load(model))
    q_at_speed = imbalance_response(model, [speed], Q1)[:, :, 0] if speed > 0 else np.zeros((model.dofs.size, 1), complex)
    reactions = bearing_reactions(model, q_static, q_at_speed)
    strength_static = strength_total = None
    notes = []
    buckling = None
    if model.shaft.laminate is not None:
        strength_static = shaft_safety_factor(model, q_static)
        totals = [shaft_safety_factor(model, q_static, q_at_speed[:, c]) for c in range(q_at_speed.shape[1])]
        strength_total = min(totals, key=lambda r: r.safety_factor)
        step("torsional buckling")
        from flexshaft.buckling import buckling_safety_factor, torsional_buckling_torque

        radius = (model.shaft.outer_diameter - design.shaft.wall_thickness) / 2
        result = torsional_buckling_torque(model.shaft.laminate, radius, design.shaft.length)
        torque = model.power / speed if speed > 0 else 0.0
        buckling = {
            "critical_torque_positive_Nm": result.torque_positive,
            "critical_torque_negative_Nm": result.torque_negative,
            "wave_number_positive": result.n_positive,
            "wave_number_negative": result.n_negative,
            "theory": result.theory,
            "torque_Nm": torque,
            "safety_factor": buckling_safety_factor(result, torque) if torque > 0 else float("inf"),
        }
    else:
        notes.append("ply strength and laminated-shell buckling need a lamina shaft material; skipped")
    step("thermal")
    thermal = None
    if model.shaft.laminate is not None:
        from flexshaft.studies.thermal import thermal_results

        thermal = thermal_results(design, model, self_heat=True)
    else:
        notes.append("shaft thermal model needs a laminated shaft (lamina conductivities); skipped")
    step("whirl stability")
    stab, comparison, gmap = _whirl(design, model, notes)
    design_studies_result = None
    if studies:
        step("design studies (thesis chapter 3)")
        from flexshaft.studies.chapter3 import design_studies
        from flexshaft.sweep import SweepError

        try:
            design_studies_result = design_studies(design, studies, progress=lambda label: step(f"design studies: {label}"))
        except (SweepError, ValueError) as exc:
            notes.append(f"design studies skipped: {str(exc).splitlines()[0]}")
    results = RunResults(
        model=model,
        summary=model_summary(model),
        modes_at_rest=modes_table(m0),
        modes_at_speed=modes_table(mw),
        mode_shapes=mw,
        campbell=camp,
        speeds=speeds,
        shaft_peak=envelope.max(axis=0),
        shaft_envelope=envelope,
        actuator_displacement=disp,
        actuator_force=force,
        static_displacement=q_static,
        strength_static=strength_static,
        strength_total=strength_total,
        imbalance_at_speed=q_at_speed,
        buckling=buckling,
        stability=stab,
        shaft_comparison=comparison,
        gain_map=gmap,
        thermal=thermal,
        design_studies=design_studies_result,
        notes=notes,
        bearing_reactions=reactions,
        imbalance_spinup=q,
    )
    step("requirements verdict")
    from flexshaft.studies.verdict import evaluate
    from flexshaft.studies.verdict_evidence import evidence_from_run

    results.verdict = evaluate(evidence_from_run(results), design.requirements)
    return results


def _whirl(design, model: Model, notes: list):
    """Stability of the design, the thesis's three-shaft comparison and the (K_p, K_d) map."""
    from flexshaft.analyses.stability import stability
    from flexshaft.design import DesignError
    from flexshaft.studies.whirl import compare_shafts, gain_stability_map

    top = max(model.speed, 1.0) * 1.5
    speeds = np.linspace(0.0, top, 61)
    stab = stability(model, speeds, n_modes=10)
    comparison = {}
    try:
        viscous = compare_shafts(design, speeds, "viscous", n_modes=8)
        hysteretic = compare_shafts(design, np.linspace(0.0, top, 31), "hysteretic", n_modes=8)
        comparison = {k: {"viscous": viscous[k], "hysteretic": hysteretic[k]} for k in viscous}
    except (DesignError, ValueError) as exc:
        notes.append(f"thesis shaft comparison skipped: {str(exc).splitlines()[0]}")
    gmap = None
    if model.actuators and model.all_pd:
        kp0 = model.actuators[0].controller.kp
        gmap = gain_stability_map(design, [kp0 / 30, kp0 / 5, kp0], [0.0, 300.0, 1000.0, 3000.0], speeds, n_modes=8)
    return stab, comparison, gmap
