"""Output folders (issue 12.6): checked before computing, marked, reproducible.

* ``--out`` on a file, below a file, or on a folder that cannot be written is a user error
  (exit 2, the folder named), for ``run`` and the study commands alike, before any computation.
* A non-empty folder that flexshaft did not write, or that it wrote for another design or
  another command, is refused unless ``--force``; a folder written for the same design by the
  same command is updated.
* ``results.json`` holds no timestamp and no timing (those go to ``timings.json``): two runs
  of one design write byte-identical files.

``run`` is exercised once here (about 3 s of CPU, mostly the report's figures) on a small design
at one envelope point that skips the thesis-shaft comparison and the design studies: the
session's run (tests/conftest.py's ``small_run``, shared with tests/test_output_guard.py and
tests/test_run.py); the tests that write into its folder work on a copy of it. The second run
of the same design into its own folder (updated, results.json byte-identical, the markup of the
actuators' names printed literally) is tests/test_output_guard.py's rerun into a copy where
links were planted (one run for both: test_a_link_planted_in_ones_own_run_folder_is_replaced).
The other cases stop before computing, or use ``study ply-angle`` with two angles.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest
from conftest import RUN_DESIGN
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.cli.output import MARKER
from flexshaft.design import baseline_text

runner = CliRunner()

SMALL = (
    baseline_text()
    .replace("shaft_elements = 36", "shaft_elements = 4", 1)
    .replace("boom_elements = 24", "boom_elements = 2", 1)
)
OTHER_DESIGN = SMALL.replace('name = "Thesis Table 3.1', 'name = "Another design', 1)


@pytest.fixture(scope="module")
def first_run(small_run: dict) -> dict:
    """The session's ``run --studies none --json`` of RUN_DESIGN (tests/conftest.py): read only;
    a test that runs into its folder copies it first (:func:`own_copy`)."""
    return small_run


def own_copy(run: dict, tmp_path: Path) -> Path:
    """A copy of the run's output folder (its marker still names the run's design file)."""
    out = tmp_path / "results"
    shutil.copytree(run["out"], out, symlinks=True)
    return out


def test_run_writes_results_timings_and_marker_separately(first_run: dict) -> None:
    out = first_run["out"]
    assert first_run["stderr"] == ""  # no progress display when stderr is not a terminal
    assert json.loads(first_run["stdout"])["design"].startswith("Thesis Table 3.1")
    results = first_run["results"].decode()
    seconds = results.replace('_rad_s"', "")  # a speed or frequency key's unit is rad/s, not seconds
    for word in ("timing", "elapsed", "generated", '_s"', "seconds"):
        assert word not in seconds, word
    assert "NaN" not in results and "Infinity" not in results  # strict JSON
    timings = json.loads((out / "timings.json").read_text())
    # each envelope point's steps carry its name (the design keeps one point: hot_soak_start)
    assert RUN_DESIGN.count("[[envelope.points]]") == 1
    assert "hot_soak_start: assembling the model" in timings["stages_s"]
    stages = {label.split(": ", 1)[-1] for label in timings["stages_s"]}
    assert {"assembling the model", "natural frequencies", "requirements verdict"} <= stages
    assert all(seconds >= 0.0 for seconds in timings["stages_s"].values())
    marker = json.loads((out / MARKER).read_text())
    assert marker["written_by"] == "flexshaft" and marker["command"] == "run"
    assert len(marker["design_fingerprint"]) == 64


def test_a_folder_of_another_design_is_refused_without_force(first_run: dict, tmp_path: Path) -> None:
    other = tmp_path / "other.toml"
    other.write_text(OTHER_DESIGN, encoding="utf-8")
    result = runner.invoke(app, ["run", str(other), "--out", str(own_copy(first_run, tmp_path))])
    assert result.exit_code == 2
    assert "holds the results of another design" in result.stderr and "--force" in result.stderr
    assert "Traceback" not in result.output


def test_a_folder_of_another_command_is_refused(first_run: dict, tmp_path: Path) -> None:
    out = own_copy(first_run, tmp_path)
    result = runner.invoke(app, ["study", "ply-angle", str(first_run["design"]), "--step", "30", "--out", str(out)])
    assert result.exit_code == 2
    assert "holds the output of 'flexshaft run', not of 'flexshaft study ply-angle'" in result.stderr


# ------------------------------------------------------------------------------------------------
# refusals before any computation


@pytest.fixture()
def no_computation(monkeypatch):
    """Make any analysis an internal fault (exit 4), so exit 2 proves the refusal came first."""
    import flexshaft.thesis.design_studies as chapter3
    import flexshaft.thesis.ply_angle as ply_angle
    import flexshaft.thesis.wall as wall
    import flexshaft.verdict.assess as run_module

    def forbidden(*args, **kwargs):
        raise AssertionError("computed before checking --out")

    for module, name in (
        (run_module, "assess"),
        (ply_angle, "ply_angle_study"),
        (wall, "wall_thickness_study"),
        (chapter3, "design_studies"),
    ):
        monkeypatch.setattr(module, name, forbidden)


COMMANDS = [["run"], ["study", "ply-angle"], ["study", "wall"], ["study", "all"]]


@pytest.mark.parametrize("command", COMMANDS, ids=" ".join)
def test_out_on_a_file_is_a_user_error(command, tmp_path: Path, no_computation) -> None:
    target = tmp_path / "a_file"
    target.write_text("keep me")
    for out, message in ((target, "is a file, not a folder"), (target / "sub", "a part of the path is a file")):
        result = runner.invoke(app, [*command, "--out", str(out)])
        assert result.exit_code == 2, result.output
        assert message in result.stderr and str(target) in result.stderr
        assert "Traceback" not in result.output
    assert target.read_text() == "keep me"


@pytest.mark.parametrize("command", COMMANDS, ids=" ".join)
def test_a_non_empty_foreign_folder_is_refused(command, tmp_path: Path, no_computation) -> None:
    (tmp_path / "thesis.docx").write_text("not flexshaft's")
    result = runner.invoke(app, [*command, "--out", str(tmp_path)])
    assert result.exit_code == 2, result.output
    assert "is not empty and was not written by flexshaft" in result.stderr and "--force" in result.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["thesis.docx"]


def test_force_writes_into_a_foreign_folder_and_another_designs_folder(tmp_path: Path) -> None:
    design, other = tmp_path / "small.toml", tmp_path / "other.toml"
    design.write_text(SMALL, encoding="utf-8")
    other.write_text(OTHER_DESIGN, encoding="utf-8")
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    study = ["study", "ply-angle", "--step", "30", "--out", str(out)]
    assert runner.invoke(app, [*study, str(design)]).exit_code == 2
    forced = runner.invoke(app, [*study, str(design), "--force"])
    assert forced.exit_code == 0, forced.output
    assert (out / "notes.txt").read_text() == "mine" and (out / "results.nc").is_file()
    again = runner.invoke(app, [*study, str(design)])  # same design, same command: resumed in place
    assert again.exit_code == 0, again.output
    refused = runner.invoke(app, [*study, str(other)])
    assert refused.exit_code == 2
    # the two designs told apart by title, file and fingerprint
    assert (
        "another design: 'Thesis Table 3.1 configuration: one-piece" in refused.stderr
        and f"(from {design.resolve()}, fingerprint " in refused.stderr
        and "not 'Another design" in refused.stderr
        and f"(from {other.resolve()}, fingerprint " in refused.stderr
    )


@pytest.fixture()
def read_only_folder(tmp_path: Path):
    """An empty folder nobody may write into: mode 555, and for root (who ignores modes) also
    the immutable attribute (``chattr +i``; skipped where it cannot be set)."""
    import shutil

    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o555)
    immutable = False
    if os.geteuid() == 0:
        chattr = shutil.which("chattr")
        if chattr is None or subprocess.run([chattr, "+i", str(locked)], capture_output=True).returncode != 0:
            locked.chmod(0o755)
            pytest.skip("running as root and the immutable attribute cannot be set here")
        immutable = True
    try:
        probe = locked / "probe"
        with pytest.raises(PermissionError):
            probe.write_text("x")
        yield locked
    finally:
        if immutable:
            subprocess.run([shutil.which("chattr"), "-i", str(locked)], check=True)
        locked.chmod(0o755)


@pytest.mark.parametrize("command", [["run"], ["study", "wall"], ["study", "all"]], ids=" ".join)
@pytest.mark.parametrize("inside", [False, True], ids=["folder", "new subfolder"])
def test_a_read_only_folder_is_a_user_error(command, inside, read_only_folder: Path, no_computation) -> None:
    result = runner.invoke(app, [*command, "--out", str(read_only_folder / "new" if inside else read_only_folder)])
    assert result.exit_code == 2, result.output
    expected = "cannot create the folder" if inside else "is not writable (permission denied)"
    assert expected in result.stderr and str(read_only_folder) in result.stderr
    assert "Traceback" not in result.output
    assert list(read_only_folder.iterdir()) == []
