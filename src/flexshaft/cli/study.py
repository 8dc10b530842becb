"""``flexshaft study ...``: the thesis design studies from the command line.

Mounted in :mod:`flexshaft.cli` with ``app.add_typer(study_app, name="study")``. Every command
writes ``OUT/results.nc`` (netCDF, units in attributes) and prints a one-line headline; the
sweeps resume when re-run on the same ``--out`` folder.
"""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import numpy as np
import typer

study_app = typer.Typer(no_args_is_help=True, help="Design studies of thesis chapter 3 (sweeps; resumable).")

_DESIGN = typer.Argument(None, help="Design file (TOML). Default: the embedded thesis baseline.", show_default=False)
_OUT = typer.Option(None, "--out", "-o", help="Run folder (chunks, manifest, results.nc); re-run to resume.")
_JOBS = typer.Option(1, "--jobs", "-j", min=1, help="Local worker processes (one BLAS thread each).")
_DASK = typer.Option(None, "--dask", help="Dask scheduler address, e.g. tcp://host:8786 (needs flexshaft[dask]).")


def _design(path: Optional[Path]):
    from flexshaft.design import DesignError, baseline_design, load_design

    try:
        return baseline_design() if path is None else load_design(path)
    except DesignError as exc:
        typer.echo(f"error: invalid design {path or '(embedded baseline)'}:\n{exc}", err=True)
        raise typer.Exit(code=2)


def _figure(fig, out: Optional[Path], stem: str) -> None:
    """Save a study figure (PNG and SVG) into ``out`` (default ``flexshaft-study-STEM``)."""
    from flexshaft.plot.driveline import save_figure

    folder = out if out is not None else Path(f"flexshaft-study-{stem}")
    paths = save_figure(fig, folder, stem)
    typer.echo(f"figure: {paths['png']}")


def _run(func, design, out, jobs, dask, **kw):
    from flexshaft.sweep import SweepError

    try:
        return func(design=_design(design), run_dir=out, jobs=jobs, client=dask, **kw)
    except SweepError as exc:
        typer.echo(f"error: {exc}", err=True)
        raise typer.Exit(code=2)


@study_app.command("ply-angle")
def ply_angle(design: Optional[Path] = _DESIGN, step: float = typer.Option(5.0, min=0.5, max=45.0, help="Angle step [deg]."),
              out: Optional[Path] = _OUT, jobs: int = _JOBS, dask: Optional[str] = _DASK) -> None:
    """Safety factor vs α of (α/−α/−α/α), no imbalance (thesis: optimum ±55°)."""
    from flexshaft.studies.sweeps import ply_angle_study

    ds = _run(ply_angle_study, design, out, jobs, dask, angles=np.arange(step, 90.0, step))
    best = ds["safety_factor"].idxmax("alpha").item()
    typer.echo(f"best α = ±{best:g}°: safety factor {ds['safety_factor'].max().item():.2f}")
    from flexshaft.plot.studies import ply_angle_figure
    from flexshaft.studies.sweeps import DOMINANT_STRESS_CODES

    dominant = [DOMINANT_STRESS_CODES.get(int(c), "?") if np.isfinite(c) else "?" for c in ds["dominant_stress"].values]
    _figure(ply_angle_figure(ds.alpha.values, ds["safety_factor"].values, dominant), out, "ply_angle")


@study_app.command("two-angle")
def two_angle(design: Optional[Path] = _DESIGN, step: float = typer.Option(15.0, min=1.0, max=45.0, help="Angle step [deg]."),
              out: Optional[Path] = _OUT, jobs: int = _JOBS, dask: Optional[str] = _DASK) -> None:
    """Safety factor map of (α/−α/β/−β)s laminates, no imbalance (thesis: best (55/−55/0/0)s)."""
    from flexshaft.plot.studies import two_angle_figure
    from flexshaft.studies.sweeps import two_angle_study

    angles = np.arange(0.0, 90.0 + 1e-9, step)
    ds = _run(two_angle_study, design, out, jobs, dask, alphas=angles, betas=angles)
    sf = ds["safety_factor"]
    i = np.unravel_index(int(np.nanargmax(sf.values)), sf.shape)
    typer.echo(f"best ({ds.alpha.values[i[0]]:g}/-{ds.alpha.values[i[0]]:g}/{ds.beta.values[i[1]]:g}/-{ds.beta.values[i[1]]:g})s: "
               f"safety factor {sf.values[i]:.2f}")
    _figure(two_angle_figure(ds.alpha.values, ds.beta.values, sf.values), out, "two_angle")


@study_app.command("wall")
def wall(design: Optional[Path] = _DESIGN, out: Optional[Path] = _OUT, jobs: int = _JOBS, dask: Optional[str] = _DASK) -> None:
    """Safety factor (with/without imbalance), first frequency, spin-up peak vs wall thickness."""
    from flexshaft.studies.sweeps import wall_thickness_study

    ds = _run(wall_thickness_study, design, out, jobs, dask)
    typer.echo(ds[["safety_factor", "safety_factor_no_imbalance", "spinup_peak_deflection"]].to_dataframe().to_string())
    from flexshaft.plot.studies import wall_thickness_figure

    _figure(wall_thickness_figure(ds.wall_thickness.values, ds["safety_factor"].values,
                                  ds["safety_factor_no_imbalance"].values, ds["natural_frequency_1"].values), out, "wall")


@study_app.command("gain")
def gain(design: Optional[Path] = _DESIGN, out: Optional[Path] = _OUT, jobs: int = _JOBS, dask: Optional[str] = _DASK) -> None:
    """Safety factor and actuator displacement vs the proportional gain K_p."""
    from flexshaft.studies.sweeps import proportional_gain_study

    ds = _run(proportional_gain_study, design, out, jobs, dask)
    typer.echo(ds[["safety_factor", "actuator_displacement"]].to_dataframe().to_string())
    from flexshaft.plot.studies import gain_figure

    _figure(gain_figure(ds.kp.values, ds["safety_factor"].values, ds["actuator_displacement"].values), out, "gain")


@study_app.command("buckling")
def buckling(design: Optional[Path] = _DESIGN, out: Optional[Path] = _OUT, jobs: int = _JOBS, dask: Optional[str] = _DASK) -> None:
    """Torsional buckling safety factor vs wall thickness."""
    from flexshaft.studies.sweeps import buckling_study

    ds = _run(buckling_study, design, out, jobs, dask)
    typer.echo(ds["buckling_safety_factor"].to_dataframe().to_string())
    from flexshaft.plot.studies import buckling_figure

    _figure(buckling_figure(ds.wall_thickness.values, ds["buckling_safety_factor"].values), out, "buckling")


@study_app.command("spinup-map")
def spinup_map_cmd(design: Optional[Path] = _DESIGN, n_gains: int = typer.Option(30, min=2, max=400),
                   n_speeds: int = typer.Option(400, min=10, max=20000), out: Optional[Path] = _OUT) -> None:
    """Peak shaft deflection, actuator displacement and force over a (K_p, K_d) grid."""
    from flexshaft.netcdf import write_netcdf
    from flexshaft.studies.sweeps import spinup_gain_map

    kd = np.concatenate([[0.0], np.logspace(1, 4.5, n_gains - 1)])
    ds = spinup_gain_map(np.logspace(5, 8, n_gains), kd, design=_design(design), n_speeds=n_speeds)
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        write_netcdf(ds, out / "results.nc")
    i = np.unravel_index(int(np.argmin(ds["shaft_peak"].values)), ds["shaft_peak"].shape)
    best = (float(ds.kp.values[i[0]]), float(ds.kd.values[i[1]]))
    typer.echo(f"best K_p = {best[0]:.3e} N/m, K_d = {best[1]:.3e} N s/m: "
               f"peak deflection {1e3 * ds['shaft_peak'].values[i]:.2f} mm")
    from flexshaft.plot.studies import gain_map_figure

    for var, scale, label in (("shaft_peak", 1e3, "max spin-up shaft orbit [mm]"),
                              ("actuator_displacement_peak", 1e3, "max actuator displacement [mm]"),
                              ("actuator_force_peak", 1.0, "max actuator force [N]")):
        values = ds[var].values if ds[var].ndim == 2 else ds[var].values.max(axis=-1)
        _figure(gain_map_figure(ds.kp.values, ds.kd.values, values, label, scale=scale, best=best), out, f"spinup_map_{var}")


@study_app.command("all")
def all_studies(design: Optional[Path] = _DESIGN,
                resolution: str = typer.Option("report", help="Grid resolution: report (~10 s) or full (~1 min)."),
                out: Path = typer.Option(Path("flexshaft-studies"), "--out", "-o", help="Folder for figures, netCDF and HTML."),
                jobs: int = _JOBS,
                gap: Optional[float] = typer.Option(None, help="Actuator gap [m] limiting the tuned gains.")) -> None:
    """Every chapter-3 study: figures, netCDF data, design_studies.json and a report.html."""
    import json

    from flexshaft.report.html import write_report
    from flexshaft.report.studies_section import design_studies_section
    from flexshaft.studies.chapter3 import design_studies, headline, save_study_data

    if resolution not in ("report", "full"):
        typer.echo(f"error: --resolution must be 'report' or 'full', got {resolution!r}", err=True)
        raise typer.Exit(code=2)
    d = _design(design)
    res = design_studies(d, resolution, progress=lambda label: typer.echo(label, err=True), jobs=jobs, actuator_gap=gap)
    save_study_data(res, out)
    write_report(out, f"Design studies: {d.name}", [design_studies_section(res, out)], design_name=d.name)
    typer.echo(json.dumps(headline(res), indent=2))
