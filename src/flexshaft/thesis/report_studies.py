"""The thesis studies ``flexshaft run`` reports beside a design's assessment.

The chapter-4 whirl comparison (the thesis's three shafts on the design's driveline, viscous and
hysteretic, :func:`~flexshaft.thesis.whirl.shaft_whirl`), the whirl onset over the actuator
gains (:func:`~flexshaft.thesis.whirl.gain_stability_map`) and the chapter-3 design studies
(:mod:`flexshaft.thesis.design_studies`). They are no part of the assessment (no check reads
them): :func:`start_thesis_studies` submits them to a pool as independent tasks, the caller
assesses the design on the same pool meanwhile, and :meth:`PendingThesisStudies.result` waits
for them.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from concurrent.futures import Executor
from dataclasses import dataclass

from flexshaft.analyses.stability import StabilityResult
from flexshaft.assembly import build_model
from flexshaft.design import DesignError
from flexshaft.parallel.tasks import Task, TaskRun, start_tasks
from flexshaft.resolution import REPORT, Resolution
from flexshaft.sweep.study import SweepError
from flexshaft.thesis.design_studies import DesignStudies, finish_design_studies, plan_design_studies
from flexshaft.thesis.whirl import StabilityMap, gain_stability_map, shaft_whirl, stack_maps, thesis_shaft_designs

__all__ = ["GAIN_MAP_KD", "PendingThesisStudies", "ThesisStudies", "start_thesis_studies"]

#: Derivative gains of the run's whirl-onset map [N s/m] (its proportional gains: the design's
#: first actuator's K_p, a fifth and a thirtieth of it).
GAIN_MAP_KD = (0.0, 300.0, 1000.0, 3000.0)
#: Modes tracked by the whirl comparison and the gain map.
_WHIRL_MODES = 8


@dataclass(frozen=True)
class ThesisStudies:
    """The thesis studies of a run, SI units.

    Attributes
    ----------
    shaft_comparison : mapping of str to mapping of str to StabilityResult
        Thesis shaft label -> {"viscous", "hysteretic"} -> its whirl stability (empty when the
        comparison does not apply to the design, ``notes`` say why).
    gain_map : StabilityMap or None
        Whirl onset over (K_p, K_d) of the active bearings (None without PD active bearings).
    design_studies : DesignStudies or None
        The chapter-3 studies (None when not asked for or when they do not apply).
    notes : tuple of str
        What was skipped and why.
    """

    shaft_comparison: Mapping[str, Mapping[str, StabilityResult]]
    gain_map: StabilityMap | None
    design_studies: DesignStudies | None
    notes: tuple[str, ...] = ()


@dataclass(frozen=True)
class PendingThesisStudies:
    """The thesis studies started by :func:`start_thesis_studies`; :meth:`result` waits for them."""

    whirl: TaskRun
    design_studies: tuple[DesignStudies, TaskRun] | None
    notes: tuple[str, ...]

    def result(self, progress: Callable[[str], None] | None = None) -> ThesisStudies:
        """Wait for the studies (``progress`` is called with a label before each part)."""
        step = progress or (lambda label: None)
        notes = list(self.notes)
        step("whirl studies (thesis chapter 4)")
        outcomes = self.whirl.results()
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
        gain_map = stack_maps([o.value for o in rows]) if rows else None
        studies = None
        if self.design_studies is not None:
            step("design studies (thesis chapter 3)")
            studies = finish_design_studies(
                *self.design_studies, progress=lambda label: step(f"design studies: {label}")
            )
        return ThesisStudies(comparison, gain_map, studies, tuple(notes))


def start_thesis_studies(
    design, resolution: str = "report", executor: Executor | None = None, *, whirl: Resolution = REPORT
) -> PendingThesisStudies:
    """Start the thesis studies of ``design`` as tasks (on ``executor`` when given, else they
    run in this process when their result is asked for).

    Parameters
    ----------
    resolution : {"report", "full"}
        Grids of the chapter-3 design studies
        (:data:`~flexshaft.thesis.design_studies.STUDY_GRIDS`).
    whirl : Resolution
        Speeds of the whirl comparison and the gain map: those of the assessment they are
        drawn beside (:meth:`~flexshaft.resolution.Resolution.stability_speeds`).
    """
    model = build_model(design)
    speeds = whirl.stability_speeds(model.speed)
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
                {"n_modes": _WHIRL_MODES},
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
                    (design, [kp], list(GAIN_MAP_KD), speeds),
                    {"n_modes": _WHIRL_MODES},
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
    started = None if chapter3 is None else (chapter3, run.part({t.key for t in tasks} - set(whirl_keys)))
    return PendingThesisStudies(run.part(whirl_keys), started, tuple(notes))
