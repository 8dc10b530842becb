"""``flexshaft optimize``: refusals before any work, the JSON verdict after a failed
re-verification, and a read-only output folder at the error boundary.

References (hand-written docs, quoted):

* docs/optimizer.md: "Exit codes: 0 when at least one design passes (and every written design
  re-verifies), 2 for a user error (bad option or path, ...), 3 when no design passes or a
  written design fails its re-verification." and "user errors exit 2, naming the option."
  ``--json`` prints "``passed``, ... The exit codes are as above": a result that exits 3 is
  not ``passed``.
* docs/limits.md / the schema: an actuator gap is allowed in (0, 0.1] m, so a gap of -1 m is
  no valid design; ``--set`` is a "Fixed override PATH=VALUE on every candidate" (the option's
  help), so a bad one is the user's option to change.
* ``--ply-thickness-mm``: "Ply thickness in mm: the wall thickness is plies x this" (its help);
  a thickness of 0 mm is no thickness.
* README.md: "Exit codes. 0 success; 2 a user error (bad design file, argument or output
  folder) with a message naming what to change; ... 4 an internal error (a bug ...)". A
  read-only file system (errno EROFS) under the output folder is the user's to change.

The optimizer is replaced by a stand-in that records whether it was reached, the thermal study
by one raising the operating system's error; nothing is computed (each test well under 1 s).
"""

from __future__ import annotations

import errno
import importlib
import json
import os
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
import typer
import xarray as xr
from typer.testing import CliRunner

from flexshaft.cli import app
from tests.test_optimize_command_reference import _Result

runner = CliRunner()
command = importlib.import_module("flexshaft.cli.optimize")  # the package exports the function
THERMAL_STUDY = importlib.import_module("flexshaft.thermal.study")


@pytest.fixture
def search_reached(monkeypatch) -> list:
    """The optimizer replaced by a stand-in that records each call (and computes nothing)."""
    import flexshaft.optimize.nsga as nsga

    calls: list = []

    def stand_in(problem, budget, out, **kwargs):
        calls.append(problem)
        raise AssertionError("the search was reached")

    monkeypatch.setattr(nsga, "optimize", stand_in)
    return calls


def test_a_set_value_no_design_takes_is_refused_naming_set(search_reached, tmp_path: Path) -> None:
    """--set bearings[1].gap=-1 (a gap outside (0, 0.1] m) with an explicit --var: refused as a
    user error (exit 2) naming --set and the field, before the search or its folder."""
    out = tmp_path / "o"
    result = runner.invoke(
        app,
        [
            "optimize",
            "--budget",
            "4",
            "--out",
            str(out),
            "--var",
            "shaft.wall_thickness=0.0015:0.004",
            "--set",
            "bearings[1].gap=-1",
        ],
    )
    assert result.exit_code == 2, result.output
    assert "error: --set:" in result.stderr and "bearings[1].gap" in result.stderr, result.stderr
    assert search_reached == [] and not out.exists()


def test_a_zero_ply_thickness_is_refused_naming_the_option(search_reached, tmp_path: Path) -> None:
    """--ply-thickness-mm 0: refused (exit 2) naming the option, before the search or its folder."""
    out = tmp_path / "o"
    result = runner.invoke(app, ["optimize", "--budget", "4", "--out", str(out), "--ply-thickness-mm", "0"])
    assert result.exit_code == 2, result.output
    assert "error: --ply-thickness-mm:" in result.stderr, result.stderr
    assert search_reached == [] and not out.exists()


class _Reverified(_Result):
    """The sibling's one-design result, re-verified by a full run that fails it, with what the
    JSON reads (one objective, no constraint, one feasible evaluation)."""

    def __init__(self) -> None:
        super().__init__(spinup_deflection=4.2e-4)
        self.pareto["evaluation"] = ("design", [0])
        self.evaluations = xr.Dataset({"feasible": ("evaluation", [True])})
        self.problem = SimpleNamespace(
            outputs=[("driveline_mass", "kg", ""), ("shaft_mass", "kg", "")],
            derived_outputs=[],
            all_output_names=["driveline_mass", "shaft_mass"],
            objectives=[SimpleNamespace(output="driveline_mass", sense="min")],
            constraints=[],
            fidelity="verdict",
            base=SimpleNamespace(name="stand-in"),
            variables=(),
        )

    def verify(self, files, **kwargs):
        self.verified_with.append(files)
        return xr.Dataset({"design_file": ("design", np.array([str(f) for f in files])), "passed": ("design", [0])})

    def blocking_checks(self):
        return []


def test_json_is_not_passed_when_a_written_design_fails_its_reverification(monkeypatch, tmp_path: Path, capsys) -> None:
    """One written design, the full run fails it: exit 3, and --json says passed false with
    the design among reverification_failed."""
    import flexshaft.plot.driveline as driveline

    monkeypatch.setattr(driveline, "save_figure", lambda figure, out, name: {"png": out / f"{name}.png"})
    result = _Reverified()
    with pytest.raises(typer.Exit) as ended:
        command._report(result, tmp_path, 8, True, 1, None, True)
    assert ended.value.exit_code == 3
    assert len(result.verified_with) == 1
    data = json.loads(capsys.readouterr().out)
    assert data["passed"] is False, data
    assert data["reverification_failed"] == ["pareto_001.toml"]


def test_a_read_only_file_system_is_a_user_error(monkeypatch: pytest.MonkeyPatch) -> None:
    """errno EROFS on the output: exit 2 naming the path, no 'internal error'."""

    def thermal_summary(*args, **kwargs):
        raise OSError(errno.EROFS, os.strerror(errno.EROFS), "/mounted-ro/out")

    monkeypatch.setattr(THERMAL_STUDY, "thermal_summary", thermal_summary)
    result = runner.invoke(app, ["thermal"])
    assert result.exit_code == 2, result.output
    assert f"error: cannot write or read /mounted-ro/out: {os.strerror(errno.EROFS)}" in result.stderr
    assert "internal error" not in result.stderr


@pytest.mark.parametrize(("name", "label"), [("my.toml", "base (my)"), ("my.design", "base (my.design)")])
def test_the_base_is_labelled_by_its_file_name_without_toml(monkeypatch, tmp_path: Path, name, label) -> None:
    """docs/optimizer.md: "The base is labelled `base (NAME)` ...: NAME is the design file's
    name without its `.toml` (`base (my)` for `my.toml`)"; another suffix is part of the name.
    The search is a stand-in recording the label it is handed (nothing is computed)."""
    import flexshaft.optimize.nsga as nsga
    from flexshaft.design import embedded_text

    labels: list = []

    def stand_in(problem, budget, out, **kwargs):
        labels.append(kwargs["base_label"])
        raise typer.Exit(9)

    monkeypatch.setattr(nsga, "optimize", stand_in)
    design = tmp_path / name
    design.write_text(embedded_text("tuned"), encoding="utf-8")
    args = ["optimize", str(design), "--budget", "4", "--out", str(tmp_path / "o")]
    args += ["--var", "shaft.wall_thickness=0.0015:0.004"]
    result = runner.invoke(app, args)
    assert labels == [label], result.output
