"""Command-line interface: ``flexshaft run | baseline | check | modes | stability | thermal | study``.

User errors (bad design file, bad argument) end with a one-paragraph message naming the field,
the value and what is allowed, and exit code 2; never a traceback. ``flexshaft run --strict``
exits with code 3 when the design fails a requirement of its ``[requirements]`` table.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path
from typing import Optional

import typer

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    help="Design and analysis of high-flexibility rotorcraft tail-rotor drivelines.",
)

DesignArg = typer.Argument(None, help="Design file (TOML). Default: the embedded thesis baseline.", show_default=False)


#: Exit code of ``flexshaft run --strict`` when a requirement fails (2 is a user error).
REQUIREMENT_FAILED = 3


def _fail(message: str) -> None:
    typer.echo(f"error: {message}", err=True)
    raise typer.Exit(code=2)


def _finite(
    name: str, value: float | None, minimum: float | None = None, maximum: float | None = None
) -> float | None:
    if value is None:
        return None
    if not math.isfinite(value):
        _fail(f"{name}: must be a finite number (got {value})")
    if minimum is not None and value < minimum:
        _fail(f"{name}: must be >= {minimum:g} (got {value:g})")
    if maximum is not None and value > maximum:
        _fail(f"{name}: must be <= {maximum:g} (got {value:g})")
    return value


def _load(path: Optional[Path], embedded: str = "baseline"):
    from flexshaft.design import DesignError, embedded_design, load_design

    try:
        return embedded_design(embedded) if path is None else load_design(path)
    except DesignError as exc:
        _fail(f"invalid design {f'(embedded {embedded})' if path is None else str(path)}:\n{exc}")


def _design_text(path: Optional[Path], embedded: str = "baseline") -> tuple[str | None, str]:
    """The design file as read (for the report) and where it came from."""
    from flexshaft.design import EMBEDDED_DESIGNS, embedded_text

    if path is None:
        return embedded_text(embedded), f"embedded {embedded} design ({EMBEDDED_DESIGNS[embedded][1]})"
    try:
        return path.read_text(encoding="utf-8"), str(path)
    except (OSError, UnicodeDecodeError):  # it validated a moment ago; report without the text
        return None, str(path)


def _print_verdict(console, verdict) -> None:
    from rich.markup import escape
    from rich.table import Table

    from flexshaft.report.verdict import VERDICT_COLUMNS, verdict_rows

    colour = {"PASS": "green", "FAIL": "bold red", "not evaluated": "yellow"}
    table = Table(title="requirements verdict (worst case of each)")
    for col in VERDICT_COLUMNS[:-1]:
        table.add_column(col, justify="right" if col in ("value", "limit", "margin") else "left")
    for check, row in zip(verdict.checks, verdict_rows(verdict, compact=True)):
        status = row[4]
        where = row[5] if status != "not evaluated" else row[6]
        count = f" {check.n_failed}/{len(check.findings)}" if check.n_failed and len(check.findings) > 1 else ""
        table.add_row(*map(escape, row[:4]), f"[{colour[status]}]{status}{count}[/]", escape(where))
    console.print(table)
    head = "[bold green]PASS[/]" if verdict.passed else "[bold red]FAIL[/]"
    console.print(f"verdict: {head}: {escape(verdict.summary.split(': ', 1)[1])}", highlight=False)


def _print_modes(console, title: str, rows: list[dict]) -> None:
    from rich.table import Table

    table = Table(title=title)
    for col in ("mode", "Hz", "rpm", "ζ", "log dec", "kind", "whirl", "component"):
        table.add_column(col, justify="right" if col in ("mode", "Hz", "rpm", "ζ", "log dec") else "left")
    for r in rows:
        table.add_row(str(r["mode"]), f"{r['frequency_Hz']:.3f}", f"{r['frequency_rpm']:.0f}",
                      f"{r['damping_ratio']:.3g}", f"{r['log_decrement']:.3g}", r["kind"],
                      "—" if r["whirl"] == "none" else r["whirl"], r["component"])
    console.print(table)


@app.command()
def baseline(
    name: str = typer.Option("baseline", "--name", help="Embedded design: baseline (thesis Table 3.1, K_p 1e7, "
                             "K_d 0) or tuned (the tuned final design, default of `flexshaft run`)."),
) -> None:
    """Print an embedded design file (start your own from a copy)."""
    from flexshaft.design import EMBEDDED_DESIGNS, embedded_text

    if name not in EMBEDDED_DESIGNS:
        _fail(f"--name: no such embedded design (got {name!r}; allowed: {', '.join(EMBEDDED_DESIGNS)})")
    sys.stdout.write(embedded_text(name))


@app.command()
def check(design: Optional[Path] = DesignArg) -> None:
    """Validate a design file and print a one-line summary."""
    d = _load(design)
    typer.echo(f"ok: {d.name}")


@app.command("modes")
def modes_cmd(
    design: Optional[Path] = DesignArg,
    speed_rpm: Optional[float] = typer.Option(None, "--speed-rpm", help="Spin speed [rpm]; default: the operating speed."),
    n_modes: int = typer.Option(10, "--n", min=1, max=500, help="Number of modes."),
    as_json: bool = typer.Option(False, "--json", help="Print the results as JSON."),
) -> None:
    """Damped natural frequencies, whirl direction and component of the lowest modes."""
    import numpy as np

    from flexshaft.assembly import build_model
    from flexshaft.design.schema import MAX_SPEED_RPM
    from flexshaft.analyses.summary import modes_at

    _finite("--speed-rpm", speed_rpm, 0.0, MAX_SPEED_RPM)
    d = _load(design)
    model = build_model(d)
    speed = model.speed if speed_rpm is None else speed_rpm * 2 * np.pi / 60
    rows = modes_at(model, speed, n_modes)
    if as_json:
        typer.echo(json.dumps({"speed_rpm": speed * 60 / (2 * np.pi), "modes": rows}, indent=2))
        return
    from rich.console import Console

    _print_modes(Console(), f"{d.name}\nmodes at {speed * 60 / (2 * np.pi):.0f} rpm", rows)


@app.command("stability")
def stability_cmd(
    design: Optional[Path] = DesignArg,
    max_rpm: Optional[float] = typer.Option(None, "--max-rpm", help="Highest speed [rpm]; default 1.5 × operating."),
    n_speeds: int = typer.Option(61, "--n-speeds", min=2, max=2000, help="Number of speeds."),
    damping_model: str = typer.Option("hysteretic", "--model", help="hysteretic (the design's internal-damping model, each mode at its own frequency) | viscous (thesis ch. 4: one reference frequency)"),
    reference_hz: Optional[float] = typer.Option(None, "--reference-hz", help="ω_ref of the viscous model [Hz]; default: first shaft mode."),
    compare_thesis: bool = typer.Option(False, "--compare-thesis", help="Also the thesis's aluminium, (45/-45)s and (45/-45/0/0)s shafts."),
    as_json: bool = typer.Option(False, "--json", help="Print the results as JSON."),
) -> None:
    """Whirl stability with internal damping: onset speed of instability and the unstable mode."""
    import numpy as np

    from flexshaft.analyses.stability import stability
    from flexshaft.assembly import build_model
    from flexshaft.design import DesignError

    from flexshaft.design.schema import MAX_SPEED_RPM

    _finite("--max-rpm", max_rpm, 1e-9, MAX_SPEED_RPM)
    _finite("--reference-hz", reference_hz, 1e-9)
    if damping_model not in ("viscous", "hysteretic"):
        _fail(f"--model: must be 'viscous' or 'hysteretic' (got {damping_model!r})")
    d = _load(design)
    model = build_model(d)
    top = (max_rpm * 2 * np.pi / 60) if max_rpm else max(model.speed, 1.0) * 1.5
    speeds = np.linspace(0.0, top, n_speeds)
    ref = reference_hz * 2 * np.pi if reference_hz else None
    designs = {"design": d}
    if compare_thesis:
        from flexshaft.studies.whirl import thesis_shaft_designs

        try:
            designs.update(thesis_shaft_designs(d))
        except DesignError as exc:
            _fail(f"--compare-thesis needs an isotropic material 'al6061_t6' and a lamina shaft:\n{exc}")
    from flexshaft.studies.verdict import whirl_onset_check

    rpm = 60 / (2 * np.pi)
    margin = d.requirements.min_onset_margin
    required_rpm = (1 + margin) * model.speed * rpm
    rows = {}
    for label, dd in designs.items():
        res = stability(build_model(dd) if label != "design" else model, speeds, 10, damping_model, ref)
        onset = None if res.onset_speed is None else res.onset_speed * rpm
        check = whirl_onset_check(res.onset_speed, float(speeds[-1]), model.speed, margin)
        rows[label] = {
            "onset_speed_rpm": onset,
            "unstable_mode_whirl": None if res.unstable_mode is None else str(res.whirl[-1, res.unstable_mode]),
            "min_damping_ratio": float(res.stability_margin.min()),
            "onset_check": check.status,
        }
    out = {"damping_model": damping_model, "analysed_to_rpm": top * rpm, "operating_speed_rpm": model.speed * rpm,
           "min_onset_margin": margin, "required_onset_rpm": required_rpm, "shafts": rows}
    if as_json:
        typer.echo(json.dumps(out, indent=2))
        return
    typer.echo(f"operating speed {model.speed * rpm:.0f} rpm; required: no whirl onset below {required_rpm:.0f} rpm "
               f"({margin * 100:.0f} % margin, [requirements] min_onset_margin)")
    for label, r in rows.items():
        if r["onset_speed_rpm"] is not None:
            ratio = r["onset_speed_rpm"] / (model.speed * rpm) if model.speed > 0 else float("inf")
            state = (f"unstable above {r['onset_speed_rpm']:.0f} rpm ({r['unstable_mode_whirl']} whirl), "
                     f"{ratio:.2f} × the operating speed")
        else:
            state = f"stable to {out['analysed_to_rpm']:.0f} rpm"
        typer.echo(f"{label}: {state}: {r['onset_check'].upper()}")


@app.command("thermal")
def thermal_cmd(
    design: Optional[Path] = DesignArg,
    loss_model: Optional[str] = typer.Option(None, "--loss-model", help="thesis | rotating (default: the design's)"),
    convection: Optional[str] = typer.Option(None, "--convection", help="becker | kendoush (rotating shaft; default: the design's)"),
    self_heat: bool = typer.Option(False, "--self-heating", help="Iterate temperature-dependent matrix properties."),
    sweeps: bool = typer.Option(False, "--sweeps", help="Peak rise against wall thickness and convection (thesis figs 3.18, 3.19)."),
    as_json: bool = typer.Option(False, "--json", help="Print the results as JSON."),
) -> None:
    """Tailboom temperatures (hover, parked), shaft temperature rise and self-heating margin."""
    if loss_model is not None and loss_model not in ("thesis", "rotating"):
        _fail(f"--loss-model: must be 'thesis' or 'rotating' (got {loss_model!r})")
    if convection is not None and convection not in ("becker", "kendoush"):
        _fail(f"--convection: must be 'becker' or 'kendoush' (got {convection!r})")
    d = _load(design)
    from flexshaft.assembly import build_model
    from flexshaft.studies.thermal import thermal_summary

    out = thermal_summary(d, build_model(d), loss_model=loss_model, convection=convection, self_heat=self_heat, sweeps=sweeps)
    if as_json:
        typer.echo(json.dumps(out, indent=2, default=float))
        return
    for key, value in out.items():
        typer.echo(f"{key}: {value}")


@app.command()
def run(
    design: Optional[Path] = typer.Argument(None, help="Design file (TOML). Default: the embedded tuned design "
                                            "(`flexshaft baseline --name tuned`).", show_default=False),
    out: Path = typer.Option(Path("flexshaft-results"), "--out", "-o", help="Results folder."),
    as_json: bool = typer.Option(False, "--json", help="Print the key results as JSON."),
    studies: str = typer.Option("report", "--studies", help="Design studies in the report: report, full or none."),
    strict: bool = typer.Option(False, "--strict", help=f"Exit with code {REQUIREMENT_FAILED} when a requirement fails."),
) -> None:
    """Analyse a design (default: the embedded tuned design), check it against its requirements
    and write the report folder."""
    from rich.console import Console
    from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    from flexshaft.studies.run import run_analysis

    if studies not in ("report", "full", "none"):
        _fail(f"--studies: must be report, full or none (got {studies!r})")
    from flexshaft.design import DEFAULT_DESIGN

    d = _load(design, DEFAULT_DESIGN)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        _fail(f"--out: cannot create the results folder {out} ({exc.strerror})")
    console = Console(stderr=True)
    with Progress(SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn(), console=console,
                  transient=True, disable=as_json) as progress:
        task = progress.add_task("flexshaft run", total=None)
        results = run_analysis(d, progress=lambda label: progress.update(task, description=label),
                               studies=None if studies == "none" else studies)
        progress.update(task, description="writing the report")
        from flexshaft.report.driveline import results_json, write_run_report

        text, source = _design_text(design, DEFAULT_DESIGN)
        page = write_run_report(results, out, design_text=text, design_source=source)
    data = results_json(results)
    failed = strict and results.verdict is not None and not results.verdict.passed
    if as_json:
        typer.echo(json.dumps(data, indent=2, default=float))
        if failed:
            raise typer.Exit(code=REQUIREMENT_FAILED)
        return
    console = Console()
    s = data["summary"]
    console.print(f"[bold]{d.name}[/bold]")
    console.print(
        f"shaft mass {s['shaft_mass_kg']:.2f} kg, E* = {s['shaft_E_storage_Pa'] / 1e9:.2f} GPa "
        f"(η {s['shaft_E_loss_factor']:.4f}), G* = {s['shaft_G_storage_Pa'] / 1e9:.2f} GPa "
        f"(η {s['shaft_G_loss_factor']:.4f}), torque {s['torque_Nm']:.0f} N m, {s['free_dofs']} free DOFs"
    )
    _print_modes(console, "natural frequencies at rest", data["modes_at_rest"])
    _print_modes(console, f"natural frequencies at {s['operating_speed_rpm']:.0f} rpm", data["modes_at_operating_speed"])
    if data["strength_static_plus_imbalance"]:
        sf = data["strength_static_plus_imbalance"]
        console.print(f"Tsai-Wu safety factor {sf['safety_factor']:.2f} at x = {sf['x_m']:.2f} m, ply {sf['ply']} "
                      f"({sf['ply_angle_deg']:+.0f}°), {sf['dominant_stress']} dominates; "
                      f"buckling safety factor {data['buckling']['safety_factor']:.2f}")
    imb = data["imbalance"]
    console.print(f"spin-up peak shaft orbit {imb['max_shaft_orbit_spin_up_m'] * 1e3:.3f} mm at {imb['speed_of_max_rpm']:.0f} rpm")
    if results.verdict is not None:
        _print_verdict(console, results.verdict)
    console.print(f"report written to {page}")
    if failed:
        raise typer.Exit(code=REQUIREMENT_FAILED)


def _add_study_commands() -> None:
    from flexshaft.cli.study import study_app

    app.add_typer(study_app, name="study")


_add_study_commands()
from flexshaft.cli.optimize import register_optimize; register_optimize(app)  # noqa: E402,E702 (flexshaft optimize)


def main() -> None:  # pragma: no cover - console entry
    app()


if __name__ == "__main__":  # pragma: no cover
    main()
