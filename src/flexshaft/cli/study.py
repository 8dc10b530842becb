"""``flexshaft study ...``: the thesis design studies from the command line.

Mounted in :mod:`flexshaft.cli` as ``flexshaft study``. Every command writes its ``--out``
folder (default ``flexshaft-study-NAME``): ``results.nc`` (netCDF, units in attributes), the
sweep's chunks (re-run on the same folder to resume) and its figures; it prints a table in
engineering units (mm, MPa, rpm) or, with ``--json``, the data in SI with unit-suffixed keys.
The JSON's ``results_file`` is the path of the folder's ``results.nc`` when the sweep wrote it,
null otherwise.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Annotated

import typer

from flexshaft.cli.common import (
    LoadedDesign,
    actuator_gap,
    dask_client,
    guarded,
    load_design_argument,
    print_json,
    refuse_imbalance_cases,
)
from flexshaft.cli.options import DaskOption, DesignArgument, ForceOption, JobsOption, JsonOption, Resolution
from flexshaft.cli.output import default_output_folder, into_run_folder, marker_source, prepare_output_folder

__all__ = ["study_app"]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).

study_app = typer.Typer(
    no_args_is_help=True, rich_markup_mode=None, help="Design studies of thesis chapter 3 (sweeps; resumable)."
)

OutOption = Annotated[
    Path | None,
    typer.Option(
        "--out",
        "-o",
        help="Run folder: chunks, manifest, results.nc and figures; re-run to resume (a rerun of an edited "
        "design file starts afresh). Default: DESIGN-study-NAME (flexshaft-study-NAME for the embedded design).",
        show_default=False,
    ),
]


def _show_progress(as_json: bool) -> bool:
    """The sweep engine draws its bar on stdout: only on a terminal, never with --json."""
    return not as_json and sys.stdout.isatty() and sys.stderr.isatty()


def _prepare(
    design: Path | None,
    out: Path | None,
    name: str,
    force: bool,
    folder_suffix: str | None = None,
    *,
    points: int | None = None,
    jobs: int = 1,
    client=None,
    check=None,
) -> tuple[LoadedDesign, Path]:
    """The design (its ``source`` the file or ``embedded tuned design``, for the first line) and
    the output folder of a study; its work bounded first (a sweep of ``points`` designs, or
    ``check(design)``)."""
    import dataclasses

    from flexshaft.cli.tables import design_source as heading_source
    from flexshaft.design import DEFAULT_DESIGN

    loaded = load_design_argument(design)
    refuse_imbalance_cases(loaded.design, loaded.source)  # a "worst" placement beyond its bays, naming the file
    loaded = dataclasses.replace(loaded, source=heading_source(design))
    if points is not None:
        from flexshaft.cli.bounds import check_sweep, workers_of

        check_sweep(loaded.design, f"study {name}", points, workers_of(jobs, client))
    if check is not None:
        check(loaded.design)
    folder = default_output_folder(design, folder_suffix or f"study-{name}") if out is None else out
    return loaded, prepare_output_folder(
        folder, loaded.design, f"study {name}", force=force, source=marker_source(design, DEFAULT_DESIGN)
    )


def _sweep(func, loaded: LoadedDesign, folder: Path, jobs: int, client, as_json: bool, force: bool, **kw):
    """The study's sweep into its output folder (:func:`~flexshaft.cli.output.into_run_folder`)."""

    def compute():
        return func(
            design=loaded.design, run_dir=folder, jobs=jobs, client=client, progress=_show_progress(as_json), **kw
        )

    return into_run_folder(compute, folder, force)


def _save(fig, folder: Path, stem: str) -> dict:
    from flexshaft.plot.driveline import save_figure

    return {kind: str(path) for kind, path in save_figure(fig, folder, stem).items()}


def _report(
    loaded: LoadedDesign,
    name: str,
    folder: Path,
    ds,
    variables: list[str],
    figures: dict,
    headline: str,
    as_json: bool,
    table=None,
) -> None:
    """Print a study: its headline and the table of ``variables``, or the JSON of all its data."""
    from flexshaft.cli.tables import dataset_json, dataset_table, design_heading, print_line, stdout_console

    if as_json:
        results = folder / "results.nc"
        print_json(
            {
                "design": loaded.design.name,
                "study": name,
                "headline": headline,
                "results_file": str(results) if results.is_file() else None,
                "figures": figures,
                **dataset_json(ds),
            }
        )
        return
    console = stdout_console()
    print_line(console, design_heading(loaded.design.name, loaded.source), style="bold")
    console.print(table if table is not None else dataset_table(ds, variables, f"study {name}"))
    print_line(console, headline)
    for _stem, paths in figures.items():
        print_line(console, f"figure: {paths['png']}")


@study_app.command("ply-angle")
@guarded
def ply_angle(
    design: DesignArgument = None,
    step: Annotated[float, typer.Option("--step", min=0.5, max=45.0, help="Angle step [deg].")] = 5.0,
    out: OutOption = None,
    force: ForceOption = False,
    jobs: JobsOption = 1,
    dask: DaskOption = None,
    as_json: JsonOption = False,
) -> None:
    """Safety factor vs α of (α/−α/−α/α), no imbalance (thesis: optimum ±55°)."""
    import numpy as np

    from flexshaft.plot.studies import ply_angle_figure
    from flexshaft.thesis.ply_angle import DOMINANT_STRESS_CODES, ply_angle_study

    angles = np.arange(step, 90.0, step)
    client = dask_client(dask)  # checked and connected before anything is prepared
    loaded, folder = _prepare(
        design,
        out,
        "ply-angle",
        force,
        points=angles.size,
        jobs=jobs,
        client=client,
        check=_check_laminated("ply-angle", segments=False),
    )
    ds = _sweep(ply_angle_study, loaded, folder, jobs, client, as_json, force, angles=angles)
    best = float(ds["safety_factor"].idxmax("alpha").item())
    headline = f"best α = ±{best:g}°: safety factor {float(ds['safety_factor'].max().item()):.3g}"
    dominant = [DOMINANT_STRESS_CODES.get(int(c), "?") if np.isfinite(c) else "?" for c in ds["dominant_stress"].values]
    figures = {
        "ply_angle": _save(ply_angle_figure(ds.alpha.values, ds["safety_factor"].values, dominant), folder, "ply_angle")
    }
    _report(
        loaded,
        "ply-angle",
        folder,
        ds,
        ["safety_factor", "sigma1", "sigma2", "tau12", "critical_ply_angle"],
        figures,
        headline,
        as_json,
    )


@study_app.command("two-angle")
@guarded
def two_angle(
    design: DesignArgument = None,
    step: Annotated[float, typer.Option("--step", min=1.0, max=45.0, help="Angle step [deg].")] = 15.0,
    out: OutOption = None,
    force: ForceOption = False,
    jobs: JobsOption = 1,
    dask: DaskOption = None,
    as_json: JsonOption = False,
) -> None:
    """Safety factor map of (α/−α/β/−β)s laminates, no imbalance (thesis: best (55/−55/0/0)s)."""
    import numpy as np

    from flexshaft.cli.tables import matrix_table
    from flexshaft.plot.studies import two_angle_figure
    from flexshaft.thesis.two_angles import best_pair, two_angle_study

    angles = np.arange(0.0, 90.0 + 1e-9, step)
    client = dask_client(dask)  # checked and connected before anything is prepared
    loaded, folder = _prepare(
        design,
        out,
        "two-angle",
        force,
        points=angles.size**2,
        jobs=jobs,
        client=client,
        check=_check_laminated("two-angle", segments=False),
    )
    ds = _sweep(two_angle_study, loaded, folder, jobs, client, as_json, force, alphas=angles, betas=angles)
    sf = ds["safety_factor"]
    i = best_pair(sf.values, ds.alpha.values, ds.beta.values)
    a, b = ds.alpha.values[i[0]], ds.beta.values[i[1]]
    headline = f"best ({a:g}/-{a:g}/{b:g}/-{b:g})s: safety factor {float(sf.values[i]):.3g}"
    figure = two_angle_figure(ds.alpha.values, ds.beta.values, sf.values, best=(a, b))
    figures = {"two_angle": _save(figure, folder, "two_angle")}
    _report(
        loaded,
        "two-angle",
        folder,
        ds,
        ["safety_factor"],
        figures,
        headline,
        as_json,
        table=None if as_json else matrix_table(sf, "study two-angle"),
    )


def _largest_safety_factor(sf, where) -> str:
    """Headline of a study's safety factors ``sf``: the largest and ``where(i)`` it is, or why
    there is none (NaN everywhere: the shaft is not a lamina)."""
    import numpy as np

    if not np.isfinite(sf).any():
        return "safety factor not evaluated (the shaft is not a lamina)"
    i = int(np.nanargmax(sf))
    return f"largest safety factor {sf[i]:.3g} at {where(i)}"


@study_app.command("wall")
@guarded
def wall(
    design: DesignArgument = None,
    out: OutOption = None,
    force: ForceOption = False,
    jobs: JobsOption = 1,
    dask: DaskOption = None,
    as_json: JsonOption = False,
) -> None:
    """Safety factor (with/without imbalance), first frequency and spin-up peak vs wall thickness."""
    from flexshaft.plot.studies import wall_thickness_figure
    from flexshaft.thesis.wall import wall_thickness_study
    from flexshaft.units import m_to_mm

    client = dask_client(dask)  # checked and connected before anything is prepared
    loaded, folder = _prepare(design, out, "wall", force, points=10, jobs=jobs, client=client)
    ds = _sweep(wall_thickness_study, loaded, folder, jobs, client, as_json, force)
    sf = ds["safety_factor"].values
    headline = _largest_safety_factor(sf, lambda i: f"a {m_to_mm(float(ds.wall_thickness.values[i])):.3g} mm wall")
    figures = {
        "wall": _save(
            wall_thickness_figure(
                ds.wall_thickness.values,
                sf,
                ds["safety_factor_no_imbalance"].values,
                ds["natural_frequency_1"].values,
                ds["spinup_peak_deflection"].values,
            ),
            folder,
            "wall",
        )
    }
    _report(
        loaded,
        "wall",
        folder,
        ds,
        ["safety_factor", "safety_factor_no_imbalance", "natural_frequency_1", "spinup_peak_deflection"],
        figures,
        headline,
        as_json,
    )


@study_app.command("gain")
@guarded
def gain(
    design: DesignArgument = None,
    out: OutOption = None,
    force: ForceOption = False,
    jobs: JobsOption = 1,
    dask: DaskOption = None,
    as_json: JsonOption = False,
) -> None:
    """Safety factor and actuator displacement vs the proportional gain K_p [N/m] of both AMBs."""
    from flexshaft.cli.tables import sig
    from flexshaft.plot.studies import gain_figure
    from flexshaft.thesis.gain import proportional_gain_study

    client = dask_client(dask)  # checked and connected before anything is prepared
    loaded, folder = _prepare(design, out, "gain", force, points=13, jobs=jobs, client=client, check=_check_gain)
    ds = _sweep(proportional_gain_study, loaded, folder, jobs, client, as_json, force)
    sf = ds["safety_factor"].values
    headline = _largest_safety_factor(sf, lambda i: f"K_p = {sig(float(ds.kp.values[i]), 3)} N/m")
    figures = {"gain": _save(gain_figure(ds.kp.values, sf, ds["actuator_displacement"].values), folder, "gain")}
    _report(loaded, "gain", folder, ds, ["safety_factor", "actuator_displacement"], figures, headline, as_json)


@study_app.command("buckling")
@guarded
def buckling(
    design: DesignArgument = None,
    out: OutOption = None,
    force: ForceOption = False,
    jobs: JobsOption = 1,
    dask: DaskOption = None,
    as_json: JsonOption = False,
) -> None:
    """Torsional buckling safety factor vs wall thickness (about 5 s per wall)."""
    from flexshaft.plot.studies import buckling_figure
    from flexshaft.thesis.buckling_sweep import buckling_study
    from flexshaft.units import m_to_mm

    client = dask_client(dask)  # checked and connected before anything is prepared
    loaded, folder = _prepare(
        design, out, "buckling", force, points=10, jobs=jobs, client=client, check=_check_laminated("buckling")
    )
    ds = _sweep(buckling_study, loaded, folder, jobs, client, as_json, force)
    sf = ds["buckling_safety_factor"].values
    thin = [w for w, s in zip(ds.wall_thickness.values, sf) if s < 1.0]
    headline = (
        f"walls up to {m_to_mm(float(max(thin))):.3g} mm buckle (safety factor < 1)"
        if thin
        else "no wall studied buckles (safety factor ≥ 1 everywhere)"
    )
    figures = {"buckling": _save(buckling_figure(ds.wall_thickness.values, sf), folder, "buckling")}
    _report(loaded, "buckling", folder, ds, ["critical_torque", "buckling_safety_factor"], figures, headline, as_json)


@study_app.command("spinup-map")
@guarded
def spinup_map(
    design: DesignArgument = None,
    n_gains: Annotated[int, typer.Option("--n-gains", min=2, max=400, help="Gains per axis (K_p and K_d).")] = 30,
    n_speeds: Annotated[
        int,
        typer.Option(
            "--n-speeds",
            min=10,
            max=10000,
            help="Spin-up speeds (× --n-gains²: refused with the numbers when estimated above 10 min or 2 GiB).",
        ),
    ] = 400,
    out: OutOption = None,
    force: ForceOption = False,
    as_json: JsonOption = False,
) -> None:
    """Peak shaft orbit, actuator displacement and force over a (K_p [N/m], K_d [N s/m]) grid."""
    import numpy as np

    from flexshaft.cli.tables import sig
    from flexshaft.netcdf import write_netcdf
    from flexshaft.plot.studies import gain_map_figure
    from flexshaft.thesis.spinup_maps import spinup_gain_map
    from flexshaft.units import m_to_mm

    loaded, folder = _prepare(design, out, "spinup-map", force, check=lambda d: _check_spinup_map(d, n_gains, n_speeds))
    kd = np.concatenate([[0.0], np.logspace(1, 4.5, n_gains - 1)])
    ds = spinup_gain_map(np.logspace(5, 8, n_gains), kd, design=loaded.design, n_speeds=n_speeds)
    write_netcdf(ds, folder / "results.nc")
    i = np.unravel_index(int(np.argmin(ds["shaft_peak"].values)), ds["shaft_peak"].shape)
    best = (float(ds.kp.values[i[0]]), float(ds.kd.values[i[1]]))
    headline = (
        f"best K_p = {sig(best[0], 3)} N/m, K_d = {sig(best[1], 3)} N s/m: peak shaft orbit "
        f"{sig(m_to_mm(float(ds['shaft_peak'].values[i])), 3)} mm"
    )
    figures = {}
    for var, label in (
        ("shaft_peak", "max spin-up shaft orbit [mm]"),
        ("actuator_displacement_peak", "max actuator displacement [mm]"),
        ("actuator_force_peak", "max actuator force [N]"),
    ):
        values = ds[var].values if ds[var].ndim == 2 else ds[var].values.max(axis=-1)
        scale = m_to_mm(1.0) if ds[var].attrs.get("units") == "m" else 1.0
        stem = f"spinup_map_{var}"
        figures[stem] = _save(
            gain_map_figure(ds.kp.values, ds.kd.values, values, label, scale=scale, best=best), folder, stem
        )
    if as_json:
        _report(loaded, "spinup-map", folder, ds, [], figures, headline, as_json)
        return
    from flexshaft.cli.tables import design_heading, print_line, stdout_console

    console = stdout_console()
    print_line(console, design_heading(loaded.design.name, loaded.source), style="bold")
    print_line(console, headline)
    print_line(console, f"data: {folder / 'results.nc'}")
    for paths in figures.values():
        print_line(console, f"figure: {paths['png']}")


def _check_laminated(name: str, *, segments: bool = True):
    """The ply-angle studies vary the layup of a laminated shaft, the buckling study its wall in
    the laminated-shell model (one laminated tube): refused before the output folder is made
    (they used to fail after it, leaving an empty folder marked incomplete)."""

    def check(design) -> None:
        from flexshaft.cli.common import fail, plain

        kind = design.materials[design.shaft.material].kind
        if kind != "lamina" or (segments and design.segmented):
            reason = (
                f"its material {plain(design.shaft.material)!r} is {kind}" if kind != "lamina" else "it is segmented"
            )
            varied = "the wall of the laminated-shell buckling model" if name == "buckling" else "its ply angles"
            fail(
                f"study {name}: the shaft of {plain(design.name)!r} is not one laminated tube ({reason}); "
                f"the study varies {varied}"
            )

    return check


def _check_gain(design) -> None:
    """The K_p study varies the proportional gain of the active bearings with PD laws."""
    from flexshaft.cli.common import fail
    from flexshaft.thesis.gain import gain_paths

    if not gain_paths(design):
        fail(
            'study gain: the design has no active bearing (kind = "active") with a proportional gain kp: '
            "the study varies K_p of the active bearings (a bearing given by a controller transfer function has none)"
        )


def _check_spinup_map(design, n_gains: int, n_speeds: int) -> None:
    """A spin-up map needs active bearings (their gains are its axes) and an operating speed
    (its spin-up ends there); its work is bounded (:func:`flexshaft.cli.bounds.check_spinup_map`)."""
    from flexshaft.cli.bounds import check_spinup_map
    from flexshaft.cli.common import fail

    if not any(b.kind == "active" for b in design.bearings):
        fail(
            'study spinup-map: the design has no active bearing (kind = "active"): the map varies the '
            "proportional and derivative gains of the active bearings"
        )
    if not design.operating.speed_rad_s > 0:
        fail(
            "study spinup-map: the design's operating speed is 0 (operating.speed_rpm or speed): the spin-up ends there"
        )
    check_spinup_map(design, n_gains, n_speeds)


@study_app.command("all")
@guarded
def all_studies(
    design: DesignArgument = None,
    resolution: Annotated[
        Resolution,
        typer.Option(
            "--resolution",
            case_sensitive=False,
            help="Grid resolution: report (about 10 s of computation) or full (about 25 s); --jobs divides it.",
        ),
    ] = Resolution.report,
    out: Annotated[
        Path | None,
        typer.Option(
            "--out",
            "-o",
            help="Folder for figures, netCDF, design_studies.json and report.html. Default: DESIGN-studies "
            "(flexshaft-studies for the embedded design).",
            show_default=False,
        ),
    ] = None,
    force: ForceOption = False,
    jobs: JobsOption = 1,
    gap: Annotated[
        float | None, typer.Option("--gap", help="Actuator gap limiting the tuned gains [m].", show_default=False)
    ] = None,
    gap_mm: Annotated[
        float | None,
        typer.Option("--gap-mm", help="The same gap in millimetres (as montecarlo's --gap-mm).", show_default=False),
    ] = None,
    as_json: JsonOption = False,
) -> None:
    """Every chapter-3 study: figures, netCDF data, design_studies.json and a report.html."""
    gap = actuator_gap(gap, gap_mm)
    from flexshaft.cli.tables import design_source

    loaded, folder = _prepare(
        design, out, "all", force, "studies", check=lambda d: _check_studies(d, design_source(design))
    )
    from flexshaft.cli.progress import StageProgress
    from flexshaft.parallel.pool import worker_pool
    from flexshaft.report.html import write_report
    from flexshaft.report.studies_section import design_studies_section
    from flexshaft.thesis.design_studies import design_studies, headline, save_study_data

    d = loaded.design
    # the studies as independent tasks on one pool of `jobs` workers (each sweep in its worker)
    with worker_pool(jobs, ("xarray",)) as pool, StageProgress(transient=as_json) as progress:
        res = design_studies(d, resolution.value, progress=progress.step, actuator_gap=gap, executor=pool)
        progress.step("writing the report")
        save_study_data(res, folder)
        page = write_report(
            folder, f"Design studies: {d.name}", [design_studies_section(res, folder)], design_name=d.name
        )
    data = headline(res)
    if as_json:
        print_json(data)
        return
    _print_headline(data, page, loaded.source)


def _check_studies(design, source: str) -> None:
    """``study all`` runs the thesis studies of ``flexshaft run`` (and its assessment's grids);
    a refusal names ``source``, the design file."""
    from flexshaft.assembly.size import check_problem_size
    from flexshaft.cli.common import fail

    if not design.operating.speed_rad_s > 0:
        fail("study all: the thesis studies need an operating speed > 0 (operating.speed_rpm or speed is 0)")
    check_problem_size(design, "run", source=source)


def _print_headline(data: dict, page: Path, source: str) -> None:
    from flexshaft.cli.tables import design_heading, print_line, stdout_console, table
    from flexshaft.units import m_to_mm

    def mm(value):
        return None if value is None else m_to_mm(value)

    thesis = data["thesis"]
    before, after = data["gains_before"] or {}, data["gains_after"] or {}
    rows = [
        ["optimal ply angle α of (α/−α/−α/α) [deg]", data["optimal_angle_deg"], thesis["optimal_angle_deg"]],
        ["  its safety factor", data["optimal_angle_safety_factor"], None],
        ["best (α/−α/β/−β)s", data["best_two_angle_layup"] or "—", "(55/-55/0/0)s"],
        ["  its safety factor", data["best_two_angle_safety_factor"], None],
        ["best wall [mm]", mm(data["best_wall_m"]), mm(thesis["best_wall_m"])],
        ["K_p before → tuned [N/m]", _pair(before.get("kp_N_per_m"), after.get("kp_N_per_m")), None],
        ["K_d before → tuned [N s/m]", _pair(before.get("kd_N_s_per_m"), after.get("kd_N_s_per_m")), None],
        [
            "spin-up peak orbit before tuning [mm]",
            mm(data["peak_deflection_before_m"]),
            mm(thesis["tuned_peak_before_m"]),
        ],
        ["spin-up peak orbit after tuning [mm]", mm(data["peak_deflection_after_m"]), mm(thesis["tuned_peak_after_m"])],
    ]
    console = stdout_console()
    print_line(console, design_heading(data["design"], source), style="bold")
    console.print(
        table(
            f"design studies ({data['resolution']} resolution)",
            ["quantity", "this design", "thesis"],
            rows,
            numeric={1, 2},
            digits=3,
        )
    )
    for note in data["notes"]:
        print_line(console, f"note: {note}")
    print_line(console, f"report written to {page}")


def _pair(first, second) -> str:
    """Two gains with three significant figures, written as every other gain the commands print
    (:func:`~flexshaft.cli.tables.sig`: 200000, not 2e+05)."""
    from flexshaft.cli.tables import sig

    return " → ".join(sig(v, 3) for v in (first, second))
