"""Command-line interface: ``flexshaft run | baseline | check | modes | stability | thermal | runup |
montecarlo | study | compare | optimize | validate | explore``.

Exit codes: 0 success; 2 a user error (bad design file, argument or output folder), with a
message naming what to change and never a traceback; 3 ``flexshaft run --strict`` on a design
that fails a requirement of its ``[requirements]`` table; 4 an internal fault (a bug), with a
hint to report it and the traceback under ``flexshaft --debug``.

Tables are in engineering units (rpm, Hz, mm, MPa, °C) with the unit in each header; ``--json``
prints SI values with the unit in each key (``frequency_Hz``, ``wall_thickness_m``; rotational
speeds in rpm as ``_rpm`` and temperatures in °C as ``_c``, the units of the design file). Mode
numbers start at 1 (the Python API counts from 0).

The modules: :mod:`~flexshaft.cli.common` (error boundary, plain text, design loading, JSON),
:mod:`~flexshaft.cli.options` (choices and shared options), :mod:`~flexshaft.cli.tables`,
:mod:`~flexshaft.cli.progress`, :mod:`~flexshaft.cli.output` (``--out`` folders: one guarded
path, marker written last), :mod:`~flexshaft.cli.bounds` (each command's work, bounded before
it computes), and the commands in :mod:`~flexshaft.cli.analysis`, :mod:`~flexshaft.cli.run` and
:mod:`~flexshaft.cli.study`.
"""

from __future__ import annotations

from typing import Annotated

import typer

from flexshaft.cli.analysis import baseline, check, modes, stability, thermal
from flexshaft.cli.common import EXIT_REQUIREMENT_FAILED, settings
from flexshaft.cli.compare import compare
from flexshaft.cli.explore import explore
from flexshaft.cli.optimize import optimize
from flexshaft.cli.run import run
from flexshaft.cli.study import study_app
from flexshaft.cli.transient import montecarlo, runup
from flexshaft.cli.validate import validate

__all__ = ["REQUIREMENT_FAILED", "app", "main"]

#: Exit code of ``flexshaft run --strict`` when a requirement fails (2 is a user error).
REQUIREMENT_FAILED = EXIT_REQUIREMENT_FAILED

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    rich_markup_mode=None,  # "[rpm]" in a help text is a unit, not markup
    pretty_exceptions_enable=False,
    help="Design and analysis of high-flexibility rotorcraft tail-rotor drivelines.\n\n"
    "Exit codes: 0 ok, 2 user error (design, argument, output folder), 3 a requirement failed "
    "(run --strict), 4 internal error (see --debug).",
)


def _version(value: bool) -> None:
    if value:
        from flexshaft import __version__

        typer.echo(f"flexshaft {__version__}")
        raise typer.Exit()


@app.callback()
def _options(
    version: Annotated[
        bool, typer.Option("--version", callback=_version, is_eager=True, help="Print the version and exit.")
    ] = False,
    debug: Annotated[
        bool, typer.Option("--debug", envvar="FLEXSHAFT_DEBUG", help="Show the traceback of an error.")
    ] = False,
) -> None:
    """Global options (the app's help text is set on the Typer)."""
    settings.debug = debug
    _one_blas_thread_per_process()


#: BLAS libraries' thread-count variables, read when they load (with numpy).
_BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def _one_blas_thread_per_process() -> None:
    """One BLAS thread in the command's process and its workers, unless the user set the
    variables: the analyses' dense solves are small (a second BLAS thread slows them on a busy
    2-core machine, see flexshaft.parallel.threads) and the commands parallelise over processes; a
    threaded BLAS that spins while worker processes hold the cores cost a third more CPU
    time in ``flexshaft run`` (benchmarks/studies_timing.py). Only effective before numpy
    loads, which the commands do lazily."""
    import os
    import sys

    if "numpy" not in sys.modules:
        for name in _BLAS_THREAD_VARIABLES:
            os.environ.setdefault(name, "1")


app.command("baseline")(baseline)
app.command("check")(check)
app.command("modes")(modes)
app.command("stability")(stability)
app.command("thermal")(thermal)
app.command("run")(run)
app.command("runup")(runup)
app.command("montecarlo")(montecarlo)
app.add_typer(study_app, name="study")
app.command("compare")(compare)
app.command("optimize")(optimize)
app.command("validate")(validate)
app.command("explore")(explore)


def main() -> None:  # pragma: no cover - console entry
    app()


if __name__ == "__main__":  # pragma: no cover
    main()
