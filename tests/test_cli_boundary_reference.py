"""The CLI's error boundary against its documented exit codes, with stand-in commands.

Reference: README.md, "Exit codes":

    0 success; 2 a user error (bad design file, argument or output folder) with a message naming
    what to change; 3 ``run --strict`` when the design fails a requirement; 4 an internal error
    (a bug: please report it with the output of ``flexshaft --debug ...``).

and the docstring of :mod:`flexshaft.cli.common`: a user error ends with ``error: …`` on stderr
(no traceback; ``--debug`` adds it), an internal fault prints a hint to report it and the
traceback only with ``flexshaft --debug``; user strings are printed with control characters
escaped; ``--help`` of ``run --strict`` reads "Exit with code 3 when a requirement fails". The
output folder's final marker is written when the command ends: complete after it returned or
exited on purpose (exit 0 or 3), incomplete after an error (README: "``"complete": false``
until every file is written").

Each case is a stand-in command wrapped by the real boundary (:func:`~flexshaft.cli.common.guarded`)
in a small Typer app run with CliRunner, raising what a layer below raises: a
:class:`~flexshaft.cli.common.UserError`, a design's :class:`~flexshaft.design.DesignError`
naming a field and its value, an analysis' ``RefusedInputError``, a full disk (``ENOSPC``)
naming the file, ``typer.Exit(3)`` of a failed requirement, a plain bug. No analysis runs.
The BLAS default of :mod:`flexshaft.cli` is checked against its docstring ("One BLAS thread in
the command's process and its workers, unless the user set the variables").
Whole file: about 0.03 s of CPU (``--cpu-durations``; the solvers are never imported).
"""

from __future__ import annotations

import errno
import json
import sys
import types
from pathlib import Path

import pytest
import typer
from typer.testing import CliRunner

from flexshaft.cli import common
from flexshaft.cli.common import EXIT_REQUIREMENT_FAILED, guarded, settings
from flexshaft.cli.output import MARKER, prepare_output_folder

# README, "Exit codes"
OK, USER_ERROR, REQUIREMENT_FAILED, INTERNAL_ERROR = 0, 2, 3, 4

runner = CliRunner()


class _Design:
    name = "My design"

    def model_dump(self, mode: str = "json") -> dict:
        return {"name": self.name, "shaft": {"wall_thickness": 0.003}}


def _app(raise_, folder: Path | None = None) -> typer.Typer:
    """A Typer app of two commands (so each is named on the command line) whose ``go``
    prepares ``folder`` if given, writes a result into it, then calls ``raise_()``."""
    app = typer.Typer()

    @app.callback()
    def options(debug: bool = typer.Option(False, "--debug")) -> None:
        settings.debug = debug

    @app.command("go")
    @guarded
    def go() -> None:
        if folder is not None:
            prepare_output_folder(folder, _Design(), "run", source="my.toml")
            (folder / "results.json").write_text("{}")
        raise_()

    @app.command("other")
    @guarded
    def other() -> None:
        pass

    return app


def _invoke(raise_, *, debug: bool = False, folder: Path | None = None):
    try:
        return runner.invoke(_app(raise_, folder), [*(["--debug"] if debug else []), "go"])
    finally:
        settings.debug = False


def _raiser(exc: BaseException):
    def raise_() -> None:
        raise exc

    return raise_


def _complete(folder: Path) -> bool:
    return json.loads((folder / MARKER).read_text(encoding="utf-8"))["complete"]


def test_success_exits_0_and_marks_the_folder_complete(tmp_path: Path) -> None:
    result = _invoke(lambda: None, folder=tmp_path / "out")
    assert result.exit_code == OK, result.output
    assert _complete(tmp_path / "out") is True


def test_a_user_error_exits_2_with_its_message_and_no_traceback(tmp_path: Path) -> None:
    result = _invoke(_raiser(common.UserError("--speed: must be a finite number (got nan)")), folder=tmp_path / "o")
    assert result.exit_code == USER_ERROR
    assert result.stderr.startswith("error: --speed: must be a finite number (got nan)")
    assert "Traceback" not in result.output and "internal error" not in result.output
    assert _complete(tmp_path / "o") is False  # the command did not finish its folder
    debug = _invoke(_raiser(common.UserError("--speed: bad")), debug=True)
    assert debug.exit_code == USER_ERROR and "Traceback (most recent call last)" in debug.stderr


def test_an_invalid_design_exits_2_naming_the_field_and_value() -> None:
    from flexshaft.design import DesignError, Problem

    error = DesignError([Problem("shaft.wall_thickness", "must be > 0 (got -0.003)")], "my.toml")
    result = _invoke(_raiser(error))
    assert result.exit_code == USER_ERROR
    assert "my.toml" in result.stderr and "shaft.wall_thickness" in result.stderr and "-0.003" in result.stderr
    assert "Traceback" not in result.output and "internal error" not in result.output


def test_an_analysis_refusing_its_input_is_a_user_error(monkeypatch) -> None:
    """The analyses' RefusedInputError (a singular system, an unstable controller) names the
    input: exit 2. The boundary finds the class only where its module is loaded (it never
    imports the solvers); the real module when the session loaded it, else a stand-in module
    holding a class of that name (numpy and scipy stay unloaded)."""
    guards = sys.modules.get("flexshaft.analyses.guards")
    if guards is None:
        guards = types.ModuleType("flexshaft.analyses.guards")
        guards.RefusedInputError = type("RefusedInputError", (ValueError,), {})
        monkeypatch.setitem(sys.modules, "flexshaft.analyses.guards", guards)
    refusal = guards.RefusedInputError("bearings[1].kp: the controller is unstable at rest")
    result = _invoke(_raiser(refusal))
    assert result.exit_code == USER_ERROR
    assert "bearings[1].kp" in result.stderr and "internal error" not in result.output


def test_a_full_disk_exits_2_naming_the_file(tmp_path: Path) -> None:
    target = tmp_path / "out" / "report.html"
    result = _invoke(_raiser(OSError(errno.ENOSPC, "No space left on device", str(target))))
    assert result.exit_code == USER_ERROR
    assert str(target) in result.stderr and "No space left on device" in result.stderr
    assert "Traceback" not in result.output


def test_a_failed_requirement_exits_3_and_its_folder_is_complete(tmp_path: Path) -> None:
    """``run --strict`` writes every result, then exits 3: the folder is complete."""
    assert EXIT_REQUIREMENT_FAILED == REQUIREMENT_FAILED
    result = _invoke(_raiser(typer.Exit(code=EXIT_REQUIREMENT_FAILED)), folder=tmp_path / "out")
    assert result.exit_code == REQUIREMENT_FAILED, result.output
    assert "internal error" not in result.output and "error" not in result.stderr
    assert _complete(tmp_path / "out") is True


def test_a_bug_exits_4_with_a_hint_and_the_traceback_only_with_debug() -> None:
    result = _invoke(_raiser(ZeroDivisionError("a bug below")))
    assert result.exit_code == INTERNAL_ERROR
    assert "internal error: ZeroDivisionError: a bug below" in result.stderr and "--debug" in result.stderr
    assert "Traceback" not in result.output
    debug = _invoke(_raiser(ZeroDivisionError("a bug below")), debug=True)
    assert debug.exit_code == INTERNAL_ERROR and "Traceback (most recent call last)" in debug.stderr


def test_a_user_errors_message_is_printed_with_control_characters_escaped() -> None:
    result = _invoke(_raiser(common.UserError("--out: the folder evil\x1b[2J is a file")))
    assert result.exit_code == USER_ERROR
    assert "\x1b" not in result.stderr and r"evil\x1b[2J" in result.stderr


@pytest.mark.parametrize("numpy_loaded", [False, True], ids=["before numpy", "after numpy"])
def test_one_blas_thread_unless_the_user_chose(monkeypatch, numpy_loaded: bool) -> None:
    from flexshaft.cli import _one_blas_thread_per_process

    for name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("OMP_NUM_THREADS", "4")  # the user's choice
    if numpy_loaded:
        monkeypatch.setitem(sys.modules, "numpy", types.ModuleType("numpy"))
    else:
        monkeypatch.delitem(sys.modules, "numpy", raising=False)
    _one_blas_thread_per_process()
    import os

    expected = None if numpy_loaded else "1"  # only effective before numpy loads: left alone after
    assert os.environ.get("OPENBLAS_NUM_THREADS") == expected and os.environ.get("MKL_NUM_THREADS") == expected
    assert os.environ["OMP_NUM_THREADS"] == "4"


def test_an_interruption_says_what_was_kept_and_marks_the_folder_incomplete(tmp_path: Path) -> None:
    """Ctrl-C (KeyboardInterrupt) ends the command at once, as the user asked; what the
    interrupted work kept, attached to the exception as a note (the sweep engine's stored chunks,
    tests/test_sweep_chunks_reference.py), is printed on stderr as ``interrupted: …``; the
    output folder stays marked incomplete. Never an internal error (exit 4) or a traceback."""
    interrupted = KeyboardInterrupt()
    interrupted.add_note("2 of 3 chunks are stored in runs/x: the same command with the same options resumes from them")
    folder = tmp_path / "out"
    result = _invoke(_raiser(interrupted), folder=folder)
    assert result.exit_code not in (OK, USER_ERROR, REQUIREMENT_FAILED, INTERNAL_ERROR)
    assert "interrupted: 2 of 3 chunks are stored in runs/x" in result.stderr
    assert "Traceback" not in result.output and "internal error" not in result.stderr
    assert not _complete(folder)
