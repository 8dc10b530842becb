"""What ``flexshaft run`` and ``flexshaft explore`` do with their arguments before computing.

References (hand-written docs, quoted verbatim):

* README.md: "`flexshaft run my.toml` writes `my-results/` (`flexshaft-results/` for the
  embedded design; ...)"; and "PNG figures (SVG with `--svg`; none with `--no-figures`, for a
  scripted `--strict` gate ...)" -- ``--no-figures`` alone is a valid run, ``--svg`` with
  ``--no-figures`` asks for figures that are not drawn (the run's own refusal, exit 2, names both).
* docs/explorer.md: "`--interactive` needs the extra; without it the command exits 2 before
  computing anything." and "Without the extra, `flexshaft explore` exits with code 2 and the
  `pip install` command."; its option table: "| `DESIGN` | the design file to start from
  (default: the embedded tuned design) |" and "| `--out FOLDER` | where the full-resolution runs
  started from the page go (`run-001`, `run-002`, ...) |" (a folder: a file there is refused).
* README.md, "Exit codes: 0 success; 2 a user error (bad design file, argument or output folder),
  with a message naming what to change".

A missing optional package is made unimportable for the test (``sys.modules[name] = None``,
which makes ``import name`` raise ``ModuleNotFoundError`` as when it is not installed). The run's
computation and the explorer's server are recording stand-ins: nothing is computed, no socket is
opened; each test loads one embedded design (about 0.1-0.3 s of CPU).
"""

from __future__ import annotations

import importlib
import sys
import types
from pathlib import Path

import pytest
import typer
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.design import embedded_design, embedded_text

run_command = importlib.import_module("flexshaft.cli.run")  # `flexshaft.cli.run` is the command function
runner = CliRunner()


def refused(result, *words: str) -> str:
    """The stderr of a clean refusal: exit 2, no traceback, naming ``words``."""
    assert result.exit_code == 2, (result.exit_code, result.output)
    assert "Traceback" not in result.output and "internal error" not in result.stderr
    for word in words:
        assert word in result.stderr, (word, result.stderr)
    return result.stderr


# ------------------------------------------------------------------------------------------------
# flexshaft run


@pytest.fixture
def pipeline(monkeypatch, tmp_path):
    """``flexshaft run``'s computation replaced by a recorder that stops the command (exit 0)
    once handed its folder and options; the working directory is ``tmp_path``."""
    calls: list[dict] = []

    def stand_in(loaded, folder, progress, **options):
        calls.append({"folder": Path(folder), "design": loaded.design, **options})
        raise typer.Exit(code=0)

    monkeypatch.setattr(run_command, "run_pipeline", stand_in)
    monkeypatch.chdir(tmp_path)
    return calls


def test_run_writes_design_stem_results_by_default(pipeline, tmp_path: Path) -> None:
    """README.md: `flexshaft run my.toml` writes `my-results/` (`flexshaft-results/` for the
    embedded design)."""
    (tmp_path / "my.toml").write_text(embedded_text("tuned"), encoding="utf-8")
    result = runner.invoke(app, ["run", "my.toml"])
    assert result.exit_code == 0, result.output
    assert pipeline.pop()["folder"].resolve() == (tmp_path / "my-results").resolve()
    result = runner.invoke(app, ["run"])
    assert result.exit_code == 0, result.output
    assert pipeline.pop()["folder"].resolve() == (tmp_path / "flexshaft-results").resolve()


def test_run_no_figures_alone_runs_and_with_svg_is_refused(pipeline, tmp_path: Path) -> None:
    """README.md: PNG figures, SVG with `--svg`, none with `--no-figures` (the scripted gate):
    `--no-figures` alone runs without figures; `--svg --no-figures` contradicts itself and is
    refused (exit 2) before the design is read, naming both options."""
    result = runner.invoke(app, ["run", "--no-figures", "-o", "gate"])
    assert result.exit_code == 0, result.output
    call = pipeline.pop()
    assert (call["figures"], call["svg"]) == (False, False)
    missing = tmp_path / "no-such-design.toml"  # refused for the options, not the file
    refused(runner.invoke(app, ["run", str(missing), "--svg", "--no-figures", "-o", "both"]), "--svg", "--no-figures")
    assert not pipeline and not (tmp_path / "both").exists()


def test_run_interactive_without_plotly_exits_2_before_computing(pipeline, monkeypatch, tmp_path: Path) -> None:
    """docs/explorer.md: "`--interactive` needs the extra; without it the command exits 2 before
    computing anything" -- no computation, no output folder, the install command printed."""
    monkeypatch.setitem(sys.modules, "plotly", None)
    out = tmp_path / "interactive-run"
    message = refused(runner.invoke(app, ["run", "--interactive", "-o", str(out)]), "plotly", "pip install")
    assert "flexshaft[explore]" in message
    assert not pipeline and not out.exists()


# ------------------------------------------------------------------------------------------------
# flexshaft explore


@pytest.fixture
def served(monkeypatch, tmp_path):
    """``flexshaft explore``'s server replaced by a recorder of the design and options it gets."""
    calls: list[dict] = []
    launch = types.ModuleType("flexshaft.explore.launch")
    launch.serve = lambda loaded, **kwargs: calls.append({"design": loaded.design, **kwargs})  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "flexshaft.explore.launch", launch)
    monkeypatch.chdir(tmp_path)
    return calls


def test_explore_starts_from_the_tuned_design(served, monkeypatch) -> None:
    """docs/explorer.md: DESIGN "default: the embedded tuned design" (not the thesis baseline)."""
    monkeypatch.setattr(importlib.import_module("flexshaft.cli.explore"), "missing_packages", list)
    result = runner.invoke(app, ["explore"])
    assert result.exit_code == 0, result.output
    design = served.pop()["design"]
    assert design == embedded_design("tuned")
    assert design != embedded_design("baseline")


def test_explore_names_only_the_missing_package(served, monkeypatch) -> None:
    """docs/explorer.md: without the extra, exit 2 and the `pip install` command; the message
    names what is missing -- here uvicorn alone (starlette and plotly import)."""
    for present in ("starlette", "plotly"):
        importlib.import_module(present)  # the test's premise: these two are installed
    monkeypatch.setitem(sys.modules, "uvicorn", None)
    message = refused(runner.invoke(app, ["explore"]), "uvicorn", "pip install 'flexshaft[explore]'")
    assert "starlette" not in message and "plotly" not in message
    assert not served


def test_explore_refuses_a_file_as_out_before_serving(served, monkeypatch, tmp_path: Path) -> None:
    """docs/explorer.md: `--out FOLDER` receives the runs (`run-001`, ...): an existing file
    there is refused (exit 2, naming --out) and the server never starts."""
    monkeypatch.setattr(importlib.import_module("flexshaft.cli.explore"), "missing_packages", list)
    (tmp_path / "runs").write_text("mine\n", encoding="utf-8")
    refused(runner.invoke(app, ["explore", "--out", "runs"]), "--out", "runs", "not a folder")
    assert not served
    assert (tmp_path / "runs").read_text(encoding="utf-8") == "mine\n"
