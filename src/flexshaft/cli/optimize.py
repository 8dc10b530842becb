"""``flexshaft optimize``: multi-objective design search with the requirements verdict as constraints.

Mounted in :mod:`flexshaft.cli`. Default objectives: the driveline mass (actuators included)
against the smallest normalised margin of the requirements. The terminal shows the Pareto designs
and the references; with no feasible design, which requirements block (``blocking_checks.json``
in the run folder too); ``--json`` prints the same as JSON. Exit codes: 0 when at least one
design passes every requirement (and, unless ``--no-verify``, every written design re-verifies
with the full run), 2 for a user error (bad option, unknown path, missing extra, a run folder of
another search), 3 when no design passes or a written design fails its re-verification.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable
from enum import Enum
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn

import typer

from flexshaft.cli.common import dask_client, fail, guarded, plain, print_json
from flexshaft.cli.options import JOBS_HELP, MAX_JOBS, JsonOption

if TYPE_CHECKING:
    from flexshaft.optimize.variables import DesignVariable


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


def _fail(message: str) -> NoReturn:
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


def _base_text(path: Path | None, embedded: str) -> str | None:
    """The base design file's text, whose comments the written designs keep (None if unreadable)."""
    from flexshaft.design import EMBEDDED_DESIGNS, embedded_text

    try:
        if path is None:
            return embedded_text(embedded)
        if not path.exists() and str(path) in EMBEDDED_DESIGNS:
            return embedded_text(str(path))
        return path.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError):
        return None


def _base_label(path: Path | None) -> str:
    if path is None:
        return "base (tuned design)"
    return f"base ({path.stem if path.suffix == '.toml' else path.name})"


@guarded
def optimize(
    design: Path | None = typer.Argument(
        None,
        help="Base design file (TOML). Default: the embedded tuned design (`flexshaft baseline --name tuned`), as "
        "for every command.",
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
    jobs: int = typer.Option(1, "--jobs", "-j", min=1, max=MAX_JOBS, help=JOBS_HELP),
    dask: str | None = typer.Option(None, "--dask", help="Dask scheduler address, e.g. tcp://host:8786."),
    var: list[str] | None = typer.Option(
        None,
        "--var",
        help="Variable PATH[,PATH...]=LOWER:UPPER[:int|:log] in the design file's units (SI, "
        "ply angles in degrees); layup.NAME fills {NAME} of --layup. Default: a search that holds the design: "
        "ply angles (a/-a/b/-b)s, or each of the design's own within 15 deg; wall thickness, K_p and K_d of "
        "the active bearings (shared when equal), their stations.",
    ),
    layup: str | None = typer.Option(None, "--layup", help="Layup template, e.g. '({a}/{-a}/0_{n})s'."),
    ply_thickness_mm: float | None = typer.Option(
        None, "--ply-thickness-mm", help="Ply thickness in mm: the wall thickness is plies x this."
    ),
    objective: list[str] | None = typer.Option(
        None,
        "--objective",
        help="driveline_mass (tubes, couplings, bearings, actuators), min_margin (smallest normalised margin "
        "of the requirements), shaft_mass, safety_factor, buckling_safety_factor, actuator_force, "
        "actuator_orbit, spinup_deflection, max_temperature, min_log_decrement. Default: driveline_mass "
        "and min_margin.",
    ),
    ignore_check: list[str] | None = typer.Option(
        None, "--ignore-check", help="Verdict check not used as a constraint (default: all)."
    ),
    set_value: list[str] | None = typer.Option(
        None, "--set", help="Fixed override PATH=VALUE on every candidate; the default search leaves out what it holds."
    ),
    fidelity: Fidelity = typer.Option(
        Fidelity.verdict, "--fidelity", help="verdict (the run's resolution) or screening (coarser, for ranking)."
    ),
    pop_size: int | None = typer.Option(None, "--pop-size", min=2, help="NSGA-II population, at most --budget."),
    seed: int = typer.Option(1, "--seed", min=0, help="Seed of the search (>= 0)."),
    reference: list[str] | None = typer.Option(
        None, "--reference", help="Design marked on the figure: embedded name or file."
    ),
    designs: int = typer.Option(8, "--designs", min=1, help="Pareto designs written as design files (at most)."),
    verify: bool = typer.Option(True, "--verify/--no-verify", help="Re-verify the written designs with the full run."),
    as_json: JsonOption = False,
) -> None:
    """Search the designs that pass every requirement for the best trade-off of the objectives,
    by default the driveline mass against the smallest requirement margin (NSGA-II from pymoo:
    pip install the 'optimize' extra of flexshaft)."""
    from flexshaft.cli.output import default_output_folder, marker_source, prepare_output_folder
    from flexshaft.cli.tables import design_heading, design_source
    from flexshaft.design import DEFAULT_DESIGN, EMBEDDED_DESIGNS, DesignError, with_overrides
    from flexshaft.optimize import DesignProblem, OptimizeError
    from flexshaft.optimize.evaluate import CHECK_KEYS, applicable_checks
    from flexshaft.optimize.variables import DEFAULT_OBJECTIVES
    from flexshaft.sweep import SweepError

    base = _load_design(design, DEFAULT_DESIGN)
    if design is not None and not design.exists() and str(design) in EMBEDDED_DESIGNS:
        source = design_source(None, str(design))  # an embedded design by name
    else:
        source = design_source(design)
    if not as_json:  # JSON mode prints the JSON document only
        typer.echo(plain(design_heading(base.name, source)))
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
    if pop_size is not None and pop_size > budget:  # before the run folder (flexshaft.optimize.nsga.optimize)
        _fail(
            f"--pop-size: at most --budget ({budget:,}): a larger population cannot finish its first generation "
            f"(got {pop_size:,})"
        )
    if ply_thickness_mm is not None and not (math.isfinite(ply_thickness_mm) and ply_thickness_mm > 0):
        _fail(f"--ply-thickness-mm: must be a positive thickness (got {ply_thickness_mm})")
    try:
        if var:
            variables, template = tuple(parse_variable(s) for s in var), layup
        else:
            variables, template = _default_search(base, fixed, layup, ply_thickness_mm is not None)
        problem = DesignProblem(
            variables,
            base=base,
            objectives=tuple(objective or DEFAULT_OBJECTIVES),
            constraints=tuple(k for k in applicable_checks(base) if k not in (ignore_check or [])),
            layup=template,
            ply_thickness=None if ply_thickness_mm is None else ply_thickness_mm * 1e-3,
            fixed=fixed,
            fidelity=Fidelity(fidelity).value,
            name=f"flexshaft optimize: {base.name}",
            base_text=_base_text(design, DEFAULT_DESIGN),
        )
        from flexshaft.cli.bounds import check_optimize, check_verification, workers_of
        from flexshaft.optimize.nsga import optimize as run_optimization

        check_optimize(base, budget, Fidelity(fidelity).value, workers_of(jobs, client), source)
        if verify:
            check_verification(base, designs, budget, workers_of(jobs, client))
        name = str(design) if embedded and design is not None else DEFAULT_DESIGN
        out = prepare_output_folder(
            default_output_folder(None if embedded else design, "optimize", name if design else "flexshaft")
            if out is None
            else out,
            base,
            "optimize",
            force=force,
            source=marker_source(None if embedded else design, name),
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
    _report(result, out, designs, verify, jobs, client, as_json)


_NO_DESIGN = (
    "no evaluated design passes every requirement: raise the budget, widen the bounds or relax what "
    "blocks (the table; the margins of every design in evaluations.nc)"
)


def _report(result, out: Path, max_designs: int, verify: bool, jobs: int, client, as_json: bool) -> None:
    from flexshaft.plot.driveline import save_figure

    paths = result.save(out)
    figure = save_figure(result.plot(), out, "pareto")
    files, failed = [], []
    if result.pareto.sizes.get("design", 0):
        files = result.write_designs(out / "designs", max_designs)
        if verify:
            ds = result.verify(files, jobs=jobs, client=client)
            failed = [Path(f).name for f, ok in zip(ds["design_file"].values, ds["passed"].values) if ok != 1]
        result.save(out)
    if as_json:
        print_json(_json_result(result, {**paths, "figure": figure["png"]}, files, failed))
    else:
        typer.echo(f"{result!r}; {result.n_computed} computed in {result.elapsed:.0f} s")
        typer.echo(f"written: {paths['evaluations']}, {paths['pareto']}, {paths['blocking']}, {figure['png']}")
        if files:
            _print_table(result)
            typer.echo(f"design files: {out / 'designs'} ({len(files)})")
        else:
            _print_blocking(result)
    if not files:
        typer.echo(_NO_DESIGN, err=True)
        raise typer.Exit(code=NO_DESIGN_PASSES)
    if failed:
        typer.echo(f"re-verification with the full run FAILS for: {', '.join(failed)}", err=True)
        raise typer.Exit(code=NO_DESIGN_PASSES)


def _default_search(
    base, fixed: dict, layup: str | None, ply_thickness: bool
) -> tuple[tuple[DesignVariable, ...], str | None]:
    """The default search around the design every candidate starts from: the base with the
    ``--set`` fields (a set neighbour bounds a bearing's station, a set gain widens the range),
    without what they hold (and the wall with ``--ply-thickness-mm``)."""
    from flexshaft.design import with_overrides
    from flexshaft.optimize import default_variables

    start = with_overrides(base, fixed) if fixed else base
    held = [*fixed, *(["shaft.wall_thickness"] if ply_thickness else [])]
    return _search_around(default_variables(start, layup), held, layup)


def _search_around(
    default: tuple[tuple[DesignVariable, ...], str | None], held_paths: Iterable[str], layup: str | None
) -> tuple[tuple[DesignVariable, ...], str | None]:
    """The default search without what is held: the paths ``--set`` gives (however written, or
    a table holding them; a gain shared by several bearings stays searched at the others) and
    the wall with ``--ply-thickness-mm`` (it follows the ply count), and the ply-angle
    variables with their template when ``--set`` gives the shaft's layup (and ``--layup`` does
    not)."""
    import dataclasses

    from flexshaft.design.io import paths_overlap

    fixed = list(held_paths)

    def held(path: str) -> bool:
        return any(paths_overlap(path, f) for f in fixed)

    variables, template = default
    if held("shaft.layup") and layup is None:
        variables, template = tuple(v for v in variables if v.placeholder is None), None
    kept = []
    for v in variables:
        rest = [p for p in v.paths if not held(p)]
        if len(rest) == len(v.paths):
            kept.append(v)
        elif rest:
            kept.append(dataclasses.replace(v, path=tuple(rest)))  # the shared variable at the paths not held
    return tuple(kept), template


def _suffixed(name: str, units: str) -> str:
    """A JSON key with its unit (``driveline_mass_kg``; dimensionless: the name alone)."""
    return name if units in ("", "1") else f"{name}_{units.replace(' ', '_')}"


def _json_result(result, paths: dict, files: list, failed: list) -> dict:
    """The optimization as plain data: the search, the Pareto designs, the references, what
    blocks and the files written (SI values, each unit in its key)."""
    import numpy as np

    problem, ev, pareto = result.problem, result.evaluations, result.pareto
    units = {name: unit for name, unit, _ in problem.outputs + problem.derived_outputs}
    shown = [n for n in problem.all_output_names if not n.startswith("status_")]

    def outputs_of(values) -> dict:
        return {_suffixed(n, units[n]): float(values[n]) for n in shown if n in values}

    designs = []
    for k in range(pareto.sizes.get("design", 0)):
        row = {n: pareto[n].values[k] for n in shown if n in pareto}
        verified = float(pareto["verified"].values[k]) if "verified" in pareto else -1.0
        designs.append(
            {
                "file": str(pareto["file"].values[k]) or None if "file" in pareto else None,
                "verified": {1.0: True, 0.0: False}.get(verified),
                "evaluation": int(pareto["evaluation"].values[k]),
                "limiting_check": str(pareto["limiting_check"].values[k]) if "limiting_check" in pareto else None,
                "variables": {
                    _suffixed(v.name, v.units.replace(" m-1", "_per_m")): (
                        int(pareto[v.name].values[k]) if v.integer else float(pareto[v.name].values[k])
                    )
                    for v in problem.variables
                },
                "outputs": outputs_of(row),
            }
        )
    n = ev.sizes.get("evaluation", 0)
    return {
        "design": str(problem.base.name),
        "objectives": [
            {"output": o.output, "sense": o.sense, "units": units.get(o.output, "")} for o in problem.objectives
        ],
        "constraints": [c.removeprefix("margin_") for c in problem.constraints],
        "fidelity": problem.fidelity,
        "evaluations": int(n),
        "feasible": int(np.sum(ev["feasible"].values)) if n else 0,
        "computed": int(result.n_computed),
        "elapsed_s": float(result.elapsed),
        "passed": bool(files) and not failed,
        "pareto": designs,
        "references": {
            label: {
                "feasible": bool(values.get("feasible", False)),
                "limiting_check": values.get("limiting_check"),
                "outputs": outputs_of(values),
            }
            for label, values in result.references.items()
        },
        "blocking_checks": result.blocking_checks(),
        "reverification_failed": failed,
        "files": {**{k: str(v) for k, v in paths.items()}, "designs": [str(f) for f in files]},
    }


def _print_blocking(result) -> None:
    """What keeps every design out: per requirement, the candidates it rejects."""
    from flexshaft.cli.tables import stdout_console, table

    rows = result.blocking_checks()
    n = result.evaluations.sizes.get("evaluation", 0)
    stdout_console().print(
        table(
            f"no design passes: what blocks the {n} evaluated designs",
            ["requirement", "rejects", "alone", "not evaluated", "best margin"],
            [[r["check"], r["rejected"], r["alone"], r["not_evaluated"], r["best_margin"]] for r in rows],
            numeric=range(1, 5),
            caption="rejects: designs failing it; alone: designs failing only it; best margin: the largest "
            "normalised margin reached (>= 0 passes)",
        )
    )


def _print_table(result) -> None:
    from flexshaft.cli.tables import print_line, stdout_console, table

    pareto = result.pareto
    console = stdout_console()
    if "shaft_mass" not in pareto:  # a custom evaluation: print the objectives only
        print_line(console, str(pareto[[o.output for o in result.problem.objectives]].to_dataframe()))
        return
    names = (
        "driveline_mass",
        "shaft_mass",
        "min_margin",
        "safety_factor",
        "buckling_safety_factor",
        "actuator_force",
        "spinup_deflection",
    )

    def row(label, outputs, limiting, verdict):
        nan = float("nan")
        return [
            label,
            *(outputs.get(n, nan) for n in names[:3]),
            limiting or "",
            *(outputs.get(n, nan) for n in names[3:6]),
            outputs.get("spinup_deflection", nan) * 1e3,
            verdict,
        ]

    rows = [
        row(label, outputs, outputs.get("limiting_check"), "PASS" if outputs["feasible"] else "FAIL")
        for label, outputs in result.references.items()
    ]
    for k in range(pareto.sizes["design"]):
        name = str(pareto["file"].values[k]) if "file" in pareto else ""
        if not name:
            continue
        verified = {1.0: "PASS run", 0.0: "FAIL run"}.get(
            float(pareto["verified"].values[k]) if "verified" in pareto else -1.0, "PASS"
        )
        limiting = str(pareto["limiting_check"].values[k]) if "limiting_check" in pareto else ""
        values = {n: float(pareto[n].values[k]) for n in names if n in pareto}
        rows.append(row(name.removesuffix(".toml"), values, limiting, verified))
    console.print(
        table(
            "Pareto designs and references (search verdict; 'run': re-verified by the full run)",
            [
                "design",
                "driveline [kg]",
                "shaft [kg]",
                "smallest margin",
                "limited by",
                "strength SF",
                "buckling SF",
                "force [N]",
                "orbit [mm]",
                "verdict",
            ],
            rows,
            numeric=[1, 2, 3, 5, 6, 7, 8],
            caption="driveline: tubes, couplings, bearings and actuators; smallest margin: the smallest "
            "normalised margin of the requirements (>= 0 passes), that of 'limited by'",
        )
    )
