"""Edit and rerun (issue 28, point 1): each design file has its own results folder, and a rerun
of the same file replaces its own earlier results, also after the file was edited.

The bar of the issue: from a fresh folder, the README's quick start (``flexshaft run``, the
embedded design into ``flexshaft-results/``), then ``flexshaft baseline > my.toml && flexshaft
run my.toml``, an edit, and ``flexshaft run my.toml`` again: all exit 0 without ``--force``.
It runs in tests/test_run.py (``test_the_readme_loop_runs_without_force``), marked slow: it
goes on from that module's quick start (a subprocess, as a user types it), the full run whose
report the module checks (one run of the embedded design, not two), then, in the test process,
two full runs of the baseline at its envelope points, the first as the README types it (with
the thesis studies), the rerun without them, about 9 s of CPU: the rerun of ``run``
after an edit, whose folder then holds the edited design's results (a 0.0035 m wall weighs 7/6
of the 0.003 m one, within 3 %) and no longer the first run's ``studies/``. The fast tests
below check the same rules for the study commands on a coarse mesh, that another design's
folder is still refused with a message that tells the two designs apart, and that a rerun
removes the files and folders of the earlier run and keeps the user's, on the folder rules
themselves.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.cli.output import MARKER, default_output_folder
from flexshaft.design import baseline_text

runner = CliRunner()

#: The baseline on a coarse mesh, judged at its nominal point (without its envelope's points:
#: what these tests check does not depend on them, and each point is a whole assessment).
SMALL = re.sub(
    r"\[\[envelope\.points\]\].*?(?=\n# -+\n\[mesh\])",
    "",
    baseline_text()
    .replace("shaft_elements = 36", "shaft_elements = 6", 1)
    .replace("boom_elements = 24", "boom_elements = 4", 1),
    flags=re.S,
)
WALL = re.compile(r"^wall_thickness = [0-9.e-]+", re.M)


def _edit_wall(path: Path, wall: float) -> None:
    text = path.read_text(encoding="utf-8")
    assert WALL.search(text), "the design file has a shaft wall_thickness line"
    path.write_text(WALL.sub(f"wall_thickness = {wall}", text, count=1), encoding="utf-8")


def test_the_default_folder_follows_the_design() -> None:
    assert default_output_folder(None, "results") == Path("flexshaft-results")
    assert default_output_folder(Path("designs/my.toml"), "results") == Path("my-results")
    assert default_output_folder(Path("b.toml"), "study-wall") == Path("b-study-wall")


def test_an_edited_design_replaces_its_own_results(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    design = tmp_path / "my.toml"
    design.write_text(SMALL, encoding="utf-8")
    first = runner.invoke(app, ["study", "ply-angle", "my.toml", "--step", "30"])
    assert first.exit_code == 0, first.output
    out = tmp_path / "my-study-ply-angle"
    (out / "notes.txt").write_text("mine")  # the user's own file in the folder is kept
    chunks = sorted(p.name for p in (out / "chunks").iterdir())
    old = (out / "results.nc").read_bytes()
    _edit_wall(design, 0.0035)
    second = runner.invoke(app, ["study", "ply-angle", "my.toml", "--step", "30"])
    assert second.exit_code == 0, second.output
    assert (out / "notes.txt").read_text() == "mine"
    assert (out / "results.nc").read_bytes() != old  # computed afresh for the edited design
    assert sorted(p.name for p in (out / "chunks").iterdir()) == chunks  # the old chunks were replaced
    marker = json.loads((out / MARKER).read_text())
    assert marker["complete"] is True and "notes.txt" not in marker["entries"]


def test_another_design_is_refused_and_told_apart(tmp_path: Path, monkeypatch) -> None:
    """Was: "another design ('My design…', not 'My design…')": the same title twice."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a.toml").write_text(SMALL, encoding="utf-8")
    (tmp_path / "b.toml").write_text(SMALL.replace("wall_thickness = 0.003", "wall_thickness = 0.0035", 1))
    assert runner.invoke(app, ["study", "ply-angle", "a.toml", "--step", "30", "-o", "shared"]).exit_code == 0
    refused = runner.invoke(app, ["study", "ply-angle", "b.toml", "--step", "30", "-o", "shared"])
    assert refused.exit_code == 2
    message = refused.stderr
    assert f"from {tmp_path / 'a.toml'}" in message and f"from {tmp_path / 'b.toml'}" in message
    fingerprints = re.findall(r"fingerprint ([0-9a-f]{12})", message)
    assert len(fingerprints) == 2 and fingerprints[0] != fingerprints[1]
    assert "--force" in message
    forced = runner.invoke(app, ["study", "ply-angle", "b.toml", "--step", "30", "-o", "shared", "--force"])
    assert forced.exit_code == 0, forced.output


def test_a_rerun_after_an_edit_removes_the_folders_the_earlier_run_wrote(tmp_path: Path) -> None:
    """The rerun of an edited design removes every entry its earlier run wrote, folders with
    their content (``flexshaft run``'s ``studies/``) as well as files, and keeps the user's own
    files. On the folder rules themselves (:func:`~flexshaft.cli.output.prepare_output_folder`
    and the marker it writes when the command ends), without computing the results; the
    README's loop end to end is tests/test_run.py's."""
    from flexshaft.cli import common
    from flexshaft.cli.output import prepare_output_folder
    from flexshaft.design import loads_design

    folder, source = tmp_path / "my-results", str(tmp_path / "my.toml")
    first, edited = loads_design(SMALL), loads_design(WALL.sub("wall_thickness = 0.0035", SMALL, count=1))
    mark = len(common._AT_END)
    prepare_output_folder(folder, first, "run", source=source)
    (folder / "studies" / "wall").mkdir(parents=True)
    (folder / "studies" / "wall" / "wall.nc").write_bytes(b"results of the first design")
    (folder / "report.html").write_text("first design", encoding="utf-8")
    common._end_command(mark, True)  # the first run ends: its marker lists what it wrote
    assert sorted(json.loads((folder / MARKER).read_text())["entries"]) == ["report.html", "studies"]
    (folder / "notes.txt").write_text("the user's own file", encoding="utf-8")
    mark = len(common._AT_END)
    prepare_output_folder(folder, edited, "run", source=source)
    common._end_command(mark, True)
    assert sorted(p.name for p in folder.iterdir()) == sorted([MARKER, "notes.txt"])
    # the same design again keeps its results (nothing to replace)
    (folder / "report.html").write_text("edited design", encoding="utf-8")
    mark = len(common._AT_END)
    prepare_output_folder(folder, edited, "run", source=source)
    common._end_command(mark, True)
    assert (folder / "report.html").read_text(encoding="utf-8") == "edited design"
