"""``python -m flexshaft`` is the ``flexshaft`` command (was: "No module named flexshaft.__main__").

Reference: README.md installs the console script ``flexshaft``; Python's ``-m`` runs a package's
``__main__`` module (the Python documentation, "runpy"). Run in this process with
:func:`runpy.run_module` as ``-m`` does; the version line is the console script's
(``flexshaft --version``: ``flexshaft <version>``).
"""

from __future__ import annotations

import runpy
import sys
from importlib.metadata import version

import pytest


def test_python_m_flexshaft_runs_the_command(monkeypatch, capsys):
    monkeypatch.setattr(sys, "argv", ["flexshaft", "--version"])
    with pytest.raises(SystemExit) as ended:
        runpy.run_module("flexshaft", run_name="__main__", alter_sys=True)
    assert ended.value.code in (0, None)
    assert capsys.readouterr().out.strip() == f"flexshaft {version('flexshaft')}"
