"""The main job: every analysis of one design at its operating point (``flexshaft run``).

Returns plain data (:class:`RunResults`) that the report, the JSON output and notebooks use.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from flexshaft.analyses import imbalance_response, modes
from flexshaft.analyses.campbell import Campbell, campbell
from flexshaft.analyses.metal_strength import metal_strength
from flexshaft.analyses.misalignment import coupling_misalignment
from flexshaft.analyses.response import actuator_response, bearing_reactions, worst_case_orbits
from flexshaft.analyses.shaft_buckling import shaft_buckling
from flexshaft.analyses.shaft_strength import StrengthResult, shaft_safety_factor, static_load_parts
from flexshaft.analyses.summary import model_summary, modes_table
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.assembly.model import Model

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
    critical_speeds: object = None  # CriticalSpeeds without mode labels (analyses.criticals.scan_critical_speeds)

    @property
    def spinup(self) -> np.ndarray:
        """Indices of ``speeds`` up to the operating speed (the spin-up proper)."""
        return np.flatnonzero(self.speeds <= self.model.speed * (1 + 1e-9))


def run_analysis(
    design,
    n_speeds: int = 651,
    n_campbell: int = 60,
    progress: Callable[[str], None] | None = None,
    studies: str | None = "report",
    executor=None,
) -> RunResults:
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
    executor : concurrent.futures.Executor, optional
        A pool (e.g. :func:`flexshaft.parallel.pool.worker_pool`) that computes the studies while
        this process computes the design's own analyses; the results do not depend on it.
    """
    from flexshaft.assembly.size import check_problem_size

    step = progress or (lambda label: None)
    check_problem_size(design, "run", n_speeds=n_speeds, stacklevel=3)  # refuses what cannot finish; warns when large
    step("assembling the model")
    model = build_model(design)
    speed = model.speed
    top = max(speed, 1.0)
    speeds = np.linspace(SCAN_BOTTOM, SCAN_TOP, n_speeds) * top
    # The design's own analyses that do not need each other, as tasks: on a pool they run in
    # its workers while this process computes the rest (the results do not depend on where).
    own = _start_own_analyses(design, model, speeds, n_campbell, executor)
    started = _start_studies(design, model, studies, executor) if studies else None
    step("natural frequencies")
    m0 = modes(model, 0.0, 10)
    mw = modes(model, speed, 10)
    step("static loads and strength")
    Q1 = imbalance_loads(model)
    parts = static_load_parts(model)
    q_static = parts["external"] + parts["torque"]
    q_at_speed = (
        imbalance_response(model, [speed], Q1)[:, :, 0] if speed > 0 else np.zeros((model.dofs.size, 1), complex)
    )
    reactions = bearing_reactions(model, q_static, q_at_speed)
    strength_static = strength_total = None
    notes = []
    if model.shaft.laminate is not None:
        strength_static = shaft_safety_factor(model, parts)
        totals = [
            shaft_safety_factor(model, parts, q_at_speed[:, c], leave_one_out=True) for c in range(q_at_speed.shape[1])
        ]
        strength_total = min(totals, key=lambda r: r.safety_factor)
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
    if model.shaft.laminate is None:
        notes.append("shaft thermal model needs a laminated shaft (lamina conductivities); skipped")
    done = {key: outcome.value for key, outcome in own.results(step).items()}
    camp, buckling, thermal, stab = done["campbell"], done.get("buckling"), done.get("thermal"), done["stability"]
    q, amp, envelope, disp, force, criticals = done["imbalance"]
    comparison, gmap, design_studies_result = {}, None, None
    if started is not None:
        comparison, gmap, design_studies_result = _finish_studies(started, notes, step)
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
        critical_speeds=criticals,
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


def _start_own_analyses(design, model: Model, speeds: np.ndarray, n_campbell: int, executor):
    """Campbell diagram, spin-up imbalance response, torsional buckling, thermal and whirl
    stability of the design, as tasks (on ``executor`` when given)."""
    from flexshaft.parallel.tasks import Task, start_tasks

    top = max(model.speed, 1.0)
    # a worker rebuilds the model from the design (a few ms; the design pickles in a few kB);
    # in this process the tasks share the model already built
    source = design if executor is not None else model
    tasks = [
        Task("imbalance", "imbalance response over speed", _spinup_response, (source, speeds), cost=0.4),
        Task(
            "campbell", "Campbell diagram", _campbell, (source, np.linspace(0.0, SCAN_TOP * top, n_campbell)), cost=0.15
        ),
    ]
    if model.shaft.laminate is not None:
        tasks.append(Task("buckling", "torsional buckling", _buckling, (source,), cost=0.3))
        tasks.append(Task("thermal", "thermal", _thermal, (source,), cost=0.25))
    tasks.append(Task("stability", "whirl stability", _stability, (source,), cost=0.2))
    return start_tasks(tasks, executor)


def _model_of(source) -> Model:
    """The model of an own-analysis task's ``source``: a Model, or a design to build it from."""
    return source if isinstance(source, Model) else build_model(source)


def _spinup_response(source, speeds):
    """Worst-case imbalance response over ``speeds``: (q, orbits, worst envelope, actuator
    displacement and force, the lateral critical speeds found on it)."""
    from flexshaft.analyses.criticals import scan_critical_speeds

    model = _model_of(source)
    q = imbalance_response(model, speeds, imbalance_loads(model))  # (ndof, ncases, nspeeds)
    amp, case = worst_case_orbits(model, q)
    idx = np.arange(speeds.size)
    envelope = amp[:, case, idx]
    disp, force = actuator_response(model, q[:, case, idx], speeds)
    return q, amp, envelope, disp, force, scan_critical_speeds(model, speeds, amp)


def _campbell(source, speeds):
    return campbell(_model_of(source), speeds, n_modes=12)


def _buckling(source):
    return shaft_buckling(_model_of(source)).to_dict()


def _thermal(source):
    from flexshaft.thermal.study import thermal_results

    model = _model_of(source)
    return thermal_results(model.design, model, self_heat=True)


def _stability(source):
    from flexshaft.analyses.stability import stability

    model = _model_of(source)
    return stability(model, whirl_speeds(model), n_modes=10)


def _start_studies(design, model: Model, resolution: str, executor):
    """Start the thesis studies as tasks (on ``executor`` when given): the three-shaft whirl
    comparison (viscous and hysteretic), the (K_p, K_d) onset map and the chapter-3 studies."""
    from flexshaft.design import DesignError
    from flexshaft.parallel.tasks import Task, start_tasks
    from flexshaft.studies.chapter3 import plan_design_studies
    from flexshaft.studies.whirl import gain_stability_map, shaft_whirl, thesis_shaft_designs
    from flexshaft.sweep import SweepError

    speeds = whirl_speeds(model)
    notes, tasks = [], []
    try:
        shafts = thesis_shaft_designs(design)
    except (DesignError, ValueError) as exc:
        notes.append(f"thesis shaft comparison skipped: {str(exc).splitlines()[0]}")
        shafts = {}
    for label, shaft in shafts.items():  # viscous and hysteretic on one model and modal basis
        tasks.append(
            Task(
                f"whirl/shaft:{label}",
                f"whirl of the {label} shaft",
                shaft_whirl,
                (shaft, speeds),
                {"n_modes": 8},
                cost=0.3,
            )
        )
    if model.actuators and model.all_pd:
        kp0 = model.actuators[0].controller.kp
        for i, kp in enumerate((kp0 / 30, kp0 / 5, kp0)):
            tasks.append(
                Task(
                    f"whirl/gain_map:{i}",
                    "whirl onset over the actuator gains",
                    gain_stability_map,
                    (design, [kp], [0.0, 300.0, 1000.0, 3000.0], speeds),
                    {"n_modes": 8},
                    cost=0.45,
                )
            )
    whirl_keys = [t.key for t in tasks]
    chapter3 = None
    try:
        chapter3, chapter3_tasks = plan_design_studies(design, resolution)
        tasks += chapter3_tasks
    except (SweepError, ValueError) as exc:
        notes.append(f"design studies skipped: {str(exc).splitlines()[0]}")
    # one submission, the longest tasks first, so that the workers finish together
    run = start_tasks(tasks, executor, errors=(DesignError, ValueError))
    whirl = run.part(whirl_keys)
    if chapter3 is not None:
        chapter3 = (chapter3, run.part({t.key for t in tasks} - set(whirl_keys)))
    return whirl, chapter3, notes


def _finish_studies(started, notes: list, step):
    """Wait for the studies of :func:`_start_studies`: (shaft comparison, gain map, chapter 3)."""
    from flexshaft.studies.chapter3 import finish_design_studies
    from flexshaft.studies.whirl import stack_maps

    whirl, chapter3, start_notes = started
    notes.extend(start_notes)
    step("whirl studies (thesis chapter 4)")
    outcomes = whirl.results()
    failed = [o.error for o in outcomes.values() if o.error is not None and not o.key.startswith("whirl/gain_map")]
    comparison = {}
    if failed:
        notes.append(f"thesis shaft comparison skipped: {str(failed[0]).splitlines()[0]}")
    else:
        for key, outcome in outcomes.items():
            if key.startswith("whirl/shaft:"):
                comparison[key.partition(":")[2]] = outcome.value
    rows = [o for k, o in outcomes.items() if k.startswith("whirl/gain_map")]
    for o in rows:
        if o.error is not None:
            raise o.error
    gmap = stack_maps([o.value for o in rows]) if rows else None
    design_studies_result = None
    if chapter3 is not None:
        step("design studies (thesis chapter 3)")
        design_studies_result = finish_design_studies(
            *chapter3, progress=lambda label: step(f"design studies: {label}")
        )
    return comparison, gmap, design_studies_result
