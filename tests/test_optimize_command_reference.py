"""``flexshaft optimize``: what its options become, with the optimizer replaced by a stand-in
(nothing is optimised or assessed).

References: the command's documented option grammar (``--var PATH[,PATH...]=LOWER:UPPER[:int|:log]``,
``--ply-thickness-mm`` "in mm", ``--objective``, ``--ignore-check``, ``--pop-size``,
``--no-verify``: the options' help and docs/optimizer.md), the unit factor written out
(1 mm = 1e-3 m), and the objectives' senses as docs/optimizer.md lists them ("`safety_factor`
(minimum ply Tsai-Wu) max, ... `actuator_force` [N] min").
"""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.optimize.variables import OptimizeError

runner = CliRunner()
command = importlib.import_module("flexshaft.cli.optimize")  # the package exports the function


def test_a_variable_spec_is_read_as_written() -> None:
    """``bearings[1].kp,bearings[2].kp=1e5:1e7:log``: two paths sharing one value, lower bound
    1e5 N/m, upper 1e7 N/m, searched in log10; ``...=0.0015:0.004``: plain, 1.5 to 4 mm."""
    gains = command.parse_variable("bearings[1].kp,bearings[2].kp=1e5:1e7:log")
    assert gains.path == ("bearings[1].kp", "bearings[2].kp")
    assert (gains.lower, gains.upper, gains.log, gains.integer) == (1e5, 1e7, True, False)
    wall = command.parse_variable("shaft.wall_thickness=0.0015:0.004")
    assert (wall.path, wall.lower, wall.upper, wall.log, wall.integer) == (
        "shaft.wall_thickness",
        0.0015,
        0.004,
        False,
        False,
    )
    plies = command.parse_variable("layup.n=1:4:int")
    assert (plies.lower, plies.upper, plies.integer, plies.log) == (1, 4, True, False)


@pytest.fixture
def handed_over(monkeypatch, tmp_path: Path):
    """Runs the command with the optimizer replaced: the stand-in records the problem and the
    options it is handed, then refuses (exit 2), so nothing is evaluated."""
    import flexshaft.optimize.nsga as nsga

    seen: dict = {}

    def stand_in(problem, budget, out, **kwargs):
        seen.update(problem=problem, budget=budget, **kwargs)
        raise OptimizeError("stand-in: nothing optimised")

    monkeypatch.setattr(nsga, "optimize", stand_in)

    def run(*args: str) -> dict:
        result = runner.invoke(app, ["optimize", "--budget", "6", "--out", str(tmp_path / "o"), *args])
        assert result.exit_code == 2 and "stand-in: nothing optimised" in result.output, result.output
        return seen

    return run


def test_the_options_reach_the_search(handed_over) -> None:
    """--objective actuator_force and safety_factor (a force minimised, a safety factor
    maximised), --ignore-check drops that check from the constraints, --pop-size and --seed
    are the search's, --ply-thickness-mm 0.125 is 1.25e-4 m (the wall then follows the ply
    count of the --layup template)."""
    seen = handed_over(
        "--objective",
        "actuator_force",
        "--objective",
        "safety_factor",
        "--ignore-check",
        "actuator_force",
        "--pop-size",
        "6",
        "--seed",
        "7",
        "--ply-thickness-mm",
        "0.125",
        "--layup",
        "({a}/{-a}/0_{n})s",
        "--var",
        "layup.a=30:70",
        "--var",
        "layup.n=4:12:int",
    )
    problem = seen["problem"]
    assert [(o.output, o.sense) for o in problem.objectives] == [("actuator_force", "min"), ("safety_factor", "max")]
    constraints = {c.removeprefix("margin_") for c in problem.constraints}
    assert "actuator_force" not in constraints and "tsai_wu" in constraints, constraints
    assert (seen["budget"], seen["pop_size"], seen["seed"]) == (6, 6, 7)
    assert problem.ply_thickness == pytest.approx(0.125e-3, rel=1e-12)  # 0.125 mm = 1.25e-4 m


class _Result:
    """A finished search as _report reads it: one Pareto design, no reference."""

    def __init__(self, spinup_deflection: float) -> None:
        self.pareto = xr.Dataset(
            {
                "file": ("design", np.array(["pareto_001.toml"])),
                "driveline_mass": ("design", [11.0]),
                "shaft_mass": ("design", [4.0]),
                "min_margin": ("design", [0.25]),
                "safety_factor": ("design", [2.5]),
                "buckling_safety_factor": ("design", [3.5]),
                "actuator_force": ("design", [120.0]),
                "spinup_deflection": ("design", [spinup_deflection]),
            }
        )
        self.references: dict = {}
        self.n_computed, self.elapsed = 6, 1.0
        self.verified_with: list = []

    def save(self, out):
        return {"evaluations": out / "e.nc", "pareto": out / "p.nc", "blocking": out / "b.json"}

    def plot(self):
        return None

    def write_designs(self, folder, most):
        return [folder / "pareto_001.toml"]

    def verify(self, files, **kwargs):
        self.verified_with.append(files)
        raise AssertionError("verified although --no-verify")


def test_the_table_shows_the_orbit_in_mm_and_no_verify_runs_nothing(monkeypatch, tmp_path: Path, capsys) -> None:
    """The Pareto table's 'orbit [mm]' column: a spin-up orbit of 4.2e-4 m is 0.42 mm. With
    --no-verify (verify=False) no written design is re-run."""
    import flexshaft.plot.driveline as driveline

    monkeypatch.setattr(driveline, "save_figure", lambda figure, out, name: {"png": out / f"{name}.png"})
    result = _Result(spinup_deflection=4.2e-4)
    command._report(result, tmp_path, 8, False, 1, None, False)
    assert result.verified_with == []
    row = next(line for line in capsys.readouterr().out.splitlines() if "pareto_001" in line)
    cells = [c.strip() for c in row.strip("│ ").split("│")]
    # design, driveline, shaft, smallest margin, limited by, strength SF, buckling SF, force, orbit, verdict
    assert float(cells[8]) == pytest.approx(0.42, rel=1e-6) and cells[9] == "PASS", cells
    assert float(cells[1]) == 11.0 and float(cells[7]) == 120.0 and not math.isnan(float(cells[3]))
