"""What ``runup --json`` and ``montecarlo --json`` hand back is the run the user asked for, in the
unit its key names.

References (rules written in the hand-written docs, quoted in each test, and values chosen here):

* README.md: "``--json`` (every command) prints JSON on stdout instead: values in SI units, the
  unit in each key (...), except rotational speeds in rpm (``_rpm``)": ``start_rpm`` of
  ``--start-rpm 1000`` is 1000 (not its 1000 · 2π/60 = 104.7 rad/s).
* ``montecarlo --force-limit``'s help: "default each one's own force capacity (as the verdict ...)":
  without the option the JSON's ``force_limit_N`` is the limit the study counted against, not
  null; likewise ``gap_m``. What the study reports as these is written in its docstrings
  (src/flexshaft/montecarlo/steady.py, ``MonteCarlo.gap``: "The smallest gap of the active
  bearings [m]", ``MonteCarlo.force_limit``: "The smallest force capacity of the active bearings
  [N]"): the stand-in study's bearings hold gaps 5e-4 and 2.5e-4 m and capacities 1500 and
  2000 N, so 2.5e-4 m and 1500 N.

The run-up and Monte-Carlo analyses are stand-ins (the sibling file's fixtures, imported), so no
analysis runs; exact comparisons (the values pass through at most one rpm → rad/s → rpm round
trip, rel 1e-12).
"""

from __future__ import annotations

import json
import sys
from types import SimpleNamespace

import numpy as np
import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from tests.test_runup_montecarlo_commands_reference import RUNUP, montecarlo_result, no_files, runup_seen  # noqa: F401


def test_runup_json_start_rpm_is_in_rpm(tmp_path, runup_seen) -> None:  # noqa: F811
    result = CliRunner().invoke(app, [*RUNUP, "--json", "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["start_rpm"] == pytest.approx(1000.0, rel=1e-12)  # --start-rpm 1000, key in rpm
    assert data["stop_rpm"] == pytest.approx(3000.0, rel=1e-12)
    assert data["duration_s"] == 2.0


def test_montecarlo_json_reports_the_limits_counted_against(tmp_path, monkeypatch, no_files) -> None:  # noqa: F811
    def run(design, samples, **kw):
        assert kw["gap"] is None and kw["force_limit"] is None  # no option: each bearing's own
        return montecarlo_result(  # gap and force_limit: the smallest of the bearings' (docstring)
            2.5e-4,
            1500.0,
            np.arange(1.0, 101.0) * 1e-5,
            limits={
                "amb_1": SimpleNamespace(gap=5e-4, force_capacity=1500.0),
                "amb_2": SimpleNamespace(gap=2.5e-4, force_capacity=2000.0),
            },
        )

    monkeypatch.setattr("flexshaft.cli.bounds.check_montecarlo", lambda *a: None)
    monkeypatch.setitem(sys.modules, "flexshaft.montecarlo.steady", SimpleNamespace(run_montecarlo=run))
    result = CliRunner().invoke(app, ["montecarlo", "--samples", "100", "--json", "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["force_limit_N"] == 1500.0
    assert data["gap_m"] == 2.5e-4
