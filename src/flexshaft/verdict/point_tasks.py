"""The analyses of an operating point that do not need each other, as tasks.

:func:`independent_tasks` starts them (:mod:`flexshaft.parallel.tasks`): the spin-up response with
the critical speeds on it, the Campbell diagram (with the report's detail), torsional buckling
and the shaft's thermal results (a laminated shaft), the whirl stability of the tracked modes,
every root of the closed loop at a few speeds with the magnetic-bearing loops (one task: the
loops' frequency grid is built on the closed-loop poles). With an executor
a worker rebuilds the model from the design (a few ms; the design pickles in a few kB); in this
process the tasks share the model already built.

The Campbell diagram tracks at least ``resolution.campbell_modes`` modes and as many more as it
takes to reach 1.1 × the highest frequency a check holds a mode against: the top of its speed
range times the largest excitation order (the shaft's 1/rev, the tail rotor's N/rev through its
gearbox, the main rotor's harmonics; :func:`campbell_ceiling`).
"""

from __future__ import annotations

import dataclasses
from concurrent.futures import Executor

import numpy as np

from flexshaft.analyses.bearing_loops import BearingLoop, bearing_loops
from flexshaft.analyses.campbell import Campbell, campbell
from flexshaft.analyses.criticals import CriticalSpeeds, scan_critical_speeds
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.modal import default_basis_size
from flexshaft.analyses.root_stability import RootStability, root_stability
from flexshaft.analyses.shaft_buckling import ShaftBuckling, shaft_buckling
from flexshaft.analyses.spinup_response import SpinupResponse, spinup_response, with_speeds
from flexshaft.analyses.stability import StabilityResult, stability
from flexshaft.analyses.torsional import torsional_excitations
from flexshaft.assembly import build_model
from flexshaft.assembly.balance import design_eccentricity
from flexshaft.assembly.model import Model
from flexshaft.design import Design
from flexshaft.parallel.tasks import Task, TaskRun, start_tasks
from flexshaft.resolution import Resolution
from flexshaft.thermal.study import ThermalResults, thermal_results

__all__ = [
    "campbell_ceiling",
    "campbell_mode_count",
    "campbell_task",
    "independent_tasks",
    "report_buckling",
    "report_thermal",
    "required_onset_speed",
    "root_speeds",
]


def independent_tasks(
    design: Design, model: Model, resolution: Resolution, executor: Executor | None, *, detail: bool
) -> TaskRun:
    """Start the independent analyses of one operating point (module docstring)."""
    source = design if executor is not None else model
    tasks = [Task("spinup", "imbalance response over speed", _spinup, (source, resolution), cost=0.4)]
    if detail and resolution.campbell_speeds:
        tasks.append(Task("campbell", "Campbell diagram", _campbell, (source, resolution), cost=0.15))
    if model.shaft.laminate is not None:
        tasks.append(Task("buckling", "torsional buckling", _buckling, (source, detail), cost=0.3))
        tasks.append(Task("thermal", "thermal", _thermal, (source, detail), cost=0.25))
    tasks.append(Task("stability", "whirl stability", _stability, (source, resolution), cost=0.2))
    roots = Task(
        "roots", "every closed-loop root and the bearing loops", _roots_and_loops, (source, resolution), cost=0.4
    )
    tasks.append(roots)
    return start_tasks(tasks, executor)


def _model_of(source: Model | Design) -> Model:
    """The model of a task's ``source``: a Model, or a design to build it from."""
    return source if isinstance(source, Model) else build_model(source)


def _spinup(source: Model | Design, resolution: Resolution) -> tuple[SpinupResponse, CriticalSpeeds]:
    """The spin-up response over the resolution's scan and the lateral critical speeds on it
    (not yet labelled with the Campbell modes, computed in parallel)."""
    model = _model_of(source)
    highest = highest_speed_fraction(model)
    response = spinup_response(model, resolution.spin_speeds(model.speed, highest))
    top = resolution.scan_top * highest
    if model.design is not None and not design_eccentricity(model.design) > 0.0:
        criticals = _criticals_without_imbalance(model, response.speeds, top)
    else:
        criticals = scan_critical_speeds(
            model, response.speeds, response.orbits, top, responses=response.response, basis=response.basis
        )
    # the refined peaks as samples of the response: the actuators' orbit and force there too;
    # and the operating speed and the highest one, where the spin-up checks end
    peaks = [c.speed for c in criticals.criticals or () if np.isfinite(c.amplification_factor)]
    return with_speeds(model, response, [*peaks, model.speed, highest * model.speed]), criticals


#: The mass eccentricity [m] the critical speeds of a design without imbalance are found with.
UNIT_ECCENTRICITY = 1e-6


def _criticals_without_imbalance(model: Model, speeds: np.ndarray, top: float) -> CriticalSpeeds:
    """The lateral critical speeds of a design without imbalance (``eccentricity = 0``, no
    ``balance_grade``: its spin-up response is zero and has no peak). Its critical speeds still
    exist and API still asks their separation: the response is linear in the eccentricity, so
    the peaks' speeds and amplification factors do not depend on its size; they are found with
    :data:`UNIT_ECCENTRICITY` on the design's own scan ``speeds`` [rad/s], and the peak orbits
    of that eccentricity are dropped (the spin-up checks read the design's own, zero, response)."""
    assert model.design is not None
    loads = model.design.loads.model_copy(update={"eccentricity": UNIT_ECCENTRICITY, "balance_grade": None})
    unit = dataclasses.replace(model, design=model.design.model_copy(update={"loads": loads}))
    scan = spinup_response(unit, speeds)  # the design's scan speeds, projected as its own
    found = scan_critical_speeds(unit, scan.speeds, scan.orbits, top, responses=scan.response, basis=scan.basis)
    if found.criticals is None:
        return found
    kept = tuple(
        dataclasses.replace(c, location={k: v for k, v in c.location.items() if k != "peak_orbit"})
        for c in found.criticals
    )
    return dataclasses.replace(found, criticals=kept)


def highest_speed_fraction(model: Model) -> float:
    """The highest operating speed as a fraction of the operating speed (``[operating]
    speed_range``; 1 without one): the spin-up checks run to it, the separation margins of the
    criticals above the range are measured from it."""
    operating = None if model.design is None else model.design.operating
    return 1.0 if operating is None or operating.speed_range is None else max(1.0, float(operating.speed_range[1]))


def campbell_ceiling(model: Model, resolution: Resolution) -> float:
    """The highest frequency a check holds a mode against [rad/s]: the Campbell diagram's top
    speed times the largest excitation order of the design (at least 1/rev)."""
    top = float(resolution.campbell_grid(model.speed)[-1]) if resolution.campbell_speeds else model.speed
    orders = [1.0] + ([e.ratio for e in torsional_excitations(model.design)] if model.design is not None else [])
    return top * max(orders)


def campbell_mode_count(model: Model, resolution: Resolution) -> int:
    """Modes the Campbell diagram tracks: at least ``resolution.campbell_modes``, and every
    undamped mode at rest (of K + K_a, M) below 1.1 × :func:`campbell_ceiling` plus two."""
    wanted = 1.1 * campbell_ceiling(model, resolution)
    basis = reduce(model, default_basis_size(resolution.campbell_modes))
    below = int(np.sum(np.sqrt(np.clip(basis.w2, 0.0, None)) < wanted))
    if below >= basis.size:  # the basis ends below the ceiling: a larger one
        basis = reduce(model, min(model.dofs.free.size, 4 * below))
        below = int(np.sum(np.sqrt(np.clip(basis.w2, 0.0, None)) < wanted))
    return min(max(resolution.campbell_modes, below + 2), model.dofs.free.size)


def campbell_task(model: Model, resolution: Resolution) -> Campbell:
    """The Campbell diagram of ``model`` at ``resolution`` (:func:`campbell_mode_count` modes)."""
    return campbell(model, resolution.campbell_grid(model.speed), n_modes=campbell_mode_count(model, resolution))


def _campbell(source: Model | Design, resolution: Resolution) -> Campbell:
    return campbell_task(_model_of(source), resolution)


def report_buckling(model: Model) -> ShaftBuckling:
    """Torsional buckling with the classical-shell comparison (the report's)."""
    return shaft_buckling(model, compare_classical=True)


def report_thermal(model: Model) -> ThermalResults:
    """Thermal results with the design sweeps and both loss models (the report's)."""
    return thermal_results(model.design, model, self_heat=True, detail=True)


def _buckling(source: Model | Design, detail: bool) -> ShaftBuckling:
    # the classical shell is the report's comparison, not the verdict's number
    return shaft_buckling(_model_of(source), compare_classical=detail)


def _thermal(source: Model | Design, detail: bool) -> ThermalResults:
    model = _model_of(source)
    return thermal_results(model.design, model, self_heat=True, detail=detail)


def _stability(source: Model | Design, resolution: Resolution) -> StabilityResult:
    model = _model_of(source)
    return stability(model, resolution.stability_speeds(model.speed), n_modes=resolution.modes)


def required_onset_speed(model: Model) -> float:
    """The speed the whirl-onset requirement asks the design to reach [rad/s]: (1 + the required
    onset margin) × the operating speed (the design's ``[requirements]``; no design: the
    operating speed). The every-root check solves there (:func:`root_speeds`), and the
    whirl-damping check holds every lateral mode below it (the forward whirls slower than the
    spin are the ones the rotating damping destabilises;
    :func:`~flexshaft.verdict.operating_point.lateral_modes`)."""
    margin = model.design.requirements.min_onset_margin if model.design is not None else 0.0
    return (1.0 + margin) * float(model.speed)


def root_speeds(model: Model) -> np.ndarray:
    """Speeds of the every-root check [rad/s]: rest, the operating speed and
    :func:`required_onset_speed`."""
    return np.unique([0.0, model.speed, required_onset_speed(model)])


def _roots_and_loops(
    source: Model | Design, resolution: Resolution
) -> tuple[RootStability, tuple[BearingLoop, ...] | None]:
    """Every root at :func:`root_speeds` and the loops at the operating speed (on a grid at the
    every-root check's closed-loop poles there: a passive check's up to the highest mode of its
    basis, above which its static corrections' roots have no physical meaning and the grid
    takes the natural frequencies instead, :func:`~flexshaft.analyses.loop_grid.frequency_grid`)."""
    model = _model_of(source)
    roots = root_stability(model, root_speeds(model))
    if not model.actuators:
        return roots, None
    poles = roots.resolved_roots_at(model.speed)
    return roots, bearing_loops(model, poles=poles, peak_samples=resolution.loop_peak_samples)
