"""Every analysis of a design at one operating point: the recipe the verdict judges.

:func:`analyse_point` builds the design's model and runs, at the grids of a
:class:`~flexshaft.resolution.Resolution`, the analyses the requirements read (modes at the
operating speed, the spin-up imbalance response and the lateral critical speeds on it, static
loads and bearing reactions, ply and metal strength, coupling misalignment, torsional buckling,
the shaft's self-heating, whirl stability) and, at a report's resolution, what only the report
shows (modes at rest, the Campbell diagram, the strength's load shares, the classical-shell
buckling, the thermal sweeps). It returns them as a frozen :class:`PointAnalyses`.

One operating point is the design's own (its ``[operating]`` speed and power, its materials at
their reference temperature). An operating envelope (several points, each a variant of the
design) calls :func:`analyse_point` once per point.

Parallel: the analyses that do not need each other (the spin-up response with its critical
speeds, the Campbell diagram, buckling, thermal, whirl stability) are tasks
(:mod:`flexshaft.parallel.tasks`); with an ``executor`` they run in its workers, each rebuilding
the model from the design, while this process computes the rest. The results do not depend on
where they were computed (tests/test_tasks.py).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from concurrent.futures import Executor
from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.campbell import Campbell, campbell
from flexshaft.analyses.criticals import CriticalSpeeds, scan_critical_speeds
from flexshaft.analyses.metal_strength import MetalStrength, metal_strength
from flexshaft.analyses.misalignment import CouplingMisalignment, coupling_misalignment
from flexshaft.analyses.modal import Modes, modes
from flexshaft.analyses.response import BearingReaction, bearing_reactions, imbalance_response
from flexshaft.analyses.shaft_buckling import ShaftBuckling, shaft_buckling
from flexshaft.analyses.shaft_strength import StrengthResult, shaft_safety_factor, static_load_parts
from flexshaft.analyses.spinup_response import SpinupResponse, spinup_response
from flexshaft.analyses.stability import StabilityResult, stability
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.assembly.model import Model
from flexshaft.design import Design
from flexshaft.parallel.tasks import Task, TaskRun, start_tasks
from flexshaft.resolution import Resolution
from flexshaft.thermal.study import ThermalResults, thermal_results

__all__ = ["PointAnalyses", "analyse_point"]


@dataclass(frozen=True, kw_only=True)
class PointAnalyses:
    """The analyses of a design at one operating point, SI units.

    Attributes
    ----------
    design : Design
    resolution : Resolution
        The grids they were computed at.
    model : Model
        The assembled model.
    modes_at_rest : Modes or None
        Damped modes at rest (None below the report's detail).
    modes_at_speed : Modes
        Damped modes at the operating speed.
    campbell : Campbell or None
        Campbell diagram (None without Campbell speeds).
    spinup : SpinupResponse
        Imbalance response over the spin-up scan (worst case at each speed).
    criticals : CriticalSpeeds
        Lateral critical speeds on the spin-up scan, labelled with the Campbell modes.
    static_displacement : ndarray
        Static response to the external loads and the torque (ndof,) [m, rad].
    imbalance_at_speed : ndarray
        Imbalance response at the operating speed (ndof, n_cases) [m, rad].
    bearing_reactions : mapping of str to BearingReaction
        Static and imbalance loads of every bearing.
    strength_static, strength_total : StrengthResult or None
        Tsai-Wu of the laminated shaft under the static loads, and with the imbalance at the
        operating speed (worst load case); None without a one-piece laminated shaft.
    buckling : ShaftBuckling or None
        Torsional buckling of the laminated shaft (None without one).
    metal_strength : MetalStrength or None
        Fatigue, yield and buckling of the isotropic segments (None without one).
    coupling_misalignment : CouplingMisalignment or None
        Static and whirling angle of every coupling (None without couplings).
    thermal : ThermalResults or None
        Shaft temperature and self-heating (None without a laminated shaft).
    stability : StabilityResult
        Whirl stability from rest over the resolution's whirl speeds.
    notes : tuple of str
        Analyses skipped and why.
    """

    design: Design
    resolution: Resolution
    model: Model
    modes_at_rest: Modes | None
    modes_at_speed: Modes
    campbell: Campbell | None
    spinup: SpinupResponse
    criticals: CriticalSpeeds
    static_displacement: np.ndarray
    imbalance_at_speed: np.ndarray
    bearing_reactions: Mapping[str, BearingReaction]
    strength_static: StrengthResult | None
    strength_total: StrengthResult | None
    buckling: ShaftBuckling | None
    metal_strength: MetalStrength | None
    coupling_misalignment: CouplingMisalignment | None
    thermal: ThermalResults | None
    stability: StabilityResult
    notes: tuple[str, ...] = ()

    @property
    def operating_speed(self) -> float:
        """Ω_op [rad/s]."""
        return float(self.model.speed)


def analyse_point(
    design: Design,
    resolution: Resolution,
    *,
    executor: Executor | None = None,
    progress: Callable[[str], None] | None = None,
) -> PointAnalyses:
    """Every analysis of ``design`` at its operating point (see the module docstring).

    Parameters
    ----------
    design : Design
        A validated design.
    resolution : Resolution
        Grid sizes and ranges, and whether to compute what only the report shows.
    executor : concurrent.futures.Executor, optional
        A pool (e.g. :func:`flexshaft.parallel.pool.worker_pool`) for the independent analyses.
    progress : callable, optional
        Called with a short label before each step.
    """
    step = progress or _quiet
    step("assembling the model")
    model = build_model(design)
    speed = model.speed
    own = _start_independent(design, model, resolution, executor)
    step("natural frequencies")
    at_rest = modes(model, 0.0, resolution.modes) if resolution.report_detail else None
    at_speed = modes(model, speed, resolution.modes)
    step("static loads and strength")
    parts = static_load_parts(model)
    q_static = parts["external"] + parts["torque"]
    q_at_speed = (
        imbalance_response(model, [speed], imbalance_loads(model))[:, :, 0]
        if speed > 0
        else np.zeros((model.dofs.size, 1), complex)
    )
    reactions = bearing_reactions(model, q_static, q_at_speed)
    strength_static = strength_total = None
    notes = []
    if model.shaft.laminate is not None:
        strength_static = shaft_safety_factor(model, parts)
        # the leave-one-out load shares are the report's; the minimum is the same without them
        totals = [
            shaft_safety_factor(model, parts, q_at_speed[:, c], leave_one_out=resolution.report_detail)
            for c in range(q_at_speed.shape[1])
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
    spinup, criticals = done["spinup"]
    camp = done.get("campbell")
    return PointAnalyses(
        design=design,
        resolution=resolution,
        model=model,
        modes_at_rest=at_rest,
        modes_at_speed=at_speed,
        campbell=camp,
        spinup=spinup,
        criticals=criticals.labelled(camp),
        static_displacement=q_static,
        imbalance_at_speed=q_at_speed,
        bearing_reactions=reactions,
        strength_static=strength_static,
        strength_total=strength_total,
        buckling=done.get("buckling"),
        metal_strength=metal,
        coupling_misalignment=misalignment,
        thermal=done.get("thermal"),
        stability=done["stability"],
        notes=tuple(notes),
    )


def _quiet(label: str) -> None:
    """No progress display."""


def _start_independent(design: Design, model: Model, resolution: Resolution, executor: Executor | None) -> TaskRun:
    """The spin-up response (with the critical speeds on it), the Campbell diagram, torsional
    buckling, thermal and whirl stability of the design, as tasks (on ``executor`` when given)."""
    # a worker rebuilds the model from the design (a few ms; the design pickles in a few kB);
    # in this process the tasks share the model already built
    source = design if executor is not None else model
    tasks = [Task("spinup", "imbalance response over speed", _spinup, (source, resolution), cost=0.4)]
    if resolution.campbell_speeds:
        tasks.append(Task("campbell", "Campbell diagram", _campbell, (source, resolution), cost=0.15))
    if model.shaft.laminate is not None:
        tasks.append(Task("buckling", "torsional buckling", _buckling, (source, resolution), cost=0.3))
        tasks.append(Task("thermal", "thermal", _thermal, (source, resolution), cost=0.25))
    tasks.append(Task("stability", "whirl stability", _stability, (source, resolution), cost=0.2))
    return start_tasks(tasks, executor)


def _model_of(source: Model | Design) -> Model:
    """The model of a task's ``source``: a Model, or a design to build it from."""
    return source if isinstance(source, Model) else build_model(source)


def _spinup(source: Model | Design, resolution: Resolution) -> tuple[SpinupResponse, CriticalSpeeds]:
    """The spin-up response over the resolution's scan and the lateral critical speeds on it
    (not yet labelled with the Campbell modes, computed in parallel)."""
    model = _model_of(source)
    response = spinup_response(model, resolution.spin_speeds(model.speed))
    return response, scan_critical_speeds(model, response.speeds, response.orbits, resolution.scan_top)


def _campbell(source: Model | Design, resolution: Resolution) -> Campbell:
    model = _model_of(source)
    return campbell(model, resolution.campbell_grid(model.speed), n_modes=resolution.campbell_modes)


def _buckling(source: Model | Design, resolution: Resolution) -> ShaftBuckling:
    # the classical shell is the report's comparison, not the verdict's number
    return shaft_buckling(_model_of(source), compare_classical=resolution.report_detail)


def _thermal(source: Model | Design, resolution: Resolution) -> ThermalResults:
    model = _model_of(source)
    return thermal_results(model.design, model, self_heat=True, detail=resolution.report_detail)


def _stability(source: Model | Design, resolution: Resolution) -> StabilityResult:
    model = _model_of(source)
    return stability(model, resolution.stability_speeds(model.speed), n_modes=resolution.modes)
