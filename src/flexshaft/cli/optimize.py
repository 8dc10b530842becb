"""``flexshaft optimize``: multi-objective design search with the requirements verdict as constraints.

Mounted in :mod:`flexshaft.cli`. Exit codes: 0 when at least one
design passes every requirement (and, unless ``--no-verify``, every written design re-verifies
with the full run), 2 for a user error (bad option, unknown path, missing extra, a run folder of
another search), 3 when no design passes or a written design fails its re-verification.
"""

from __future__ import annotations

import json
import math
from enum import Enum
from pathlib import Path

import typer

from flexshaft.cli.common import dask_client, fail, guarded, plain


class Fidelity(str, Enum):
    """Resolution of an optimizer evaluation (``flexshaft.optimize.evaluate.FIDELITIES``)."""

    verdict = "verdict"
    screening = "screening"


__all__ = ["NO_DESIGN_PASSES", "Fidelity", "optimize", "parse_variable"]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).

#: Exit code when no evaluated design passes every requirement (or one fails re-verification).
NO_DESIGN_PASSES = 3


def _fail(message: str) -> None:
    fail(message)  # exit 2 through the error boundary of every command


def parse_variable(spec: str):
    """``PATH[,PATH...]=LOWER:UPPER[:int|:log]`` -> DesignVariable (values in the design
    file's units: SI, ply angles in degrees)."""
    from flexshaft.optimize.variables import DesignVariable, OptimizeError

    paths, sep, rest = spec.partition("=")
    parts = rest.split(":")
    if not sep or len(parts) not in (2, 3) or not paths.strip():
        raise OptimizeError(
            f"--var {spec!r}: expected PATH[,PATH...]=LOWER:UPPER[:int|:log], "
            "e.g. shaft.wall_thickness=0.0015:0.004 or bearings[1].kp,bearings[2].kp=1e5:1e7:log"
        )
    flag = parts[2].strip() if len(parts) == 3 else ""
    if flag not in ("", "int", "log"):
        raise OptimizeError(f"--var {spec!r}: the flag must be 'int' or 'log' (got {flag!r})")
    try:
        lower, upper = float(parts[0]), float(parts[1])
    except ValueError:
        raise OptimizeError(f"--var {spec!r}: bounds must be numbers (got {parts[0]!r}, {parts[1]!r})") from None
    if flag == "int":
        if not (math.isfinite(lower) and math.isfinite(upper)) or lower != int(lower) or upper != int(upper):
            raise OptimizeError(f"--var {spec!r}: an integer variable needs integer bounds")
        lower, upper = int(lower), int(upper)
    names = tuple(p.strip() for p in paths.split(","))
    return DesignVariable(names if len(names) > 1 else names[0], lower, upper, integer=flag == "int", log=flag == "log")


def _parse_set(spec: str) -> tuple[str, object]:
    path, sep, text = spec.partition("=")
    if not sep or not path.strip():
        _fail(f"--set {spec!r}: expected PATH=VALUE, e.g. bearings[1].gap=0.0005")
    try:
        value = json.loads(text)
    except ValueError:
        value = text
    return path.strip(), value


def _load_design(path: Path | None, embedded: str):
    from flexshaft.design import EMBEDDED_DESIGNS, DesignError, embedded_design, load_design

    try:
        if path is None:
            return embedded_design(embedded)
        if not path.exists() and str(path) in EMBEDDED_DESIGNS:
            return embedded_design(str(path))
        return load_design(path)
    except DesignError as exc:
        _fail(f"invalid design {path if path is not None else f'(embedded {embedded})'}:\n{exc}")


def _base_label(path: Path | None) -> str:
    if path is None:
        return "base (Table 3.1 baseline)"
    return f"base ({path.stem if path.suffix == '.toml' else path.name})"


@guarded
def optimize(
    design: Path | None = typer.Argument(
        None,
        help="Base design file (TOML). Default: the embedded Table 3.1 baseline (`flexshaft baseline`).",
        show_default=False,
    ),
    budget: int = typer.Option(
        ...,
        "--budget",
        "-n",
        min=1,
        help="Design evaluations the search may use (refused with the numbers when estimated above 4 h per worker).",
    ),
    out: Path | None = typer.Option(
        None,
        "--out",
        "-o",
        help="Run folder: every evaluation is kept there; run again to resume or extend (a rerun of an edited "
        "design file starts afresh). Default: DESIGN-optimize (flexshaft-optimize for the embedded design).",
        show_default=False,
    ),
    force: bool = typer.Option(
        False,
        "--force",
        help="Write into a non-empty --out folder that flexshaft did not write, or wrote for another design.",
    ),
    jobs: int = typer.Option(1, "--jobs", "-j", min=1, help="Local worker processes (one BLAS thread each)."),
    dask: str | None = typer.Option(None, "--dask", help="Dask scheduler address, e.g. tcp://host:8786."),
    var: list[str] | None = typer.Option(
        None,
        "--var",
        help="Variable PATH[,PATH...]=LOWER:UPPER[:int|:log] in the design file's units (SI, "
        "ply angles in degrees); layup.NAME fills {NAME} of --layup. Default: ply angles (a/-a/b/-b)s, wall "
        "thickness, shared K_p and K_d of the active bearings, their stations.",
    ),
    layup: str | None = typer.Option(None, "--layup", help="Layup template, e.g. '({a}/{-a}/0_{n})s'."),
    ply_thickness_mm: float | None = typer.Option(
        None, "--ply-thickness-mm", help="Ply thickness in mm: the wall thickness is plies x this."
    ),
    objective: list[str] | None = typer.Option(
        None,
        "--objective",
        help="shaft_mass, safety_factor, buckling_safety_factor, actuator_force, actuator_orbit, "
        "spinup_deflection, max_temperature, min_log_decrement. Default: shaft_mass and safety_factor.",
    ),
    ignore_check: list[str] | None = typer.Option(
        None, "--ignore-check", help="Verdict check not used as a constraint (default: all)."
    ),
    set_value: list[str] | None = typer.Option(None, "--set", help="Fixed override PATH=VALUE on every candidate."),
    fidelity: Fidelity = typer.Option(
        Fidelity.verdict, "--fidelity", help="verdict (the run's resolution) or screening (coarser, for ranking)."
    ),
    pop_size: int | None = typer.Option(None, "--pop-size", min=2, help="NSGA-II population."),
    seed: int = typer.Option(1, "--seed", min=0, help="Seed of the search (>= 0)."),
    reference: list[str] | None = typer.Option(
        None, "--reference", help="Design marked on the figure: embedded name or file."
    ),
    designs: int = typer.Option(8, "--designs", min=1, help="Pareto designs written as design files (at most)."),
    verify: bool = typer.Option(True, "--verify/--no-verify", help="Re-verify the written designs with the full run."),
) -> None:
    """Search the designs that pass every requirement for the best trade-off of the objectives
    (NSGA-II from pymoo: pip install the 'optimize' extra of flexshaft)."""
    from flexshaft.cli.output import default_output_folder, design_source, prepare_output_folder
    from flexshaft.design import EMBEDDED_DESIGNS, DesignError, with_overrides
    from flexshaft.optimize import DesignProblem, OptimizeError, default_variables
    from flexshaft.optimize.evaluate import CHECK_KEYS, applicable_checks
    from flexshaft.sweep import SweepError

    base = _load_design(design, "baseline")
    client = dask_client(dask)  # checked and connected before anything is prepared
    embedded = design is None or (not design.exists() and str(design) in EMBEDDED_DESIGNS)
    fixed = dict(_parse_set(s) for s in set_value or [])
    if fixed:
        try:  # every candidate carries them: refuse a bad one here, not as a search without a feasible design
            with_overrides(base, fixed)
        except DesignError as exc:
            _fail(f"--set: the overrides {', '.join(set_value or [])} do not make a valid design:\n{exc}")
    refs = {}
    for item in reference or []:
        refs[Path(item).stem if item.endswith(".toml") else item] = _load_design(Path(item), item)
    for key in ignore_check or []:
        if key not in CHECK_KEYS:
            _fail(f"--ignore-check: unknown check {key!r} (allowed: {', '.join(CHECK_KEYS)})")
    if ply_thickness_mm is not None and not (math.isfinite(ply_thickness_mm) and ply_thickness_mm > 0):
        _fail(f"--ply-thickness-mm: must be a positive thickness (got {ply_thickness_mm})")
    try:
        if var:
            variables, template = tuple(parse_variable(s) for s in var), layup
        else:
            variables, template = default_variables(base)
            template = layup or template
        problem = DesignProblem(
            variables,
            base=base,
            objectives=tuple(objective or ("shaft_mass", "safety_factor")),
            constraints=tuple(k for k in applicable_checks(base) if k not in (ignore_check or [])),
            layup=template,
            ply_thickness=None if ply_thickness_mm is None else ply_thickness_mm * 1e-3,
            fixed=fixed,
            fidelity=Fidelity(fidelity).value,
            name=f"flexshaft optimize: {base.name}",
        )
        from flexshaft.cli.bounds import check_optimize, workers_of
        from flexshaft.optimize.nsga import optimize as run_optimization

        check_optimize(base, budget, Fidelity(fidelity).value, workers_of(jobs, client))
        name = str(design) if embedded and design is not None else "baseline"
        out = prepare_output_folder(
            default_output_folder(None if embedded else design, "optimize", name if design else "flexshaft")
            if out is None
            else out,
            base,
            "optimize",
            force=force,
            source=design_source(None if embedded else design, name),
        )
        result = run_optimization(
            problem,
            budget,
            out,
            pop_size=pop_size,
            seed=seed,
            jobs=jobs,
            client=client,
            references=refs,
            base_label=_base_label(design),
            progress=lambda line: typer.echo(plain(line), err=True),
        )  # stdout: results
    except (OptimizeError, SweepError) as exc:
        _fail(str(exc))
    _report(result, out, designs, verify, jobs, client)


def _report(result, out: Path, max_designs: int, verify: bool, jobs: int, client) -> None:
    from flexshaft.plot.driveline import save_figure

    paths = result.save(out)
    figure = save_figure(result.plot(), out, "pareto")
    typer.echo(f"{result!r}; {result.n_computed} computed in {result.elapsed:.0f} s")
    typer.echo(f"written: {paths['evaluations']}, {paths['pareto']}, {figure['png']}")
    if result.pareto.sizes.get("design", 0) == 0:
        typer.echo(
            "no evaluated design passes every requirement: raise the budget, widen the bounds or "
            "see the margins in evaluations.nc",
            err=True,
        )
        raise typer.Exit(code=NO_DESIGN_PASSES)
    files = result.write_designs(out / "designs", max_designs)
    failed = []
    if verify:
        ds = result.verify(files, jobs=jobs, client=client)
        failed = [Path(f).name for f, ok in zip(ds["design_file"].values, ds["passed"].values) if ok != 1]
    result.save(out)
    _print_table(result)
    typer.echo(f"design files: {out / 'designs'} ({len(files)})")
    if failed:
        typer.echo(f"re-verification with the full run FAILS for: {', '.join(failed)}", err=True)
        raise typer.Exit(code=NO_DESIGN_PASSES)


def _print_table(result) -> None:
    from flexshaft.cli.tables import print_line, stdout_console, table

    pareto = result.pareto
    console = stdout_console()
    if "shaft_mass" not in pareto:  # a custom evaluation: print the objectives only
        print_line(console, str(pareto[[o.output for o in result.problem.objectives]].to_dataframe()))
        return
    names = ("shaft_mass", "safety_factor", "buckling_safety_factor", "actuator_force", "spinup_deflection")

    def row(label, outputs, verdict):
        return [
            label,
            outputs["shaft_mass"],
            outputs["safety_factor"],
            outputs["buckling_safety_factor"],
            outputs["actuator_force"],
            outputs["spinup_deflection"] * 1e3,
            verdict,
        ]

    rows = [
        row(label, outputs, "PASS" if outputs["feasible"] else "FAIL") for label, outputs in result.references.items()
    ]
    for k in range(pareto.sizes["design"]):
        name = str(pareto["file"].values[k]) if "file" in pareto else ""
        if not name:
            continue
        verified = {1.0: "PASS run", 0.0: "FAIL run"}.get(
            float(pareto["verified"].values[k]) if "verified" in pareto else -1.0, "PASS"
        )
        rows.append(row(name.removesuffix(".toml"), {n: float(pareto[n].values[k]) for n in names}, verified))
    console.print(
        table(
            "Pareto designs and references (search verdict; 'run': re-verified by the full run)",
            ["design", "mass [kg]", "strength SF", "buckling SF", "force [N]", "orbit [mm]", "verdict"],
            rows,
            numeric=range(1, 6),
        )
    )
