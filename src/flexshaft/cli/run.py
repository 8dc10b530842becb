"""``flexshaft run``: the assessment of a design (:func:`flexshaft.verdict.assess.assess` at the
report's resolution), the thesis studies beside it on the same worker pool, and the report folder."""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Annotated

import typer

from flexshaft.cli.common import (
    EXIT_REQUIREMENT_FAILED,
    fail,
    guarded,
    load_design_argument,
    print_json,
    refuse_envelope_points,
)
from flexshaft.cli.options import ForceOption, JsonOption, Studies
from flexshaft.cli.output import default_output_folder, marker_source, prepare_output_folder
from flexshaft.cli.progress import StageProgress

__all__ = ["run", "run_pipeline"]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).


def _worker_processes() -> int:
    """Worker processes of the run: the CPUs this process may use, at most 4
    (benchmarks/studies_timing.py measures the run with them)."""
    from flexshaft.parallel.pool import available_cpus  # light, but the CLI imports nothing it may not need

    return max(1, min(4, available_cpus()))


@guarded
def run(
    design: Annotated[
        Path | None,
        typer.Argument(
            help="Design file (TOML). Default: the embedded tuned design (`flexshaft baseline --name tuned`).",
            show_default=False,
            metavar="DESIGN",
        ),
    ] = None,
    out: Annotated[
        Path | None,
        typer.Option(
            "--out",
            "-o",
            help="Results folder: report.html, figures, results.json, timings.json (created if "
            "missing; a rerun of the same design file replaces its results; refused if it holds other "
            "files, see --force). Default: DESIGN-results (the design file's name without .toml), "
            "flexshaft-results for the embedded design.",
            show_default=False,
        ),
    ] = None,
    force: ForceOption = False,
    as_json: JsonOption = False,
    studies: Annotated[
        Studies,
        typer.Option(
            "--studies",
            case_sensitive=False,
            help="Thesis chapter-3 design studies in the report: report (the whole run about 8 s on 2 cores), full "
            "(about 15 s) or none (about 4 s).",
        ),
    ] = Studies.report,
    strict: Annotated[
        bool, typer.Option("--strict", help=f"Exit with code {EXIT_REQUIREMENT_FAILED} when a requirement fails.")
    ] = False,
    svg: Annotated[bool, typer.Option("--svg", help="Also write every figure as SVG (PNG always).")] = False,
    figures: Annotated[
        bool,
        typer.Option(
            "--figures/--no-figures",
            help="Draw the report's figures (--no-figures: the report's text and tables and the data files "
            "only, 40-45 % less CPU in a run without studies: for scripted runs such as a --strict gate).",
        ),
    ] = True,
    interactive: Annotated[
        bool,
        typer.Option(
            "--interactive",
            help="Also write interactive.html: the key figures with hover and zoom, plotly.js inlined (works "
            "offline; needs the extra flexshaft[explore]).",
        ),
    ] = False,
) -> None:
    """Analyse a design (default: the embedded tuned design), check it against its requirements
    and write the report folder. Prints the design and the verdict first, the tables after; shows
    each stage and its time on a terminal."""
    from flexshaft.design import DEFAULT_DESIGN

    if svg and not figures:  # before the design is read: the options alone contradict
        fail("--svg writes every figure as SVG as well, and --no-figures draws none: give one of them")
    loaded = load_design_argument(design)
    if interactive:
        from flexshaft.report.interactive_page import missing_extra

        if (message := missing_extra("flexshaft run --interactive")) is not None:  # before any computation
            fail(message)  # how to install the extra
    if studies is not Studies.none and not loaded.design.operating.speed_rad_s > 0:
        # the thesis studies are spin-ups and whirl maps up to the operating speed: none at rest
        typer.echo("note: the thesis studies need an operating speed > 0 (the design's is 0): skipped", err=True)
        studies = Studies.none
    from flexshaft.assembly.size import check_problem_size
    from flexshaft.resolution import REPORT

    # refuses what cannot finish before the folder is touched: the assessment and the thesis studies
    check_problem_size(loaded.design, "run" if studies is not Studies.none else "assess", REPORT, source=loaded.source)
    refuse_envelope_points(loaded.design, loaded.source)
    folder = prepare_output_folder(
        default_output_folder(design, "results") if out is None else out,
        loaded.design,
        "run",
        force=force,
        source=marker_source(design, DEFAULT_DESIGN),
    )
    progress = StageProgress(transient=as_json)
    assessment, page, thesis = run_pipeline(
        loaded, folder, progress, studies=studies, svg=svg, figures=figures, interactive=interactive
    )
    failed = strict and not assessment.verdict.passed
    from flexshaft.report.results_json import results_json

    data = results_json(assessment, thesis)
    if as_json:
        print_json(data)
    else:
        _print_run(assessment, data, page, progress.elapsed, design)
    if failed:
        raise typer.Exit(code=EXIT_REQUIREMENT_FAILED)


def run_pipeline(
    loaded,
    folder: Path,
    progress: StageProgress,
    *,
    studies: Studies = Studies.report,
    svg: bool = False,
    figures: bool = True,
    interactive: bool = False,
) -> tuple:
    """What ``flexshaft run`` computes and writes, without its arguments and printing: the
    assessment at the report's resolution with the thesis studies beside it on one worker pool,
    then the report folder. ``flexshaft explore`` runs a design at full resolution through it.

    Parameters
    ----------
    loaded : LoadedDesign
        The design and its file text (:func:`~flexshaft.cli.common.load_design_argument`).
    folder : Path
        The output folder, already prepared (:func:`~flexshaft.cli.output.prepare_output_folder`).
    progress : StageProgress
        Not yet entered: entered once the workers have forked; its ``step`` gets each stage's
        label, its timings go to ``timings.json``.
    studies, svg, figures
        As ``flexshaft run``'s options.
    interactive : bool
        Also write ``interactive.html`` (:func:`flexshaft.report.interactive_page.write_interactive_report`).

    Returns
    -------
    (Assessment, Path, ThesisStudies or None)
        The assessment, the report page and the thesis studies.
    """
    from flexshaft.assembly.size import ProblemSizeWarning, check_problem_size
    from flexshaft.parallel.pool import worker_pool
    from flexshaft.plot.output import FIGURE_MODULES
    from flexshaft.resolution import REPORT
    from flexshaft.thesis.report_studies import start_thesis_studies
    from flexshaft.verdict.assess import assess

    # the thesis studies are spin-ups and whirl maps up to the operating speed: none at rest
    with_studies = studies is not Studies.none and loaded.design.operating.speed_rad_s > 0
    # refuses what cannot finish, warns when large: the assessment and the thesis studies
    check_problem_size(loaded.design, "run" if with_studies else "assess", REPORT, source=loaded.source)
    # No xarray in this process: the studies' results travel as plain arrays
    # (flexshaft.analyses.labelled) and their .nc files are written from them
    # (flexshaft.netcdf.write_labelled_netcdf; xarray only when netCDF4 is installed).
    # the workers import what the figures need while the analyses run (none drawn: nothing)
    with worker_pool(_worker_processes(), FIGURE_MODULES if figures else ()) as pool, progress:
        # the thesis studies are no part of the assessment: they run beside it on the same workers
        pending = start_thesis_studies(loaded.design, studies.value, pool) if with_studies else None
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ProblemSizeWarning)  # estimated above, with the studies
            assessment = assess(loaded.design, REPORT, executor=pool, progress=progress.step)
        thesis = pending.result(progress.step) if pending is not None else None
        progress.step("writing the report")
        from flexshaft.report.driveline import write_run_report  # after the analyses: 0.1-0.2 s of imports

        page = write_run_report(
            assessment,
            folder,
            design_text=loaded.text,
            design_source=loaded.source,
            timings=dict(progress.timings),
            thesis=thesis,
            svg=svg,
            figures=figures,
            executor=pool,
        )
        if interactive:
            from flexshaft.report.interactive_page import write_interactive_report

            progress.step("writing the interactive figures")
            write_interactive_report(assessment, folder)
    return assessment, page, thesis


def _print_run(assessment, data: dict, page: Path, seconds: float, path: Path | None) -> None:
    """The design, the verdict in one line, the model and the modes, the headline numbers, the
    verdict table and where the report is."""
    from flexshaft.cli.tables import (
        design_heading,
        design_source,
        modes_table,
        print_line,
        sig,
        stdout_console,
        verdict_line,
        verdict_table,
    )
    from flexshaft.units import m_to_mm
    from flexshaft.verdict.envelope_text import envelope_line

    console = stdout_console()
    s = data["summary"]
    verdict = assessment.verdict
    print_line(console, design_heading(s["name"], design_source(path)), style="bold")
    print_line(console, verdict_line(verdict), style="bold green" if verdict.passed else "bold red")
    envelope = envelope_line(assessment)
    if envelope:
        print_line(console, envelope)
    # with an envelope, the analyses shown are the governing point's: each headline names it, so
    # that its numbers are not read as the verdict's worst case (the verdict table's [point])
    at = "" if assessment.design.envelope is None else f" [{assessment.governing_point}]"
    print_line(
        console,
        f"shaft mass {sig(s['shaft_mass_kg'])} kg, E* = {sig(s['shaft_E_storage_Pa'] / 1e9)} GPa "
        f"(loss factor {sig(s['shaft_E_loss_factor'], 3)}), G* = {sig(s['shaft_G_storage_Pa'] / 1e9)} GPa "
        f"(loss factor {sig(s['shaft_G_loss_factor'], 3)}), torque {sig(s['torque_Nm'])} N m, "
        f"{s['free_dofs']} free DOFs{at}",
    )
    console.print(modes_table(f"natural frequencies at rest{at}", data["modes_at_rest"]))
    console.print(
        modes_table(f"natural frequencies at {sig(s['operating_speed_rpm'])} rpm{at}", data["modes_at_operating_speed"])
    )
    sf = data["strength_static_plus_imbalance"]
    if sf:
        print_line(
            console,
            f"Tsai-Wu safety factor {sig(sf['safety_factor'], 3)} at x = {sig(sf['x_m'], 3)} m, "
            f"ply {sf['ply']} ({sf['ply_angle_deg']:+.0f}°), {sf['dominant_stress']} dominates; "
            f"buckling safety factor {sig(data['buckling']['safety_factor'], 3)}{at}",
        )
    imbalance = data["imbalance"]
    print_line(
        console,
        f"spin-up peak shaft orbit {sig(m_to_mm(imbalance['max_shaft_orbit_spin_up_m']), 3)} mm "
        f"at {sig(imbalance['speed_of_max_rpm'])} rpm{at}",
    )
    console.print(verdict_table(verdict))
    print_line(console, f"report written to {page} in {sig(seconds, 3)} s (stage times in timings.json)")
