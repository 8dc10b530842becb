"""A reader that goes away (``flexshaft run | head``): the command's results stay complete.

A closed stdout is an ordinary end for a command-line tool: the command that wrote its files
exits 0 without a word, and its output folder is marked complete (the marker that a rerun
without ``--force`` reads, tests/test_rerun.py). rich's console ended such a run with
``SystemExit(1)`` past the commands' error boundary, leaving a finished report folder marked
incomplete; the tables are now printed by a console that hands the broken pipe to the boundary
(:func:`flexshaft.cli.tables.stdout_console`).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest
from conftest import RUN_DESIGN

from flexshaft.cli import app
from flexshaft.cli.output import MARKER
from flexshaft.cli.tables import stdout_console


class _ClosedStdout:
    """A stdout whose reader went away: every write raises ``BrokenPipeError`` (EPIPE)."""

    encoding = "utf-8"

    def write(self, text: str) -> int:
        raise BrokenPipeError(32, "Broken pipe")

    def flush(self) -> None:
        raise BrokenPipeError(32, "Broken pipe")

    def isatty(self) -> bool:
        return False

    def fileno(self) -> int:
        raise OSError("no file descriptor")


def test_the_tables_console_hands_a_broken_pipe_to_the_error_boundary(monkeypatch) -> None:
    monkeypatch.setattr(sys, "stdout", _ClosedStdout())
    console = stdout_console()
    with pytest.raises(BrokenPipeError):
        console.print("a table row")
    assert console.quiet  # nothing more is written to the closed stream


def test_a_study_whose_reader_went_away_exits_0_with_its_folder_complete(tmp_path: Path, monkeypatch) -> None:
    """A command that writes an output folder, then prints its tables (as ``run`` does, whose
    whole report costs seconds more: CPU budget, issue 23): ``study buckling`` of the suite's
    small design on one worker, its stdout closed from the start (``| head`` that has read its
    lines). Its folder is written, then its first line meets the broken pipe: exit 0, nothing
    on stderr, the folder marked complete with every file it lists."""
    design = tmp_path / "design.toml"
    design.write_text(RUN_DESIGN, encoding="utf-8")
    monkeypatch.setattr(sys, "stdout", _ClosedStdout())
    with pytest.raises(SystemExit) as ended:
        app(["study", "buckling", str(design), "--jobs", "1", "--out", str(tmp_path / "out")], prog_name="flexshaft")
    assert ended.value.code == 0
    marker = json.loads((tmp_path / "out" / MARKER).read_text(encoding="utf-8"))
    assert marker["complete"] is True
    assert "results.nc" in marker["entries"]
    assert all((tmp_path / "out" / name).exists() for name in marker["entries"])
