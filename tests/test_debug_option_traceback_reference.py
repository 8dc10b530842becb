"""``flexshaft --debug`` shows the traceback of an internal error; without it none is shown.

References:

* README.md: "flexshaft --debug COMMAND ...            # show the traceback of an error", and
  the exit code 4 of "internal error (a bug: please report it with the output of
  `flexshaft --debug ...`)".
* The global option's declaration (API contract): ``--debug``, help "Show the traceback of an
  error.", environment variable ``FLEXSHAFT_DEBUG``.

The internal error is a stand-in bug (a ``RuntimeError`` raised by the ``explore`` command's
optional-package check, its second step, after the ``--out`` check) run through the real
application, so the option goes through the app's callback to the error boundary. No analysis
runs: about 0.02 s of CPU.
"""

from __future__ import annotations

import importlib

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.cli.common import settings

INTERNAL_ERROR = 4  # README, "Exit codes"
TRACEBACK = "Traceback (most recent call last)"

# the module (the package's name `explore` is the command function)
explore_command = importlib.import_module("flexshaft.cli.explore")
runner = CliRunner()


def _bug() -> list[str]:
    raise RuntimeError("stand-in bug")


@pytest.fixture(autouse=True)
def _stand_in_bug(monkeypatch, tmp_path):
    monkeypatch.setattr(explore_command, "missing_packages", _bug)
    monkeypatch.setattr(settings, "debug", False)  # restored after the test
    monkeypatch.delenv("FLEXSHAFT_DEBUG", raising=False)
    monkeypatch.chdir(tmp_path)


def test_internal_error_without_debug_has_no_traceback():
    result = runner.invoke(app, ["explore"])
    assert result.exit_code == INTERNAL_ERROR
    assert "internal error: RuntimeError: stand-in bug" in result.stderr
    assert TRACEBACK not in result.stderr


def test_debug_option_shows_the_traceback():
    result = runner.invoke(app, ["--debug", "explore"])
    assert result.exit_code == INTERNAL_ERROR
    assert TRACEBACK in result.stderr
    assert "_bug" in result.stderr  # the traceback reaches the faulty function


def test_debug_environment_variable_shows_the_traceback():
    result = runner.invoke(app, ["explore"], env={"FLEXSHAFT_DEBUG": "1"})
    assert result.exit_code == INTERNAL_ERROR
    assert TRACEBACK in result.stderr
