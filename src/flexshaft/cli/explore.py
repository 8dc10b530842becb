"""``flexshaft explore``: the design explorer in the browser (:mod:`flexshaft.explore`).

The command only checks its arguments and that the extra ``flexshaft[explore]`` is installed
(exit code 2 with the command to install it otherwise), then hands over to
:func:`flexshaft.explore.launch.serve`.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import Annotated

import typer

from flexshaft.cli.common import fail, guarded, load_design_argument
from flexshaft.cli.options import Studies

__all__ = ["EXPLORE_PACKAGES", "explore", "missing_packages"]

#: The packages of the extra ``flexshaft[explore]`` the explorer imports.
EXPLORE_PACKAGES = ("starlette", "uvicorn", "plotly")


def missing_packages() -> list[str]:
    """The packages of :data:`EXPLORE_PACKAGES` that cannot be imported."""
    missing = []
    for name in EXPLORE_PACKAGES:
        try:
            importlib.import_module(name)
        except ImportError:
            missing.append(name)
    return missing


@guarded
def explore(
    design: Annotated[
        Path | None,
        typer.Argument(
            help="Design file (TOML) to start from. Default: the embedded tuned design.",
            show_default=False,
            metavar="DESIGN",
        ),
    ] = None,
    host: Annotated[
        str, typer.Option("--host", help="Address to listen on (a warning when it is not this machine's loopback).")
    ] = "127.0.0.1",
    port: Annotated[int, typer.Option("--port", min=0, max=65535, help="Port; 0 picks a free one.")] = 0,
    pareto: Annotated[
        Path | None,
        typer.Option("--pareto", help="A `flexshaft optimize` run folder: its Pareto front, click a point to load it."),
    ] = None,
    out: Annotated[
        Path, typer.Option("--out", "-o", help="Folder of the full runs started from the page (run-001, ...).")
    ] = Path("flexshaft-explore"),
    studies: Annotated[
        Studies,
        typer.Option("--studies", case_sensitive=False, help="Thesis studies in a full run's report (as `run`)."),
    ] = Studies.report,
    workers: Annotated[
        int | None, typer.Option("--workers", min=1, max=16, help="Worker processes (default: CPUs, 2 to 4).")
    ] = None,
) -> None:
    """Explore a design in the browser: change the driveline, see the verdict move (screening
    grids, about 0.3 s per update). Prints the page's address; Ctrl-C stops."""
    if out.exists() and not out.is_dir():  # the full runs write below it: refused before the server starts
        fail(f"--out: {out} is a file, not a folder; give a folder path (it is created if missing)")
    missing = missing_packages()
    if missing:
        fail(
            f"flexshaft explore needs the optional packages {', '.join(missing)}: "
            "install them with pip install 'flexshaft[explore]'"
        )
    loaded = load_design_argument(design, "tuned")
    front = None
    if pareto is not None:  # read before the server starts; the refusal names the option
        from flexshaft.design import DesignError
        from flexshaft.explore.pareto import read_front

        try:
            front = read_front(pareto)
        except DesignError as exc:
            fail(f"--pareto {pareto}: " + "; ".join(problem.message for problem in exc.problems))
    from flexshaft.explore.launch import serve  # the web stack: only this command loads it

    serve(loaded, host=host, port=port, front=front, out=out, studies=studies.value, processes=workers)
