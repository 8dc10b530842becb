"""The main job: every analysis of one design at its operating point (``flexshaft run``).

Returns plain data (:class:`RunResults`) that the report, the JSON output and notebooks use.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from flexshaft.analyses import imbalance_response, modes
from flexshaft.analyses.campbell import Campbell, campbell
from flexshaft.analyses.metal_strength import metal_strength
from flexshaft.analyses.misalignment import coupling_misalignment
from flexshaft.analyses.response import actuator_response, bearing_reactions, worst_case_orbits
from flexshaft.analyses.shaft_buckling import shaft_buckling
from flexshaft.analyses.shaft_strength import StrengthResult, shaft_safety_factor, static_load_parts
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.assembly.model import Model
from flexshaft.analyses.summary import model_summary, modes_table

__all__ = ["RunResults", "SCAN_BOTTOM", "SCAN_TOP", "run_analysis", "whirl_speeds"]

#: Spin speeds of the run's imbalance response, as fractions of the operating speed: from a
#: slow start to 30 % over it (the largest separation margin API requires above it is 26 %).
SCAN_BOTTOM, SCAN_TOP = 0.02, 1.30


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
    shaft_orbits: np.ndarray | None = None  # (nodes, cases, speeds) orbit amplitude at every shaft node [m]
    bearing_reactions: dict = field(default_factory=dict)  # name -> analyses.response.BearingReaction
    imbalance_spinup: object = None  # HarmonicResponse (ndof, ncases, n_speeds) over `speeds`
    metal_strength: object = None  # MetalStrength of the isotropic segments (None: no isotropic segment)
    coupling_misalignment: object = None  # CouplingMisalignment (None: no couplings)

    @property
    def spinup(self) -> np.ndarray:
        """Indices of ``speeds`` up to the operating speed (the spin-up proper)."""
        return np.flatnonzero(self.speeds <= self.model.speed * (1 + 1e-9))


def run_analysis(design, n_speeds: int = 651, n_campbell: int = 60, progress: Callable[[str], None] | None = None,
                 studies: str | None = "report") -> RunResults:
    """Analyse a design: modes, Campbell, spin-up imbalance response, static loads, strength,
    buckling, thermal, whirl stability, and the verdict against the design's ``[requirements]``.

    Parameters
    ----------
    n_speeds : int
        Spin speeds of the imbalance response from 2 % to 130 % of the operating speed (the
        spin-up and, beyond the operating speed, the critical-speed separation of the verdict).
    n_campbell : int
        Campbell speeds from 0 to 130 % of the operating speed.
    progress : callable or None
        Called with a short label before each step.
    studies : {"report", "full"} or None
        Resolution of the thesis design studies (chapter 3, and the whirl comparison of
        chapter 4); None skips them.
    """
    from flexshaft.assembly.size import check_problem_size

    step = progress or (lambda label: None)
    check_problem_size(design, "run", n_speeds=n_speeds, stacklevel=3)  # refuses what cannot finish; warns when large
    step("assembling the model")
    model = build_model(design)
    speed = model.speed
    top = max(speed, 1.0)
    step("natural frequencies")
    m0 = modes(model, 0.0, 10)
    mw = modes(model, speed, 10)
    step("Campbell diagram")
    camp = campbell(model, np.linspace(0.0, SCAN_TOP * top, n_campbell), n_modes=12)
    step("imbalance response over speed")
    speeds = np.linspace(SCAN_BOTTOM, SCAN_TOP, n_speeds) * top
    Q1 = imbalance_loads(model)
    q = imbalance_response(model, speeds, Q1)  # (ndof, ncases, nspeeds)
    amp, case = worst_case_orbits(model, q)
    idx = np.arange(speeds.size)
    q_worst = q[:, case, idx]
    envelope = amp[:, case, idx]
    disp, force = actuator_response(model, q_worst, speeds)
    step("static loads and strength")
    parts = static_load_parts(model)
    q_static = parts["external"] + parts["torque"]
    q_at_speed = imbalance_response(model, [speed], Q1)[:, :, 0] if speed > 0 else np.zeros((model.dofs.size, 1), complex)
    reactions = bearing_reactions(model, q_static, q_at_speed)
    strength_static = strength_total = None
    notes = []
    buckling = None
    if model.shaft.laminate is not None:
        strength_static = shaft_safety_factor(model, parts)
        totals = [shaft_safety_factor(model, parts, q_at_speed[:, c], leave_one_out=True)
                  for c in range(q_at_speed.shape[1])]
        strength_total = min(totals, key=lambda r: r.safety_factor)
        step("torsional buckling")
        buckling = shaft_buckling(model).to_dict()
    elif design.segmented:
        notes.append("ply strength and laminated-shell buckling assume one laminated tube; the shaft is segmented")
    else:
        notes.append("ply strength and laminated-shell buckling need a lamina shaft material; skipped")
    metal = misalignment = None
    if any(design.materials[seg.material].kind == "isotropic" for seg in model.segments):
        step("metal strength")
        metal = metal_strength(model, q_static, q_at_speed)
    if model.couplings:
        misalignment = coupling_misalignment(model, q_static, q_at_speed)
    step("thermal")
    thermal = None
    if model.shaft.laminate is not None:
        from flexshaft.studies.thermal import thermal_results

        thermal = thermal_results(design, model, self_heat=True)
    else:
        notes.append("shaft thermal model needs a laminated shaft (lamina conductivities); skipped")
    step("whirl stability")
    from flexshaft.analyses.stability import stability

    stab = stability(model, whirl_speeds(model), n_modes=10)
    comparison, gmap = {}, None
    design_studies_result = None
    if studies:
        step("whirl studies (thesis chapter 4)")
        comparison, gmap = _whirl_studies(design, model, notes)
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
        shaft_orbits=amp,
        bearing_reactions=reactions,
        imbalance_spinup=q,
        metal_strength=metal,
        coupling_misalignment=misalignment,
    )
    step("requirements verdict")
    from flexshaft.studies.verdict import evaluate
    from flexshaft.studies.verdict_evidence import evidence_from_run

    results.verdict = evaluate(evidence_from_run(results), design.requirements)
    return results


def whirl_speeds(model: Model) -> np.ndarray:
    """Speeds of the run's stability analyses: 41 from rest to 1.5 × the operating speed [rad/s]
    (the onset itself is solved between them)."""
    return np.linspace(0.0, 1.5 * max(model.speed, 1.0), 41)


def _whirl_studies(design, model: Model, notes: list):
    """The thesis's three-shaft comparison (viscous and hysteretic) and the (K_p, K_d) onset map."""
    from flexshaft.design import DesignError
    from flexshaft.studies.whirl import compare_shafts, gain_stability_map

    speeds = whirl_speeds(model)
    comparison = {}
    try:
        viscous = compare_shafts(design, speeds, "viscous", n_modes=8)
        hysteretic = compare_shafts(design, speeds, "hysteretic", n_modes=8)
        comparison = {k: {"viscous": viscous[k], "hysteretic": hysteretic[k]} for k in viscous}
    except (DesignError, ValueError) as exc:
        notes.append(f"thesis shaft comparison skipped: {str(exc).splitlines()[0]}")
    gmap = None
    if model.actuators and model.all_pd:
        kp0 = model.actuators[0].controller.kp
        gmap = gain_stability_map(design, [kp0 / 30, kp0 / 5, kp0], [0.0, 300.0, 1000.0, 3000.0], speeds, n_modes=8)
    return comparison, gmap
