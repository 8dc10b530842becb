"""The design studies of thesis chapter 3 in one call: every study of docs/studies.md (1-6 and
the stability margin map of 8) on one design.

:func:`design_studies` runs them at a chosen resolution (:data:`STUDY_GRIDS`) and returns a
:class:`DesignStudies` of labelled :class:`xarray.Dataset` results (units in attributes) and the
headline numbers; :func:`flexshaft.report.studies_section.design_studies_section` draws the
figures and tables for the ``flexshaft run`` report; :func:`headline` gives the headline numbers
as JSON-ready data, beside the thesis's.

Resolutions (CPU time on the 2-core machine, tuned design; ``flexshaft run`` divides it
among its worker processes, benchmarks/studies_timing.py; see docs/studies.md):

* ``"report"``: about 10 s of studies (ply angle every 2.5°, an 8 × 8 two-angle grid including
  55°, 9 walls, 13 K_p, a 20 × 20 × 300 spin-up map, a 4 × 4 stability map at 16 speeds);
* ``"full"``: the thesis-figure resolution (1°, 5° grid, 23 walls, 31 K_p, 30 × 30 × 400,
  8 × 8 × 31); about 25 s.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, Union

import numpy as np

from flexshaft.analyses.labelled import LabelledArrays
from flexshaft.assembly import build_model
from flexshaft.design import baseline_design
from flexshaft.files import atomic_write_text
from flexshaft.netcdf import write_labelled_netcdf, write_netcdf
from flexshaft.parallel.tasks import Task, TaskRun, start_tasks
from flexshaft.resolution import REPORT
from flexshaft.sweep.study import SweepError
from flexshaft.thesis.buckling_sweep import buckling_study
from flexshaft.thesis.gain import gain_paths, proportional_gain_study
from flexshaft.thesis.ply_angle import ply_angle_study
from flexshaft.thesis.spinup_maps import spinup_studies
from flexshaft.thesis.two_angles import best_pair, two_angle_study
from flexshaft.thesis.wall import FORCED_WALLS, forced_response, quietest_spinup_wall, wall_thickness_study
from flexshaft.thesis.whirl import gain_stability_map, stability_dataset, stack_maps
from flexshaft.units import rad_s_to_rpm

if TYPE_CHECKING:
    from xarray import Dataset

#: A study's results: a Dataset from :func:`design_studies`; the plain-array content of one
#: (:class:`~flexshaft.analyses.labelled.LabelledArrays`, ``.to_dataset()``) from
#: :func:`start_design_studies`, as they travel from the workers to ``flexshaft run``'s report.
StudyData = Union["Dataset", LabelledArrays]

__all__ = [
    "COSTS",
    "DesignStudies",
    "STUDY_GRIDS",
    "StudyData",
    "TABLE_ANGLES",
    "THESIS",
    "as_datasets",
    "design_studies",
    "finish_design_studies",
    "headline",
    "nearest",
    "plan_design_studies",
    "save_study_data",
    "start_design_studies",
    "two_angle_name",
]


#: Thesis chapter 3 headline results (Ocalan 2002), for comparison.
THESIS = {
    "optimal_angle_deg": 55.0,
    "best_two_angle_deg": [55.0, 0.0],
    "best_wall_m": 0.003,
    "tuned_peak_before_m": 0.038,
    "tuned_peak_after_m": 0.004,
}

#: Grids of each resolution. Angles [deg], walls [m], gains [N/m], [N s/m].
STUDY_GRIDS: dict[str, dict[str, Any]] = {
    "report": {
        "angles": np.arange(2.5, 90.0, 2.5),
        "two_angles": np.array([0.0, 15.0, 30.0, 45.0, 55.0, 60.0, 75.0, 90.0]),
        "walls": np.array([1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0]) * 1e-3,
        "kp": np.logspace(5, 8, 13),
        "map_kp": np.logspace(5, 8, 20),
        "map_kd": np.concatenate([[0.0], np.logspace(1, 4.5, 19)]),
        "map_speeds": 300,
        "forced_speeds": 300,
        "stab_kp": np.array([3e5, 2e6, 1e7, 5e7]),
        "stab_kd": np.array([0.0, 300.0, 1170.0, 3000.0]),
        "stab_speeds": 16,
    },
    "full": {
        "angles": np.arange(0.0, 90.01, 1.0),
        "two_angles": np.arange(0.0, 90.01, 5.0),
        "walls": np.arange(0.5, 6.01, 0.25) * 1e-3,
        "kp": np.logspace(5, 8, 31),
        "map_kp": np.logspace(5, 8, 30),
        "map_kd": np.concatenate([[0.0], np.logspace(1, 4.5, 29)]),
        "map_speeds": 400,
        "forced_speeds": 600,
        "stab_kp": np.logspace(5, 8, 8),
        "stab_kd": np.concatenate([[0.0], np.logspace(2, 4, 7)]),
        "stab_speeds": 31,
    },
}

#: Ply angles listed in the critical-stress table (Table 3.3) besides the optimum [deg].
TABLE_ANGLES = (15.0, 30.0, 45.0, 55.0, 60.0, 75.0)


@dataclass(frozen=True)
class DesignStudies:
    """Results of :func:`design_studies` (SI units; datasets carry units in attributes).

    A study that does not apply to the design (no lamina shaft material, no active bearing)
    is None, with the reason in ``notes``.
    """

    design_name: str
    resolution: str
    operating_speed: float  # rad/s
    ply_angle: StudyData | None = None  # over alpha [deg]: safety factor and critical-ply stresses
    two_angle: StudyData | None = None  # over (alpha, beta) [deg]
    wall: StudyData | None = None  # over wall_thickness [m]
    forced_response: StudyData | None = None  # (wall_thickness, speed): max shaft orbit [m]
    gain: StudyData | None = None  # over kp [N/m]
    buckling: StudyData | None = None  # over wall_thickness [m]
    spinup_map: StudyData | None = None  # over (kp, kd)
    surfaces: StudyData | None = None  # (case, x, speed): shaft orbit [m]
    tuned: StudyData | None = None  # (case, speed): before/after spin-up curves
    stability_map: StudyData | None = None  # over (kp, kd): onset speed, damping ratio
    optimal_angle: float | None = None  # deg
    optimal_angle_safety_factor: float | None = None
    best_two_angle: tuple[float, float] | None = None  # (alpha, beta) deg
    best_two_angle_safety_factor: float | None = None
    best_wall: float | None = None  # m, largest safety factor with imbalance
    best_wall_safety_factor: float | None = None
    gains_before: tuple[float, float] | None = None  # (kp, kd) of the design
    gains_after: tuple[float, float] | None = None  # tuned (kp, kd)
    peak_before: float | None = None  # m, refined spin-up peak
    peak_after: float | None = None  # m
    peak_speed_before: float | None = None  # rad/s
    peak_speed_after: float | None = None  # rad/s
    actuator_gap: float | None = None  # m, limit used for the tuned gains
    timings: Mapping[str, float] = field(default_factory=dict)  # study -> seconds
    notes: tuple[str, ...] = ()

    @property
    def elapsed(self) -> float:
        """Total time of the studies [s]."""
        return float(sum(self.timings.values()))


def _reporter(progress) -> Callable[[str], None]:
    if callable(progress):
        return progress
    return lambda label: None


#: Relative cost of each study (seconds measured at the "report" resolution on the tuned
#: design, one K_p row for the stability map); it only orders the tasks on a worker pool,
#: longest first, so that the workers finish at about the same time.
COSTS = {
    "ply_angle": 1.2,
    "two_angle": 0.75,  # each unordered ply pair solved once (thesis/two_angles.py)
    "wall": 2.9,
    "forced_response": 0.45,
    "gain": 0.65,
    "buckling": 1.7,
    "spinup": 1.2,
    "stability": 0.2,
}


def design_studies(
    design=None,
    resolution: str = "report",
    progress=None,
    jobs: int = 1,
    actuator_gap: float | None = None,
    executor=None,
) -> DesignStudies:
    """Run the thesis chapter-3 studies on ``design`` (default: the embedded baseline).

    Parameters
    ----------
    design : Design, optional
    resolution : {"report", "full"}
        Grid sizes, see :data:`STUDY_GRIDS`.
    progress : callable or bool, optional
        A callable is called with a short label before each study (like
        :func:`flexshaft.verdict.assess.assess`); True shows the sweeps' progress bars.
    jobs : int
        Local worker processes for each sweep-engine study (1: in process; below ~5 s of
        work the process start-up costs more than it saves).
    actuator_gap : float, optional
        Largest allowed actuator relative orbit during spin-up [m] when choosing the tuned
        gains (the auxiliary-bearing gap, thesis figure 3.8); None: no limit.
    executor : concurrent.futures.Executor, optional
        Run the studies as independent tasks on this pool (e.g.
        :func:`flexshaft.parallel.pool.worker_pool`); the results are the same as in this process.
        Each study then runs in one worker: ``jobs`` must be 1.
    """
    if executor is not None and jobs != 1:
        raise ValueError(f"jobs must be 1 when the studies run on an executor (got jobs={jobs})")
    res, run = start_design_studies(
        design, resolution, actuator_gap, executor, jobs=jobs, progress_bars=progress is True
    )
    return as_datasets(finish_design_studies(res, run, progress))


def as_datasets(results: DesignStudies) -> DesignStudies:
    """``results`` with every study as an :class:`xarray.Dataset` (imports xarray)."""
    found = {name: getattr(results, name) for name in _DATASETS}
    return replace(results, **{k: v.to_dataset() for k, v in found.items() if isinstance(v, LabelledArrays)})


def start_design_studies(
    design=None,
    resolution: str = "report",
    actuator_gap: float | None = None,
    executor=None,
    *,
    jobs: int = 1,
    progress_bars: bool = False,
) -> tuple[DesignStudies, TaskRun]:
    """Start the studies of :func:`design_studies` (on ``executor`` when given) and return
    ``(DesignStudies, TaskRun)`` for :func:`finish_design_studies`: the caller can compute
    something else while a pool works on them."""
    res, tasks = plan_design_studies(design, resolution, actuator_gap, jobs=jobs, progress_bars=progress_bars)
    return res, start_tasks(tasks, executor, errors=(SweepError, ValueError))


def plan_design_studies(
    design=None,
    resolution: str = "report",
    actuator_gap: float | None = None,
    *,
    jobs: int = 1,
    progress_bars: bool = False,
) -> tuple[DesignStudies, list[Task]]:
    """``(DesignStudies, tasks)``: the empty results (with the notes of the studies that do
    not apply) and the :class:`~flexshaft.parallel.tasks.Task` of each study, to start
    together with other tasks (:func:`flexshaft.parallel.tasks.start_tasks`)."""
    if resolution not in STUDY_GRIDS:
        raise ValueError(f"resolution must be one of {sorted(STUDY_GRIDS)}, got {resolution!r}")
    grid = STUDY_GRIDS[resolution]
    design = design if design is not None else baseline_design()
    # the studies' results travel from the workers as plain arrays: no xarray in any process
    # until a Dataset is asked for (design_studies) or written (save_study_data)
    run = {"jobs": int(jobs), "progress": bool(progress_bars), "as_arrays": True}
    model = build_model(design)
    laminated = model.shaft.laminate is not None
    active = bool(model.actuators) and model.all_pd
    tasks, notes = [], []

    def task(key, label, function, *args):
        tasks.append(Task(key, label, function, args, cost=COSTS[key.partition(":")[0]]))

    if laminated:
        task("ply_angle", "study 1: ply angle", _ply_angle_task, design, grid["angles"], run)
        task("two_angle", "study 2: two-angle map", _two_angle_task, design, grid["two_angles"], run)
    else:
        notes.append("ply-angle studies skipped: the shaft material is not a lamina")
    task("wall", "study 3: wall thickness", _wall_task, design, grid["walls"], run, laminated)
    task(
        "forced_response",
        "study 3: forced response",
        _forced_response_task,
        design,
        FORCED_WALLS,
        grid["forced_speeds"],
    )
    if laminated and active and gain_paths(design):
        task("gain", "study 4: proportional gain", _gain_task, design, grid["kp"], run)
    elif laminated:
        notes.append("the K_p study needs active bearings with PD laws (kp); skipped")
    if laminated:
        task("buckling", "study 5: torsional buckling", _buckling_task, design, grid["walls"], run)
    if active:
        task("spinup", "study 6: spin-up gain map", _spinup_task, design, grid, actuator_gap)
        for i, kp in enumerate(grid["stab_kp"]):  # one task per K_p row: the pool balances better
            task(f"stability:{i}", "stability margin map", _stability_row_task, design, grid, kp)
    else:
        notes.append("spin-up and stability maps need PD active bearings; skipped")
    res = DesignStudies(
        design_name=str(design.name),
        resolution=resolution,
        operating_speed=float(model.speed),
        actuator_gap=actuator_gap,
        notes=tuple(notes),
    )
    return res, tasks


def finish_design_studies(res: DesignStudies, run: TaskRun, progress=None) -> DesignStudies:
    """Wait for the studies started by :func:`start_design_studies`: ``res`` with their results.

    A study that cannot run on the design (a :class:`~flexshaft.sweep.SweepError` or
    ``ValueError``) is left None with the reason in ``notes``.
    """
    outcomes = run.results(_reporter(progress))
    rows, failed, found = [], set(), {}
    notes, timings = list(res.notes), dict(res.timings)
    for task in run.tasks:
        outcome = outcomes[task.key]
        name = task.key.partition(":")[0]
        timings[name] = timings.get(name, 0.0) + outcome.seconds
        if outcome.error is not None:
            if task.label not in failed:
                notes.append(f"{task.label} skipped: {str(outcome.error).splitlines()[0]}")
            failed.add(task.label)
            continue
        fields = dict(outcome.value)
        notes.extend(fields.pop("notes", []))
        rows.extend(fields.pop("stability_rows", []))
        found.update(fields)
    if rows and "stability margin map" not in failed:
        found["stability_map"] = stability_dataset(stack_maps(rows))
    return replace(res, **found, timings=timings, notes=tuple(notes))


def _ply_angle_task(design, angles, run) -> dict:
    ds = ply_angle_study(angles, design=design, **run)
    i = int(np.nanargmax(ds["safety_factor"].values))
    return {
        "ply_angle": ds,
        "optimal_angle": float(ds.alpha.values[i]),
        "optimal_angle_safety_factor": float(ds["safety_factor"].values[i]),
    }


def _two_angle_task(design, angles, run) -> dict:
    ds = two_angle_study(angles, angles, design=design, **run)
    i, j = best_pair(ds["safety_factor"].values, ds.alpha.values, ds.beta.values)
    return {
        "two_angle": ds,
        "best_two_angle": (float(ds.alpha.values[i]), float(ds.beta.values[j])),
        "best_two_angle_safety_factor": float(ds["safety_factor"].values[i, j]),
    }


def _wall_task(design, walls, run, laminated: bool) -> dict:
    ds = wall_thickness_study(walls, design=design, **run)
    out = {"wall": ds}
    if laminated:
        sf = ds["safety_factor"].values
        i = int(np.nanargmax(sf))
        out["best_wall"], out["best_wall_safety_factor"] = float(ds.wall_thickness.values[i]), float(sf[i])
        if i in (0, sf.size - 1):
            out["notes"] = [
                f"the best wall ({out['best_wall'] * 1e3:g} mm) is at the end of the range studied: "
                "the safety factor is monotonic there"
            ]
    return out


def _forced_response_task(design, walls, n_speeds) -> dict:
    return {"forced_response": forced_response(design, walls, n_speeds)}


def _gain_task(design, kps, run) -> dict:
    return {"gain": proportional_gain_study(kps, design=design, **run)}


def _buckling_task(design, walls, run) -> dict:
    return {"buckling": buckling_study(walls, design=design, **run)}


def _spinup_task(design, grid, actuator_gap) -> dict:
    return spinup_studies(build_model(design), grid, actuator_gap)


def _stability_row_task(design, grid, kp: float) -> dict:
    speeds = np.linspace(0.0, REPORT.whirl_top * max(design.operating.speed_rad_s, 1.0), grid["stab_speeds"])
    return {"stability_rows": [gain_stability_map(design, [kp], grid["stab_kd"], speeds, n_modes=8)]}


def _f(value) -> float | None:
    if value is None:
        return None
    value = float(value)
    return value if math.isfinite(value) else None


def headline(results: DesignStudies) -> dict:
    """The studies' headline numbers beside the thesis's, JSON-ready (SI units)."""
    r = results
    out = {
        "design": r.design_name,
        "resolution": r.resolution,
        "elapsed_s": round(r.elapsed, 3),
        "optimal_angle_deg": _f(r.optimal_angle),
        "optimal_angle_safety_factor": _f(r.optimal_angle_safety_factor),
        "best_two_angle_deg": list(r.best_two_angle) if r.best_two_angle else None,
        "best_two_angle_layup": two_angle_name(r.best_two_angle) if r.best_two_angle else None,
        "best_two_angle_safety_factor": _f(r.best_two_angle_safety_factor),
        "best_wall_m": _f(r.best_wall),
        "best_wall_safety_factor": _f(r.best_wall_safety_factor),
        "gains_before": {"kp_N_per_m": _f(r.gains_before[0]), "kd_N_s_per_m": _f(r.gains_before[1])}
        if r.gains_before
        else None,
        "gains_after": {"kp_N_per_m": _f(r.gains_after[0]), "kd_N_s_per_m": _f(r.gains_after[1])}
        if r.gains_after
        else None,
        "peak_deflection_before_m": _f(r.peak_before),
        "peak_deflection_after_m": _f(r.peak_after),
        "peak_speed_before_rpm": _f(None if r.peak_speed_before is None else rad_s_to_rpm(r.peak_speed_before)),
        "peak_speed_after_rpm": _f(None if r.peak_speed_after is None else rad_s_to_rpm(r.peak_speed_after)),
        "actuator_gap_m": _f(r.actuator_gap),
        "thesis": dict(THESIS),
        "timings_s": {k: round(float(v), 3) for k, v in r.timings.items()},
        "notes": list(r.notes),
    }
    quietest = quietest_spinup_wall(r.wall) if r.wall is not None else None
    out["quietest_spinup_wall_m"] = _f(quietest[0]) if quietest else None
    out["quietest_spinup_peak_m"] = _f(quietest[1]) if quietest else None
    if r.ply_angle is not None:
        out["ply_angle_safety_factor_at_55_deg"] = _f(nearest(r.ply_angle, "alpha", 55.0)["safety_factor"])
    if r.two_angle is not None:
        out["two_angle_safety_factor_at_55_0"] = _f(
            r.two_angle["safety_factor"].sel(alpha=55.0, beta=0.0, method="nearest")
        )
    return out


_DATASETS = (
    "ply_angle",
    "two_angle",
    "wall",
    "forced_response",
    "gain",
    "buckling",
    "spinup_map",
    "surfaces",
    "tuned",
    "stability_map",
)


def save_study_data(results: DesignStudies, folder: str | Path) -> dict[str, Path]:
    """Write every study's Dataset to ``folder/study_NAME.nc`` (netCDF, units in attributes)
    and the headline to ``folder/design_studies.json``; returns the paths by name.

    Plain labelled arrays (``flexshaft run``'s) are written without building their Datasets
    (:func:`~flexshaft.netcdf.write_labelled_netcdf`: the same files, without importing
    xarray in the run's process)."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    paths = {}
    for name in _DATASETS:
        ds = getattr(results, name)
        if ds is not None:
            paths[name] = folder / f"study_{name}.nc"
            if isinstance(ds, LabelledArrays):  # as flexshaft run's workers send them: xarray not needed
                write_labelled_netcdf(ds, paths[name])
            else:
                write_netcdf(ds, paths[name])
    paths["headline"] = folder / "design_studies.json"
    atomic_write_text(paths["headline"], json.dumps(headline(results), indent=2))
    return paths


def nearest(ds, dim: str, value: float):
    return ds.sel({dim: value}, method="nearest")


def two_angle_name(pair) -> str:
    a, b = (f"{v:g}" for v in pair)
    return f"({a}/-{a}/{b}/-{b})s".replace("/-0/", "/0/").replace("/-0)", "/0)")
