"""``flexshaft compare``: two drivelines side by side (default: the tuned FMC design against
today's segmented aluminium driveline, the thesis's comparison) and the comparison report."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any

import typer

from flexshaft.cli.common import guarded, load_design_argument, print_json, refuse_envelope_points
from flexshaft.cli.options import ForceOption, JsonOption
from flexshaft.cli.output import marker_source, prepare_output_folder
from flexshaft.cli.progress import StageProgress

__all__ = ["compare"]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).

#: Embedded designs compared when no file is given: A (the FMC design) and B (the current driveline).
DEFAULTS = ("tuned", "current")


@dataclass(frozen=True)
class _Pair:
    """The two designs as one, for the output folder's marker (its name and fingerprint)."""

    a: Any
    b: Any

    @property
    def name(self) -> str:
        return f"{self.a.name} | {self.b.name}"

    def model_dump(self, mode: str = "json") -> dict:
        return {"a": self.a.model_dump(mode=mode), "b": self.b.model_dump(mode=mode)}


def _default_folder(paths: tuple[Path | None, Path | None]) -> Path:
    """``A-vs-B-compare`` from the design files' names; ``flexshaft-compare`` for the embedded pair."""
    if all(path is None for path in paths):
        return Path("flexshaft-compare")
    stems = [default if path is None else (path.stem or "design") for path, default in zip(paths, DEFAULTS)]
    return Path(f"{stems[0]}-vs-{stems[1]}-compare")


def _labels(paths: tuple[Path | None, Path | None]) -> tuple[str, str]:
    labels = [default if path is None else path.stem for path, default in zip(paths, DEFAULTS)]
    if labels[0] == labels[1]:
        labels = [f"A: {labels[0]}", f"B: {labels[1]}"]
    return labels[0], labels[1]


@guarded
def compare(
    design_a: Annotated[
        Path | None,
        typer.Argument(
            help="First design (TOML). Default: the embedded tuned FMC design (`flexshaft baseline --name tuned`).",
            show_default=False,
            metavar="A",
        ),
    ] = None,
    design_b: Annotated[
        Path | None,
        typer.Argument(
            help="Second design (TOML). Default: the embedded current segmented aluminium driveline "
            "(`flexshaft baseline --name current`).",
            show_default=False,
            metavar="B",
        ),
    ] = None,
    out: Annotated[
        Path | None,
        typer.Option(
            "--out",
            "-o",
            help="Results folder: report.html, figures, results.json, comparison.nc (created if "
            "missing; refused if it holds other files, see --force). Default: A-vs-B-compare (the design "
            "files' names), flexshaft-compare for the embedded designs.",
            show_default=False,
        ),
    ] = None,
    force: ForceOption = False,
    as_json: JsonOption = False,
) -> None:
    """Analyse two designs and write one report with both side by side: mass and parts by kind,
    every requirement with both values and margins, critical speeds, whirl, spin-up, strength,
    temperatures and overlaid figures. With no argument: the tuned FMC design against the
    current segmented aluminium driveline (about 11 s on 2 cores)."""
    loaded = [load_design_argument(path, default) for path, default in zip((design_a, design_b), DEFAULTS)]
    labels = _labels((design_a, design_b))
    from flexshaft.assembly.size import check_problem_size
    from flexshaft.resolution import REPORT

    for each in loaded:  # both assessments bounded before the folder is touched
        check_problem_size(each.design, "assess", REPORT, source=each.source)
        refuse_envelope_points(each.design, each.source)
    sources = [marker_source(path, default) for path, default in zip((design_a, design_b), DEFAULTS)]
    folder = prepare_output_folder(
        _default_folder((design_a, design_b)) if out is None else out,
        _Pair(loaded[0].design, loaded[1].design),
        "compare",
        force=force,
        source=" | ".join(sources),
    )
    from flexshaft.comparison import compare as compare_designs
    from flexshaft.report.compare import comparison_json, write_compare_report

    with StageProgress(transient=as_json) as progress:
        result = compare_designs(loaded[0].design, loaded[1].design, labels=labels, progress=progress.step)
        progress.step("writing the report")
        page = write_compare_report(result, folder)
    if as_json:
        print_json(comparison_json(result))
    else:
        _print_comparison(result, page, progress.elapsed, (design_a, design_b))


def _print_comparison(result, page: Path, seconds: float, paths: tuple[Path | None, Path | None]) -> None:
    from flexshaft.cli.tables import design_source, print_line, sig, stdout_console, table
    from flexshaft.report.compare import format_metric

    console = stdout_console()
    a, b = result.labels
    for label, run, path, default in zip(result.labels, result.runs, paths, DEFAULTS):
        source = design_source(path, default)
        print_line(console, f"design {label}: {run.model.design.name} ({source})", style="bold")
    rows = [
        [m.title, *(format_metric(m.key, m.unit, m.values[d], m.lower_bounds[d]) for d in (0, 1))]
        for m in result.metrics()
    ]
    console.print(table("driveline comparison", ["quantity", a, b], rows, numeric=()))
    for label, run in zip(result.labels, result.runs):
        verdict = run.verdict
        print_line(console, f"{label}: {verdict.summary}", style="bold green" if verdict.passed else "bold red")
    print_line(console, f"report written to {page} in {sig(seconds, 3)} s")
