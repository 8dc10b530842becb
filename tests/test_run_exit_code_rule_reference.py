"""`flexshaft run` exits 3 on a failing design only with --strict.

Reference (README, "Exit codes": "0 success; 2 a user error (bad design file, argument or output
folder) ...; 3 `run --strict` when the design fails a requirement"; the --strict help: "Exit with
code 3 when a requirement fails"). A design that fails a requirement is still a successful run
without --strict: exit 0, its failing verdict in the output; with --strict the same run exits 3
and still prints its results. The analysis is replaced by a stand-in assessment whose verdict
fails (run_pipeline and results_json are stubbed), so the test checks only the command's exit
rule, not any number (< 0.2 s a case). The run works in tmp_path (current folder and --out).
"""

from __future__ import annotations

import importlib
import json
from pathlib import Path
from types import SimpleNamespace

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app


@pytest.mark.parametrize("strict, code", [(False, 0), (True, 3)])
def test_a_failing_verdict_exits_3_only_with_strict(monkeypatch, tmp_path: Path, strict: bool, code: int) -> None:
    run = importlib.import_module("flexshaft.cli.run")  # the module: `flexshaft.cli.run` is the command
    import flexshaft.report.results_json as results_json

    monkeypatch.chdir(tmp_path)  # anything written by mistake lands in tmp_path
    failing = SimpleNamespace(verdict=SimpleNamespace(passed=False))
    monkeypatch.setattr(
        run, "run_pipeline", lambda loaded, folder, progress, **kwargs: (failing, folder / "report.html", None)
    )
    monkeypatch.setattr(results_json, "results_json", lambda assessment, thesis=None: {"verdict": {"passed": False}})
    args = ["run", "--studies", "none", "--json", "--out", str(tmp_path / "out")] + (["--strict"] if strict else [])
    result = CliRunner().invoke(app, args)
    assert result.exit_code == code, result.output
    assert json.loads(result.stdout)["verdict"]["passed"] is False  # the results are printed either way
