"""Which Pareto design each written design file holds, and its re-verification, by hand.

References (quoted: the rules of docs/optimizer.md, hand-written, and two docstrings, each
labelled "docstring, API contract in the code"):

* ``OptimizationResult.write_designs`` (docstring, API contract in the code; docs/optimizer.md
  says only "spread along it, ends included", quoted below): "Write Pareto designs as design
  files ``pareto_NN.toml`` (all of them, or ``max_designs`` spread evenly along the front, its
  ends included)"; "the Pareto dataset gets their names (``file``)". Five designs, three
  allowed: the evenly spread positions 0, (5 − 1)/2 = 2 and 4 (exact, no rounding), written
  as pareto_01, _02, _03; the other two rows name no file.
* docs/optimizer.md, the run folder: "designs/pareto_NN.toml  design files of the front (at most
  --designs, spread along it, ends included)", and "run the same command again on the folder":
  after a rerun on the same folder that writes two designs, the folder holds those two files
  and no file of the earlier, longer front.
* ``OptimizationResult.verify`` (docstring, API contract in the code): "the Pareto dataset gets
  ``verified`` (1 pass, 0 fail, −1 not written)"; docs/optimizer.md: pareto.nc holds "the
  feasible non-dominated designs (+ file, verified)". The full run itself (``flexshaft run``'s
  assessment, tens of seconds a design) is replaced here by a stand-in that returns a chosen
  verdict per file, so the test checks only that each verdict lands on the design whose file
  it is.

Each design is told apart by its wall thickness (a design path the file keeps exactly: the
writer prints floats with their shortest round-trip repr, so equality is exact). No physics
runs; about 0.3 s of CPU (pydantic validation of a few designs, xarray's first use).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import xarray as xr

from flexshaft.design import load_design
from flexshaft.optimize import DesignProblem, DesignVariable
from flexshaft.optimize import result as result_module
from flexshaft.optimize.result import OptimizationResult
from flexshaft.optimize.variables import Objective

WALLS = [0.002, 0.0024, 0.0028, 0.0032, 0.0036]


def _unused(point):  # the search never runs here
    raise AssertionError("no evaluation expected")


def _front(walls) -> OptimizationResult:
    """A Pareto set of walls from the Table 3.1 baseline (the default base), sorted by mass."""
    problem = DesignProblem(
        (DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall", units="m"),),
        objectives=(Objective("mass", "min", "mass"),),
        constraints=(),
        evaluate=_unused,
        outputs=(("mass", "kg", "1000 w"),),
    )
    pareto = xr.Dataset(
        {
            "mass": ("design", [1e3 * w for w in walls]),
            "overrides": ("design", [json.dumps({"shaft.wall_thickness": w}) for w in walls]),
        }
    )
    return OptimizationResult(problem, evaluations=None, pareto=pareto)


def test_each_file_column_entry_names_the_file_of_its_own_design(tmp_path):
    """Three of five written: rows 0, 2, 4 name pareto_01, _02, _03, and the file each row
    names loads back with THAT row's wall; rows 1 and 3 name none."""
    result = _front(WALLS)
    paths = result.write_designs(tmp_path, max_designs=3)
    assert [p.name for p in paths] == ["pareto_01.toml", "pareto_02.toml", "pareto_03.toml"]
    files = result.pareto["file"].values.tolist()
    assert files == ["pareto_01.toml", "", "pareto_02.toml", "", "pareto_03.toml"]
    for wall, name in zip(WALLS, files):
        if name:
            assert load_design(tmp_path / name).shaft.wall_thickness == wall


def test_a_rerun_on_the_same_folder_leaves_only_its_own_files(tmp_path):
    """Five written, then a two-design front written to the same folder: only pareto_01 and
    pareto_02 remain, holding the new front's walls."""
    _front(WALLS).write_designs(tmp_path, max_designs=8)
    assert len(list(tmp_path.glob("pareto_*.toml"))) == 5
    _front([0.0022, 0.003]).write_designs(tmp_path, max_designs=8)
    assert sorted(p.name for p in tmp_path.glob("pareto_*.toml")) == ["pareto_01.toml", "pareto_02.toml"]
    assert load_design(tmp_path / "pareto_02.toml").shaft.wall_thickness == 0.003


def test_each_verdict_lands_on_its_design_and_unwritten_ones_read_minus_one(tmp_path, monkeypatch):
    """The stand-in full run passes pareto_01 and pareto_03 and fails pareto_02 (given in the
    reverse of the written order, so the match must be by file name): verified is
    [1, −1, 0, −1, 1] over the five designs (rows 1 and 3 not written)."""
    verdicts = {"pareto_01.toml": 1, "pareto_02.toml": 0, "pareto_03.toml": 1}

    def full_run(paths, *, jobs=1, client=None):
        files = [str(Path(p).resolve()) for p in reversed(list(paths))]
        passed = np.array([verdicts[Path(f).name] for f in files], dtype=np.int8)
        return xr.Dataset({"passed": ("design_file", passed)}, coords={"design_file": files})

    monkeypatch.setattr(result_module, "verify_design_files", full_run)
    result = _front(WALLS)
    paths = result.write_designs(tmp_path, max_designs=3)
    result.verify(paths)
    assert result.pareto["verified"].values.tolist() == [1.0, -1.0, 0.0, -1.0, 1.0]
