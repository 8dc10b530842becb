"""``flexshaft runup`` and ``flexshaft montecarlo``: the transient run-up through the criticals
and the Monte-Carlo imbalance study (:mod:`flexshaft.analyses.transient`,
:mod:`flexshaft.montecarlo`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from flexshaft.cli.common import (
    actuator_gap,
    check_finite,
    dask_client,
    fail,
    guarded,
    load_design_argument,
    print_json,
    refuse_imbalance_cases,
)
from flexshaft.cli.options import DaskOption, DesignArgument, ForceOption, JobsOption, JsonOption
from flexshaft.cli.output import default_output_folder, into_run_folder, marker_source, prepare_output_folder

__all__ = ["montecarlo", "runup"]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).


@guarded
def runup(
    design: DesignArgument = None,
    duration: Annotated[
        float,
        typer.Option(
            "--duration",
            help="Run-up time from --start-rpm to --stop-rpm [s], at most 3600; with --dwell at most 200,000 "
            "output samples (8 per revolution at the top speed: 312 s at 4800 rpm).",
        ),
    ] = 10.0,
    start_rpm: Annotated[float, typer.Option("--start-rpm", help="Start speed [rpm].")] = 0.0,
    stop_rpm: Annotated[
        float | None,
        typer.Option(
            "--stop-rpm", help="End speed [rpm]; default the operating speed (below --start-rpm: a run-down)."
        ),
    ] = None,
    dwell: Annotated[float, typer.Option("--dwell", help="Time held at the end speed [s], at most 3600.")] = 0.0,
    out: Annotated[
        Path | None,
        typer.Option(
            "--out",
            "-o",
            help="Folder for runup.nc and runup.png. Default: DESIGN-runup (flexshaft-runup for the embedded design).",
            show_default=False,
        ),
    ] = None,
    force: ForceOption = False,
    as_json: JsonOption = False,
) -> None:
    """Run-up (or run-down) transient at constant acceleration: shaft and actuator envelopes
    against the steady-state spin-up curve."""
    from flexshaft.design.schema import MAX_SPEED_RPM
    from flexshaft.units import rad_s_to_rpm, rpm_to_rad_s

    check_finite("--duration", duration, 1e-3, 3600.0, unit="s")
    check_finite("--start-rpm", start_rpm, 0.0, MAX_SPEED_RPM, unit="rpm")
    check_finite("--stop-rpm", stop_rpm, 0.0, MAX_SPEED_RPM, unit="rpm")
    check_finite("--dwell", dwell, 0.0, 3600.0, unit="s")
    loaded = load_design_argument(design)
    refuse_imbalance_cases(loaded.design, loaded.source)  # before the model is built
    from flexshaft.analyses.transient import run_up, steady_state_envelope
    from flexshaft.assembly import build_model
    from flexshaft.cli.bounds import check_runup
    from flexshaft.plot.driveline import save_figure
    from flexshaft.plot.transient import runup_envelope_figure

    model = build_model(loaded.design)
    stop = model.speed if stop_rpm is None else rpm_to_rad_s(stop_rpm)
    if stop_rpm is None and stop == 0.0:
        fail("--stop-rpm: the design's operating speed is 0 (operating.speed_rpm = 0); give the end speed")
    if rpm_to_rad_s(start_rpm) == stop:
        fail(
            f"--start-rpm, --stop-rpm: both {start_rpm:g} rpm; a run-up (or run-down) needs two different "
            "speeds (--stop-rpm defaults to the operating speed)"
        )
    check_runup(model, duration, dwell, max(rpm_to_rad_s(start_rpm), stop))
    folder = prepare_output_folder(
        default_output_folder(design, "runup") if out is None else out,
        loaded.design,
        "runup",
        force=force,
        source=marker_source(design, _default_design()),
    )
    result = run_up(model, duration, start=rpm_to_rad_s(start_rpm), stop=stop, dwell=dwell)
    lo, hi = sorted((rpm_to_rad_s(start_rpm), stop))
    import numpy as np

    steady = steady_state_envelope(model, np.linspace(max(lo, 1e-3 * max(hi, 1.0)), hi, 400))
    from flexshaft.netcdf import write_netcdf

    write_netcdf(result.to_dataset(), folder / "runup.nc")
    figure = runup_envelope_figure({f"{duration:g} s": result}, steady, operating_rpm=rad_s_to_rpm(model.speed))
    save_figure(figure, folder, "runup", svg=False)
    peak, _, at_speed = result.peak()
    at_station = float(result.shaft_x[int(np.argmax(result.shaft_orbit.max(axis=1)))])
    data = {
        "design": loaded.design.name,
        "duration_s": duration,
        "start_rpm": start_rpm,
        "stop_rpm": rad_s_to_rpm(stop),
        "peak_shaft_orbit_m": peak,
        "peak_speed_rpm": rad_s_to_rpm(at_speed),
        "peak_station_m": at_station,
        "steady_peak_shaft_orbit_m": float(np.max(steady.shaft_orbit)),
        "actuator_orbit_max_m": {
            n: float(np.max(result.actuator_displacement[k])) for k, n in enumerate(result.actuator_names)
        },
        "actuator_force_max_N": {
            n: float(np.max(result.actuator_force[k])) for k, n in enumerate(result.actuator_names)
        },
        "max_growth_rate_per_s": result.max_growth_rate,
        "unstable": result.unstable,
        "basis_size": result.basis_size,
        "internal_damping": result.internal_damping,
    }
    if as_json:
        print_json(data)
        return
    from flexshaft.cli.tables import design_heading, design_source, print_line, sig, stdout_console, table
    from flexshaft.units import m_to_mm

    console = stdout_console()
    print_line(console, design_heading(loaded.design.name, design_source(design)), style="bold")
    print_line(
        console,
        f"run-up {sig(start_rpm)} → {sig(rad_s_to_rpm(stop))} rpm in {sig(duration)} s "
        f"({result.basis_size} modes, {result.internal_damping} internal damping)",
    )
    print_line(
        console,
        f"peak shaft orbit {sig(m_to_mm(peak))} mm at {sig(rad_s_to_rpm(at_speed))} rpm, "
        f"x = {sig(at_station)} m (steady-state spin-up peak {sig(m_to_mm(data['steady_peak_shaft_orbit_m']))} mm)",
    )
    rows = [
        [n, m_to_mm(data["actuator_orbit_max_m"][n]), data["actuator_force_max_N"][n]] for n in result.actuator_names
    ]
    if rows:
        # the imbalance response's envelope: the static offset and force are not in it (the verdict's
        # actuator checks and `montecarlo` add them)
        console.print(
            table(
                "actuators during the run-up (imbalance response, the static load not included)",
                ["actuator", "imbalance orbit [mm]", "imbalance force [N]"],
                rows,
            )
        )
    if result.unstable:
        print_line(
            console,
            f"free whirl grows at up to {sig(result.max_growth_rate)} 1/s inside the run's speed range: unstable there",
            style="bold red",
        )
    print_line(console, f"written to {folder}")


@guarded
def montecarlo(
    design: DesignArgument = None,
    samples: Annotated[
        int, typer.Option("--samples", min=10, max=1_000_000, help="Number of imbalance samples.")
    ] = 500,
    seed: Annotated[
        int,
        typer.Option(
            "--seed", min=0, max=2**63 - 1, help="Random seed (the same seed gives the same samples), 0 to 2^63 - 1."
        ),
    ] = 0,
    grade: Annotated[
        float, typer.Option("--grade", help="Balance quality grade G [mm/s] (ISO 21940-11), e.g. 6.3 or 16.")
    ] = 6.3,
    gap_mm: Annotated[
        float | None,
        typer.Option(
            "--gap-mm", help="Actuator gap [mm] of every active bearing; default each one's own gap (as the verdict)."
        ),
    ] = None,
    force_limit: Annotated[
        float | None,
        typer.Option(
            "--force-limit",
            help="Actuator force limit [N] of every active bearing; default each one's own force capacity "
            "(as the verdict: its magnet's saturation force when no capacity is given).",
        ),
    ] = None,
    out: Annotated[
        Path | None,
        typer.Option(
            "--out",
            "-o",
            help="Folder for samples.nc and montecarlo.png (resumable). Default: DESIGN-montecarlo "
            "(flexshaft-montecarlo for the embedded design).",
            show_default=False,
        ),
    ] = None,
    force: ForceOption = False,
    jobs: JobsOption = 1,
    dask: DaskOption = None,
    as_json: JsonOption = False,
) -> None:
    """Monte-Carlo imbalance: random eccentricity (balance grade), phase and place per bay;
    distributions of the spin-up peak, actuator orbit and force and the Tsai-Wu safety factor,
    and the probability of exceeding the gap and the force limit (with its exact 95 % upper
    confidence bound)."""
    import sys

    import numpy as np

    check_finite("--grade", grade, 1e-3, 4000.0, unit="mm/s")
    gap = actuator_gap(None, gap_mm)
    check_finite("--force-limit", force_limit, 1e-6, 1e9, unit="N")
    loaded = load_design_argument(design)
    client = dask_client(dask)  # checked and connected before anything is prepared
    from flexshaft.cli.bounds import check_montecarlo, workers_of

    if not loaded.design.operating.speed_rad_s > 0:
        fail("--grade: a balance grade G = e Ω needs an operating speed (the design's operating speed is 0)")
    check_montecarlo(loaded.design, samples, workers_of(jobs, client))
    folder = prepare_output_folder(
        default_output_folder(design, "montecarlo") if out is None else out,
        loaded.design,
        "montecarlo",
        force=force,
        source=marker_source(design, _default_design()),
    )
    from flexshaft.montecarlo.steady import run_montecarlo
    from flexshaft.plot.driveline import save_figure
    from flexshaft.units import m_to_mm

    result = into_run_folder(
        lambda: run_montecarlo(
            loaded.design,
            samples,
            seed=seed,
            grade_mm_s=grade,
            gap=gap,  # default (None): each active bearing's own, as the verdict
            force_limit=force_limit,
            jobs=jobs,
            client=client,
            run_dir=folder / "sweep",
            progress=not as_json and sys.stderr.isatty(),  # the bar is drawn on stderr, only on a terminal
        ),
        folder / "sweep",
        force,
    )
    gap, capacity = result.gap, result.force_limit
    from flexshaft.netcdf import write_netcdf

    write_netcdf(result.dataset, folder / "samples.nc")
    save_figure(result.plot(), folder, "montecarlo", svg=False)
    ds = result.dataset
    summary = {
        name: {"mean": float(np.nanmean(ds[name].values)), "p99": float(np.nanpercentile(ds[name].values, 99))}
        for name in (
            "shaft_peak",
            "actuator_orbit_max",
            "actuator_excursion_max",
            "actuator_force_max",
            "actuator_load_max",
        )
        if name in ds and np.isfinite(ds[name].values).any()  # a driveline without actuators has none
    }
    data = {
        "design": loaded.design.name,
        "samples": samples,
        "seed": seed,
        "grade_mm_s": grade,
        "gap_m": gap,
        "force_limit_N": capacity,
        "summary": summary,
        "p_gap_exceeded": None if result.gap_exceedance is None else result.gap_exceedance[0],
        "p_force_exceeded": None if result.force_exceedance is None else result.force_exceedance[0],
        # the counts and the exact (Clopper-Pearson) 95 % upper bounds: with no exceedance the
        # estimate above is 0, and the bound is the number to read
        "gap_exceedance": None if result.gap_events is None else result.gap_events.to_dict(),
        "force_exceedance": None if result.force_events is None else result.force_events.to_dict(),
    }
    if as_json:
        print_json(data)
        return
    from flexshaft.cli.tables import design_heading, design_source, print_line, sig, stdout_console

    console = stdout_console()
    print_line(console, design_heading(loaded.design.name, design_source(design)), style="bold")
    print_line(console, f"{samples} samples, balance grade G {sig(grade)} mm/s, seed {seed}")
    for key, label, scale, unit in (
        ("shaft_peak", "spin-up peak shaft orbit", m_to_mm, "mm"),
        ("actuator_orbit_max", "largest actuator orbit", m_to_mm, "mm"),
        ("actuator_excursion_max", "largest actuator excursion (static + orbit)", m_to_mm, "mm"),
        ("actuator_force_max", "largest actuator dynamic force", float, "N"),
        ("actuator_load_max", "largest actuator force (static + dynamic)", float, "N"),
    ):
        if key in summary:
            print_line(
                console,
                f"{label}: mean {sig(scale(summary[key]['mean']))} {unit}, "
                f"99th percentile {sig(scale(summary[key]['p99']))} {unit}",
            )
    for name, events, own, scale, unit in (
        ("gap", result.gap_events, {n: lim.gap for n, lim in result.limits.items()}, m_to_mm, "mm"),
        ("force limit", result.force_events, {n: lim.force_capacity for n, lim in result.limits.items()}, float, "N"),
    ):
        if events is None:
            continue
        given = {n: v for n, v in own.items() if v is not None}
        # each actuator is counted against its own limit: one number when they agree, else each
        if len(set(given.values())) == 1:
            limit = f"{name} {sig(scale(next(iter(given.values()))))} {unit}"
        else:
            limit = f"{name} ({', '.join(f'{n} {sig(scale(v))} {unit}' for n, v in given.items())})"
        print_line(console, f"{limit} exceeded (static + dynamic) in {events.describe()}")
    print_line(console, f"written to {folder}")


def _default_design() -> str:
    """The embedded design a command analyses without a file (imported here: the schema is
    measurably heavy for ``--help``)."""
    from flexshaft.design import DEFAULT_DESIGN

    return DEFAULT_DESIGN
