"""The design studies of thesis chapter 3 in one call, with their report section.

:func:`design_studies` runs every study of docs/studies.md (1-6 and the stability margin map of
8) on one design at a chosen resolution and returns a :class:`DesignStudies` of labelled
:class:`xarray.Dataset` results (units in attributes) and the headline numbers;
:func:`flexshaft.report.studies_section.design_studies_section` draws the figures and tables
for the ``flexshaft run`` report;
:func:`headline` gives the headline numbers as JSON-ready data, beside the thesis's.

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
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft.units import rad_s_to_rpm

__all__ = [
    "COSTS",
    "DesignStudies",
    "RESOLUTIONS",
    "THESIS",
    "design_studies",
    "finish_design_studies",
    "plan_design_studies",
    "start_design_studies",
    "headline",
    "nearest",
    "two_angle_name",
    "save_study_data",
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
RESOLUTIONS: dict[str, dict[str, Any]] = {
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

#: Gain pairs of the thesis's frequency-response surfaces (figures 3.13, 3.14).
SURFACE_GAINS = ((2e6, 1170.0), (3e5, 1170.0))
#: Walls of the thesis's forced-response view (figure 3.5) [m].
FORCED_WALLS = (0.001, 0.004)
#: Ply angles listed in the critical-stress table (Table 3.3) besides the optimum [deg].
TABLE_ANGLES = (15.0, 30.0, 45.0, 55.0, 60.0, 75.0)


@dataclass
class DesignStudies:
    """Results of :func:`design_studies` (SI units; datasets carry units in attributes).

    A study that does not apply to the design (no lamina shaft material, no active bearing)
    is None, with the reason in ``notes``.
    """

    design_name: str
    resolution: str
    operating_speed: float  # rad/s
    ply_angle: Any = None  # Dataset over alpha [deg]: safety factor and critical-ply stresses
    two_angle: Any = None  # Dataset over (alpha, beta) [deg]
    wall: Any = None  # Dataset over wall_thickness [m]
    forced_response: Any = None  # Dataset (wall_thickness, speed): max shaft orbit [m]
    gain: Any = None  # Dataset over kp [N/m]
    buckling: Any = None  # Dataset over wall_thickness [m]
    spinup_map: Any = None  # Dataset over (kp, kd)
    surfaces: Any = None  # Dataset (case, x, speed): shaft orbit [m]
    tuned: Any = None  # Dataset (case, speed): before/after spin-up curves
    stability_map: Any = None  # Dataset over (kp, kd): onset speed, damping ratio
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
    timings: dict = field(default_factory=dict)  # study -> seconds
    notes: list = field(default_factory=list)

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
    "two_angle": 1.5,
    "wall": 2.9,
    "forced_response": 0.45,
    "gain": 0.65,
    "buckling": 1.7,
    "spinup": 2.0,
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
        Grid sizes, see :data:`RESOLUTIONS`.
    progress : callable or bool, optional
        A callable is called with a short label before each study (like
        :func:`flexshaft.studies.run.run_analysis`); True shows the sweeps' progress bars.
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
    return finish_design_studies(res, run, progress)


def start_design_studies(
    design=None,
    resolution: str = "report",
    actuator_gap: float | None = None,
    executor=None,
    *,
    jobs: int = 1,
    progress_bars: bool = False,
):
    """Start the studies of :func:`design_studies` (on ``executor`` when given) and return
    ``(DesignStudies, TaskRun)`` for :func:`finish_design_studies`: the caller can compute
    something else while a pool works on them."""
    from flexshaft.parallel.tasks import start_tasks
    from flexshaft.sweep import SweepError

    res, tasks = plan_design_studies(design, resolution, actuator_gap, jobs=jobs, progress_bars=progress_bars)
    return res, start_tasks(tasks, executor, errors=(SweepError, ValueError))


def plan_design_studies(
    design=None,
    resolution: str = "report",
    actuator_gap: float | None = None,
    *,
    jobs: int = 1,
    progress_bars: bool = False,
):
    """``(DesignStudies, tasks)``: the empty results (with the notes of the studies that do
    not apply) and the :class:`~flexshaft.parallel.tasks.Task` of each study, to start
    together with other tasks (:func:`flexshaft.parallel.tasks.start_tasks`)."""
    from flexshaft.assembly import build_model
    from flexshaft.design import baseline_design
    from flexshaft.parallel.tasks import Task

    if resolution not in RESOLUTIONS:
        raise ValueError(f"resolution must be one of {sorted(RESOLUTIONS)}, got {resolution!r}")
    grid = RESOLUTIONS[resolution]
    design = design if design is not None else baseline_design()
    run = {"jobs": int(jobs), "progress": bool(progress_bars)}
    model = build_model(design)
    res = DesignStudies(
        design_name=str(design.name),
        resolution=resolution,
        operating_speed=float(model.speed),
        actuator_gap=actuator_gap,
    )
    laminated = model.shaft.laminate is not None
    active = bool(model.actuators) and model.all_pd
    tasks = []

    def task(key, label, function, *args):
        tasks.append(Task(key, label, function, args, cost=COSTS[key.partition(":")[0]]))

    if laminated:
        task("ply_angle", "study 1: ply angle", _ply_angle_task, design, grid["angles"], run)
        task("two_angle", "study 2: two-angle map", _two_angle_task, design, grid["two_angles"], run)
    else:
        res.notes.append("ply-angle studies skipped: the shaft material is not a lamina")
    task("wall", "study 3: wall thickness", _wall_task, design, grid["walls"], run, laminated)
    task(
        "forced_response",
        "study 3: forced response",
        _forced_response_task,
        design,
        FORCED_WALLS,
        grid["forced_speeds"],
    )
    if laminated and active and _both_actuators(design):
        task("gain", "study 4: proportional gain", _gain_task, design, grid["kp"], run)
    elif laminated:
        res.notes.append("the K_p study needs the baseline's two active bearings (design bearings 1 and 2)")
    if laminated:
        task("buckling", "study 5: torsional buckling", _buckling_task, design, grid["walls"], run)
    if active:
        task("spinup", "study 6: spin-up gain map", _spinup_task, design, grid, actuator_gap)
        for i, kp in enumerate(grid["stab_kp"]):  # one task per K_p row: the pool balances better
            task(f"stability:{i}", "stability margin map", _stability_row_task, design, grid, kp)
    else:
        res.notes.append("spin-up and stability maps need PD active bearings; skipped")
    return res, tasks


def finish_design_studies(res: DesignStudies, run, progress=None) -> DesignStudies:
    """Wait for the studies started by :func:`start_design_studies` and fill ``res``.

    A study that cannot run on the design (a :class:`~flexshaft.sweep.SweepError` or
    ``ValueError``) is left None with the reason in ``res.notes``.
    """
    outcomes = run.results(_reporter(progress))
    rows, failed = [], set()
    for task in run.tasks:
        outcome = outcomes[task.key]
        name = task.key.partition(":")[0]
        res.timings[name] = res.timings.get(name, 0.0) + outcome.seconds
        if outcome.error is not None:
            if task.label not in failed:
                res.notes.append(f"{task.label} skipped: {str(outcome.error).splitlines()[0]}")
            failed.add(task.label)
            continue
        fields = dict(outcome.value)
        res.notes.extend(fields.pop("notes", []))
        rows.extend(fields.pop("stability_rows", []))
        for field_name, value in fields.items():
            setattr(res, field_name, value)
    if rows and "stability margin map" not in failed:
        from flexshaft.studies.whirl import stack_maps

        res.stability_map = _stability_dataset(stack_maps(rows))
    return res


def _ply_angle_task(design, angles, run) -> dict:
    from flexshaft.studies.sweeps import ply_angle_study

    ds = ply_angle_study(angles, design=design, **run)
    i = int(np.nanargmax(ds["safety_factor"].values))
    return {
        "ply_angle": ds,
        "optimal_angle": float(ds.alpha.values[i]),
        "optimal_angle_safety_factor": float(ds["safety_factor"].values[i]),
    }


def _two_angle_task(design, angles, run) -> dict:
    from flexshaft.studies.sweeps import two_angle_study

    ds = two_angle_study(angles, angles, design=design, **run)
    i, j = np.unravel_index(int(np.nanargmax(ds["safety_factor"].values)), ds["safety_factor"].shape)
    return {
        "two_angle": ds,
        "best_two_angle": (float(ds.alpha.values[i]), float(ds.beta.values[j])),
        "best_two_angle_safety_factor": float(ds["safety_factor"].values[i, j]),
    }


def _wall_task(design, walls, run, laminated: bool) -> dict:
    from flexshaft.studies.sweeps import wall_thickness_study

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


def quietest_spinup_wall(wall) -> tuple[float, float] | None:
    """(wall [m], peak shaft orbit [m]) of the wall study's smallest spin-up peak under the
    design's gains; None without actuators (all NaN)."""
    peaks = np.asarray(wall["spinup_peak_deflection"].values, dtype=float)
    if not np.isfinite(peaks).any():
        return None
    i = int(np.nanargmin(peaks))
    return float(wall.wall_thickness.values[i]), float(peaks[i])


def _forced_response_task(design, walls, n_speeds) -> dict:
    return {"forced_response": _forced_response(design, walls, n_speeds)}


def _gain_task(design, kps, run) -> dict:
    from flexshaft.studies.sweeps import proportional_gain_study

    return {"gain": proportional_gain_study(kps, design=design, **run)}


def _buckling_task(design, walls, run) -> dict:
    from flexshaft.studies.sweeps import buckling_study

    return {"buckling": buckling_study(walls, design=design, **run)}


def _spinup_task(design, grid, actuator_gap) -> dict:
    from flexshaft.assembly import build_model

    return _spinup_studies(build_model(design), grid, actuator_gap)


def _stability_row_task(design, grid, kp: float) -> dict:
    from flexshaft.studies.whirl import gain_stability_map

    speeds = np.linspace(0.0, 1.5 * max(design.operating.speed_rad_s, 1.0), grid["stab_speeds"])
    return {"stability_rows": [gain_stability_map(design, [kp], grid["stab_kd"], speeds, n_modes=8)]}


def _both_actuators(design) -> bool:
    kinds = [b.kind for b in design.bearings]
    return len(kinds) > 2 and kinds[1] == "active" and kinds[2] == "active"


def _forced_response(design, walls, n_speeds: int):
    """Largest shaft orbit vs speed (2 %–130 % of the operating speed) for a few walls."""
    import xarray as xr

    from flexshaft.analyses import imbalance_response
    from flexshaft.analyses.response import orbit_amplitude
    from flexshaft.analyses.spinup import actuator_receptance, spinup_curves
    from flexshaft.assembly import build_model
    from flexshaft.assembly.loads import imbalance_loads
    from flexshaft.design import with_overrides

    peaks = []
    speeds = None
    for wall in walls:
        model = build_model(with_overrides(design, {"shaft.wall_thickness": float(wall)}))
        speeds = np.linspace(0.02, 1.3, n_speeds) * max(model.speed, 1.0)
        if model.actuators:
            rec = actuator_receptance(model, speeds)
            peaks.append(spinup_curves(rec, [a.controller for a in model.actuators]).shaft_peak)
        else:
            q = imbalance_response(model, speeds, imbalance_loads(model))
            dm = model.dofs
            n = np.arange(dm.n_shaft_nodes)
            peaks.append(orbit_amplitude(q[dm.shaft(n, "v")], q[dm.shaft(n, "w")]).max(axis=(0, 1)))
    return xr.Dataset(
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


def _refined_peak(
    receptance_at, controllers, speeds: np.ndarray, curve: np.ndarray, n: int = 81
) -> tuple[float, float]:
    """Peak of a spin-up curve refined on a fine grid between the neighbours of the coarse peak;
    ``receptance_at(fine_speeds)`` gives the actuator receptance there."""
    from flexshaft.analyses.spinup import spinup_curves

    i = int(np.argmax(curve))
    lo, hi = speeds[max(i - 1, 0)], speeds[min(i + 1, speeds.size - 1)]
    fine = np.linspace(lo, hi, n)
    peak = spinup_curves(receptance_at(fine), controllers).shaft_peak
    k = int(np.argmax(peak))
    if peak[k] >= curve[i]:
        return float(peak[k]), float(fine[k])
    return float(curve[i]), float(speeds[i])


def _receptance_cache(model):
    """``receptance_at(speeds)``: the actuator receptance of ``model``, each grid solved once
    (several gain pairs often refine the same resonance)."""
    from flexshaft.analyses.spinup import actuator_receptance

    cache = {}

    def receptance_at(speeds: np.ndarray):
        key = np.asarray(speeds, dtype=float).tobytes()
        if key not in cache:
            cache[key] = actuator_receptance(model, speeds)
        return cache[key]

    return receptance_at


def _spinup_studies(model, grid, actuator_gap: float | None) -> dict:
    """(K_p, K_d) map, response surfaces and the tuned-gain comparison on one receptance: the
    :class:`DesignStudies` fields they fill."""
    import xarray as xr

    from flexshaft.analyses.spinup import clustered_receptance, spinup_curves, spinup_map, spinup_speeds
    from flexshaft.assembly.model import Controller

    before = [a.controller for a in model.actuators]  # the design's own laws
    rec = clustered_receptance(model, before, spinup_speeds(model, grid["map_speeds"]))
    receptance_at = _receptance_cache(model)
    smap = spinup_map(model, grid["map_kp"], grid["map_kd"], receptance=rec)
    ds = smap.to_dataset()
    ds.attrs["title"] = "spin-up peaks over the actuator gains (thesis figures 3.12, 3.15, 3.16)"
    first = model.actuators[0].controller
    gains_before = (float(first.kp), float(first.kd))
    # The best pair on the sampled speeds may owe its rank to a resonance that falls between
    # samples: refine the peak of the few best candidates and keep the best refined one.
    ok = np.ones(smap.shaft_peak.shape, bool)
    if actuator_gap is not None:
        ok &= smap.actuator_displacement_peak.max(axis=-1) <= actuator_gap
    if not ok.any():
        raise ValueError(f"no gain pair keeps the actuator orbit within the gap {actuator_gap} m")
    order = np.argsort(np.where(ok, smap.shaft_peak, np.inf), axis=None)[: min(8, int(ok.sum()))]
    best = None
    for flat in order:
        i, j = np.unravel_index(int(flat), smap.shaft_peak.shape)
        law = [Controller.pd(float(smap.kp[i]), float(smap.kd[j]))] * rec.n_actuators
        peak, _ = _refined_peak(receptance_at, law, rec.speeds, spinup_curves(rec, law).shaft_peak)
        if best is None or peak < best[0]:
            best = (peak, float(smap.kp[i]), float(smap.kd[j]))
    _, kp_a, kd_a = best

    cases = [(f"K_p = {kp:.3g} N/m, K_d = {kd:.4g} N s/m", kp, kd) for kp, kd in SURFACE_GAINS]
    orbits = [spinup_curves(rec, (kp, kd)).shaft_orbit for _, kp, kd in cases]
    surfaces = xr.Dataset(
        {
            "shaft_orbit": (
                ("case", "x", "speed"),
                np.array(orbits),
                {"units": "m", "long_name": "shaft orbit major semi-axis"},
            )
        },
        coords={
            "case": [c[0] for c in cases],
            "kp": ("case", [c[1] for c in cases], {"units": "N/m"}),
            "kd": ("case", [c[2] for c in cases], {"units": "N s/m"}),
            "x": ("x", rec.shaft_x, {"units": "m", "long_name": "shaft station"}),
            "speed": ("speed", rec.speeds, {"units": "rad/s"}),
        },
        attrs={"title": "frequency-response surfaces (thesis figures 3.13, 3.14)"},
    )

    after = [Controller.pd(kp_a, kd_a)] * rec.n_actuators
    curves = [spinup_curves(rec, c) for c in (before, after)]
    refined = [_refined_peak(receptance_at, c, rec.speeds, cv.shaft_peak) for c, cv in zip((before, after), curves)]
    (peak_before, speed_before), (peak_after, speed_after) = refined
    tuned = xr.Dataset(
        {
            "shaft_peak": (
                ("case", "speed"),
                np.array([c.shaft_peak for c in curves]),
                {"units": "m", "long_name": "largest shaft orbit over the nodes"},
            ),
            "actuator_displacement": (
                ("case", "actuator", "speed"),
                np.array([c.actuator_displacement for c in curves]),
                {"units": "m"},
            ),
            "actuator_force": (
                ("case", "actuator", "speed"),
                np.array([c.actuator_force for c in curves]),
                {"units": "N"},
            ),
            "refined_peak": (
                "case",
                [r[0] for r in refined],
                {"units": "m", "long_name": "peak on a refined speed grid"},
            ),
        },
        coords={
            "case": ["design gains", "tuned gains"],
            "kp": ("case", [gains_before[0], kp_a], {"units": "N/m"}),
            "kd": ("case", [gains_before[1], kd_a], {"units": "N s/m"}),
            "actuator": list(rec.actuator_names),
            "speed": ("speed", rec.speeds, {"units": "rad/s"}),
        },
        attrs={"title": "tuned gains (thesis figure 3.17)"},
    )
    return {
        "spinup_map": ds,
        "gains_before": gains_before,
        "gains_after": (kp_a, kd_a),
        "surfaces": surfaces,
        "tuned": tuned,
        "peak_before": peak_before,
        "peak_speed_before": speed_before,
        "peak_after": peak_after,
        "peak_speed_after": speed_after,
    }


def _stability_dataset(smap) -> Any:
    """The stability margin map (a :class:`~flexshaft.studies.whirl.StabilityMap`) as a Dataset."""
    import xarray as xr

    return xr.Dataset(
        {
            "onset_speed": (
                ("kp", "kd"),
                smap.onset_speed,
                {"units": "rad/s", "long_name": "whirl onset speed (NaN: stable)"},
            ),
            "damping_ratio": (
                ("kp", "kd"),
                smap.margin_at_operating,
                {"units": "1", "long_name": "smallest damping ratio at the operating speed"},
            ),
        },
        coords={"kp": ("kp", smap.kp, {"units": "N/m"}), "kd": ("kd", smap.kd, {"units": "N s/m"})},
        attrs={"title": "whirl-stability margin over the actuator gains", "max_speed_rad_s": smap.max_speed},
    )


# ---------------------------------------------------------------------------------------------


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
    and the headline to ``folder/design_studies.json``; returns the paths by name."""
    from flexshaft.netcdf import write_netcdf

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    paths = {}
    for name in _DATASETS:
        ds = getattr(results, name)
        if ds is not None:
            paths[name] = folder / f"study_{name}.nc"
            write_netcdf(ds, paths[name])
    paths["headline"] = folder / "design_studies.json"
    paths["headline"].write_text(json.dumps(headline(results), indent=2))
    return paths


def nearest(ds, dim: str, value: float):
    return ds.sel({dim: value}, method="nearest")


def two_angle_name(pair) -> str:
    a, b = (f"{v:g}" for v in pair)
    return f"({a}/-{a}/{b}/-{b})s".replace("/-0/", "/0/").replace("/-0)", "/0)")
