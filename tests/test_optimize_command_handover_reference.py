"""``flexshaft optimize``: the fidelity and the reference designs the search is handed, and a
run folder of the user's own files left alone; the optimizer replaced by a stand-in (nothing is
optimised or assessed).

References: docs/optimizer.md — "Two fidelities (`--fidelity`), the presets ... `verdict`
(default) ... `screening`"; the run folder "(`--out` ...; a folder of other files is refused
without `--force`)"; the references: "the Pareto-front figure, base and references marked", and
in the API ``references={"tuned": tuned_design()}`` (a name to a design); the CLI's
``--reference`` takes an "embedded name or file" (the option's help text, the CLI's code
contract). The reference file is written here: the embedded tuned design with its wall changed
by hand from 3.75 mm to 4.2 mm (a value no embedded design has), so the design the
search receives under the file's name must carry 4.2 mm (exact: the decimal read from the
file, no arithmetic). CPU: a design load and the command's checks (< 1 s).
"""

from __future__ import annotations

import importlib
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.design import embedded_text
from flexshaft.optimize.variables import OptimizeError

runner = CliRunner()


@pytest.fixture
def seen(monkeypatch) -> dict:
    """The stand-in optimizer records the problem and options it is handed, then refuses."""
    nsga = importlib.import_module("flexshaft.optimize.nsga")
    record: dict = {}

    def stand_in(problem, budget, out, **kwargs):
        record.update(problem=problem, budget=budget, out=out, **kwargs)
        raise OptimizeError("stand-in: nothing optimised")

    monkeypatch.setattr(nsga, "optimize", stand_in)
    return record


def test_screening_fidelity_and_a_reference_file_reach_the_search(seen, tmp_path: Path) -> None:
    """``--fidelity screening`` is the problem's fidelity; ``--reference mine.toml`` arrives
    labelled ``mine`` with the file's 4.2 mm wall, not the base's 3.75 mm."""
    text = embedded_text("tuned")
    assert text.count("wall_thickness = 0.00375 ") == 1
    mine = tmp_path / "mine.toml"
    mine.write_text(text.replace("wall_thickness = 0.00375 ", "wall_thickness = 0.0042 "), encoding="utf-8")
    result = runner.invoke(
        app,
        ["optimize", "--budget", "6", "--out", str(tmp_path / "o"), "--fidelity", "screening"]
        + ["--reference", str(mine)],
    )
    assert result.exit_code == 2 and "stand-in: nothing optimised" in result.output, result.output
    assert seen["problem"].fidelity == "screening"
    assert set(seen["references"]) == {"mine"}
    assert seen["references"]["mine"].shaft.wall_thickness == 0.0042
    assert seen["problem"].base.shaft.wall_thickness == 0.00375


def test_a_folder_of_the_users_files_is_refused_without_force(seen, tmp_path: Path) -> None:
    """``--out`` naming a folder that holds a file flexshaft did not write: exit 2 before any
    search, the file unchanged and nothing added to the folder."""
    folder = tmp_path / "notes"
    folder.mkdir()
    (folder / "notes.txt").write_text("my notes\n", encoding="utf-8")
    result = runner.invoke(app, ["optimize", "--budget", "6", "--out", str(folder)])
    assert result.exit_code == 2, result.output
    assert "--force" in result.output
    assert seen == {}  # the search was never started
    assert sorted(p.name for p in folder.iterdir()) == ["notes.txt"]
    assert (folder / "notes.txt").read_text(encoding="utf-8") == "my notes\n"
