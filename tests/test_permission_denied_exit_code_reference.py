"""A file or folder the user may not write or read is a user error, exit 2, not a bug.

README's exit codes: "2 a user error (bad design file, argument or output folder) with a message
naming what to change; ... 4 an internal error (a bug ...)". Permission denied (errno EACCES) and
operation not permitted (EPERM) on the command's output are the user's to change, so the command
exits 2 with ``error: cannot write or read PATH: ...`` naming the path, and never says "internal
error" nor asks for a bug report.

The operating system's refusal is raised by a stand-in of the thermal study (a test run as root
could not make a real directory unwritable); nothing is computed: about 0.1 s.
"""

from __future__ import annotations

import errno
import importlib
import os

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app

runner = CliRunner()
THERMAL_STUDY = importlib.import_module("flexshaft.thermal.study")


@pytest.mark.parametrize("code", [errno.EACCES, errno.EPERM])
def test_a_refused_path_is_a_user_error(monkeypatch: pytest.MonkeyPatch, code: int) -> None:
    def thermal_summary(*args, **kwargs):
        raise PermissionError(code, os.strerror(code), "/protected/out")

    monkeypatch.setattr(THERMAL_STUDY, "thermal_summary", thermal_summary)
    result = runner.invoke(app, ["thermal"])
    assert result.exit_code == 2, result.output
    assert f"error: cannot write or read /protected/out: {os.strerror(code)}" in result.stderr
    assert "internal error" not in result.stderr
