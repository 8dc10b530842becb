"""``flexshaft explore``'s options reach the server: its documented defaults and ``--workers``.

References:

* docs/explorer.md, the option table: "| `--host`, `--port` | where to listen (default 127.0.0.1
  and a free port) |" and "| `--workers N` | worker processes (default: the CPUs, 2 to 4) |";
  and "It listens on this machine only; `--host 0.0.0.0` (or any address that is not a loopback)
  makes it reachable from the network".
* The options' help texts (API contract): ``--port`` "Port; 0 picks a free one.",
  ``--workers`` "Worker processes (default: CPUs, 2 to 4)." -- so the default handed on is
  ``None`` (the server picks 2 to 4 from the CPUs) and ``--workers 3`` hands on 3.

The server is a stand-in module recording its keyword arguments (no web stack, no socket, no
worker process); the optional-package check is answered "nothing missing", so the test runs
without the extra. Only the embedded tuned design is loaded: about 0.1 s of CPU.
"""

from __future__ import annotations

import importlib
import sys
import types

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app

# the module (the package's name `explore` is the command function)
explore_command = importlib.import_module("flexshaft.cli.explore")
runner = CliRunner()


@pytest.fixture
def served(monkeypatch, tmp_path):
    """Run ``flexshaft explore ARGS`` against a recording stand-in of the server; returns the
    keyword arguments ``serve`` received."""
    calls: list[dict] = []
    launch = types.ModuleType("flexshaft.explore.launch")
    launch.serve = lambda loaded, **kwargs: calls.append(kwargs)  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "flexshaft.explore.launch", launch)
    monkeypatch.setattr(explore_command, "missing_packages", list)
    monkeypatch.chdir(tmp_path)  # the default --out folder is relative

    def run(*args: str) -> dict:
        result = runner.invoke(app, ["explore", *args])
        assert result.exit_code == 0, result.output
        assert len(calls) == 1
        return calls.pop()

    return run


def test_default_listens_on_loopback_on_a_free_port(served):
    """docs/explorer.md: default 127.0.0.1 (this machine only) and a free port (``--port`` 0)."""
    kwargs = served()
    assert kwargs["host"] == "127.0.0.1"
    assert kwargs["port"] == 0


def test_workers_option_is_handed_to_the_server(served):
    """``--workers N`` is the explorer's worker-process count; without it the server's own
    default (the CPUs, 2 to 4) applies, so nothing is imposed (``None``)."""
    assert served("--workers", "3")["processes"] == 3
    assert served()["processes"] is None
    # the other options are handed on as given, too
    kwargs = served("--host", "::1", "--port", "8765")
    assert (kwargs["host"], kwargs["port"]) == ("::1", 8765)
