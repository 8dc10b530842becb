"""The output-folder rules of ``--out`` against the README, on folders built by hand.

Reference: README.md, "Output folders (``--out``)":

    ``flexshaft run my.toml`` writes ``my-results/`` (``flexshaft-results/`` for the embedded
    design; ``my-runup/``, ``my-study-wall/``, ... for the other commands). Edit ``my.toml`` and
    run it again: its folder is replaced, no ``--force`` needed (the files the earlier run wrote
    are removed first, your own files in the folder are kept, but not symbolic links: every
    link inside the folder, and inside the subfolders flexshaft wrote, is removed, never
    followed, before anything is written, so that no write can land outside the folder; your
    own subfolders are not entered). [...] a non-empty folder that
    flexshaft did not write, or one it wrote for another command or another design (another
    file with other values; the message names both designs by title, file and fingerprint) is
    refused (exit 2) unless ``--force`` is given. [...] a symbolic link inside the folder is
    replaced, never followed. flexshaft marks its folders with ``.flexshaft-output.json``
    (command, design name, fingerprint and file), written last: ``"complete": false`` until
    every file is written.

and the module docstring of :mod:`flexshaft.cli.output` (the same design is the same values
*or* the same design file; a marker of an earlier flexshaft without its list of entries:
nothing is removed). Every folder here is made by the test: the user's files, a planted link,
a marker of another command or file. The command is a stand-in (:func:`_command`) wrapped by
the CLI's real error boundary, so the final marker is written the way every command writes it
and no analysis runs; the designs are stand-ins with a title and a few values (the fingerprint
is the product's hash of those values, only ever compared, never checked as a number).
Whole file: about 0.06 s of CPU (``--cpu-durations``; no analysis, no pydantic model).
"""

from __future__ import annotations

import errno
import json
from pathlib import Path

import click
import pytest
import typer

from flexshaft.cli.common import guarded
from flexshaft.cli.output import MARKER, default_output_folder, prepare_output_folder

#: README: "Every refusal is a user error (exit code 2)" / "2 a user error (bad design file,
#: argument or output folder)".
USER_ERROR = 2


class _Design:
    """A validated design as the folder rules see it: a title and its values."""

    def __init__(self, name: str, wall: float) -> None:
        self.name = name
        self._values = {"name": name, "shaft": {"wall_thickness": wall}}

    def model_dump(self, mode: str = "json") -> dict:
        return self._values


MINE = _Design("My design", 0.003)
EDITED = _Design("My design", 0.0035)  # the same file after an edit of its wall
TWIN = _Design("My design", 0.004)  # another file with the same title and other values


@guarded
def _command(folder: Path, design: _Design, source: str, force: bool = False, writes=(), error=None) -> None:
    """A command that writes ``writes`` into its folder, then raises ``error`` if given."""
    prepare_output_folder(folder, design, "run", force=force, source=source)
    for name in writes:
        (folder / name).write_text(f"{design.name} {design.model_dump()}", encoding="utf-8")
    if error is not None:
        raise error


def _run(*args, **kwargs) -> int:
    """The exit code of the stand-in command (0 when it returned)."""
    try:
        _command(*args, **kwargs)
    except (typer.Exit, click.exceptions.Exit) as exit_:
        return exit_.exit_code
    return 0


def _marker(folder: Path) -> dict:
    return json.loads((folder / MARKER).read_text(encoding="utf-8"))


def _names(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


@pytest.fixture()
def files(tmp_path: Path) -> dict:
    return {"out": tmp_path / "my-results", "a": str(tmp_path / "my.toml"), "b": str(tmp_path / "other.toml")}


def test_the_default_folder_is_named_after_the_design_file() -> None:
    assert default_output_folder(Path("my.toml"), "results") == Path("my-results")
    assert default_output_folder(None, "results") == Path("flexshaft-results")
    assert default_output_folder(Path("my.toml"), "runup") == Path("my-runup")
    assert default_output_folder(Path("my.toml"), "study-wall") == Path("my-study-wall")


def test_a_folder_of_the_users_files_is_refused_unless_force(files: dict, capsys) -> None:
    out = files["out"]
    out.mkdir()
    (out / "thesis.docx").write_text("mine")
    (out / ".tmp-draft").write_text("mine too")  # a user's file that looks like a temporary
    assert _run(out, MINE, files["a"]) == USER_ERROR
    err = capsys.readouterr().err
    assert str(out) in err and "--force" in err and "Traceback" not in err
    assert _names(out) == [".tmp-draft", "thesis.docx"]  # nothing written, nothing removed
    assert _run(out, MINE, files["a"], force=True, writes=["results.json"]) == 0
    assert (out / "thesis.docx").read_text() == "mine" and (out / ".tmp-draft").read_text() == "mine too"
    marker = _marker(out)
    assert marker["complete"] is True and marker["entries"] == ["results.json"]  # the user's files are not its


def test_a_users_file_at_out_is_refused(tmp_path: Path, capsys) -> None:
    target = tmp_path / "notes.txt"
    target.write_text("keep")
    assert _run(target, MINE, str(tmp_path / "my.toml")) == USER_ERROR
    assert "is a file" in capsys.readouterr().err and target.read_text() == "keep"
    empty = tmp_path / "empty"
    empty.mkdir()
    assert _run(empty, MINE, str(tmp_path / "my.toml"), writes=["results.json"]) == 0  # an empty folder is fine


def test_a_link_at_out_is_refused_saying_what_it_points_to(tmp_path: Path, capsys) -> None:
    """A symbolic link to the user's file at ``--out`` is refused and the file kept (README: "The
    folder is checked before anything is computed: a file, ... is refused (exit 2)"; "no write
    can land outside the folder"); the message says the link points to a file (it used to say
    "a missing target" for a link to an existing file), and a dangling link is a link to a
    missing target, whose target is not created."""
    target = tmp_path / "notes.txt"
    target.write_text("keep")
    link, dangling = tmp_path / "link", tmp_path / "dangling"
    link.symlink_to(target)
    dangling.symlink_to(tmp_path / "nowhere")
    assert _run(link, MINE, str(tmp_path / "my.toml")) == USER_ERROR
    assert "symbolic link to a file, not a folder" in capsys.readouterr().err and target.read_text() == "keep"
    assert _run(dangling, MINE, str(tmp_path / "my.toml")) == USER_ERROR
    assert "symbolic link to a missing target" in capsys.readouterr().err and not (tmp_path / "nowhere").exists()


def test_a_folder_of_another_command_is_refused(files: dict, capsys) -> None:
    out = files["out"]
    out.mkdir()
    (out / "results.nc").write_text("a study's results")
    marker = {"written_by": "flexshaft", "command": "study wall", "design": MINE.name, "entries": ["results.nc"]}
    marker.update(design_source=files["a"], complete=True)
    (out / MARKER).write_text(json.dumps(marker), encoding="utf-8")
    assert _run(out, MINE, files["a"]) == USER_ERROR
    assert "flexshaft study wall" in capsys.readouterr().err
    assert (out / "results.nc").read_text() == "a study's results"


def test_a_rerun_of_the_same_design_keeps_its_results(files: dict) -> None:
    out, a = files["out"], files["a"]
    assert _run(out, MINE, a, writes=["results.json", "report.html"]) == 0
    (out / "notes.txt").write_text("mine")
    assert _run(out, MINE, a) == 0  # same file, same values: nothing to replace
    assert _names(out) == sorted([MARKER, "notes.txt", "report.html", "results.json"])
    assert _marker(out)["entries"] == ["report.html", "results.json"]


def test_the_same_values_from_another_file_are_the_same_design(files: dict) -> None:
    out = files["out"]
    assert _run(out, MINE, files["a"], writes=["results.json"]) == 0
    assert _run(out, MINE, files["b"]) == 0  # a copy of my.toml: same values, accepted and kept
    assert (out / "results.json").is_file()


def test_an_edited_design_file_replaces_its_own_results_and_keeps_the_users(files: dict) -> None:
    out, a = files["out"], files["a"]
    assert _run(out, MINE, a, writes=["results.json", "report.html"]) == 0
    (out / "notes.txt").write_text("mine")
    assert _run(out, EDITED, a, writes=["results.json"]) == 0  # no --force needed
    assert _names(out) == sorted([MARKER, "notes.txt", "results.json"])
    assert "0.0035" in (out / "results.json").read_text()  # the old report.html is gone, not lingering
    assert (out / "notes.txt").read_text() == "mine"
    assert _marker(out)["entries"] == ["results.json"]


def test_another_design_with_the_same_title_is_refused_and_force_replaces_its_results(files: dict, capsys) -> None:
    out, a, b = files["out"], files["a"], files["b"]
    assert _run(out, MINE, a, writes=["results.json", "report.html"]) == 0
    (out / "notes.txt").write_text("mine")
    capsys.readouterr()
    assert _run(out, TWIN, b) == USER_ERROR
    err = capsys.readouterr().err
    assert f"from {a}" in err and f"from {b}" in err and "--force" in err  # both files named
    assert _names(out) == sorted([MARKER, "notes.txt", "report.html", "results.json"])
    assert _run(out, TWIN, b, force=True, writes=["results.json"]) == 0
    assert _names(out) == sorted([MARKER, "notes.txt", "results.json"])  # the other design's report gone
    assert "0.004" in (out / "results.json").read_text() and (out / "notes.txt").read_text() == "mine"


def test_a_marker_of_an_earlier_flexshaft_removes_nothing_on_force(files: dict) -> None:
    """A marker without ``entries`` and ``design_source``: the files cannot be told apart from
    the user's, so another design written with --force removes none of them."""
    out = files["out"]
    out.mkdir()
    (out / "results.json").write_text("old")
    (out / "notes.txt").write_text("mine")
    legacy = {"written_by": "flexshaft", "command": "run", "design": TWIN.name, "design_fingerprint": "0" * 64}
    (out / MARKER).write_text(json.dumps(legacy), encoding="utf-8")
    assert _run(out, MINE, files["a"]) == USER_ERROR
    assert _run(out, MINE, files["a"], force=True) == 0
    assert (out / "notes.txt").read_text() == "mine" and (out / "results.json").read_text() == "old"


def test_links_in_the_folder_are_removed_never_followed(files: dict, tmp_path: Path) -> None:
    out, a = files["out"], files["a"]
    assert _run(out, MINE, a, writes=["results.json"]) == 0
    victim_file, victim_folder = tmp_path / "victim.txt", tmp_path / "victim-folder"
    victim_file.write_text("keep")
    victim_folder.mkdir()
    (victim_folder / "thesis.docx").write_text("keep")
    (out / "results.json").unlink()
    (out / "results.json").symlink_to(victim_file)
    (out / "studies").symlink_to(victim_folder, target_is_directory=True)
    assert _run(out, MINE, a) == 0
    assert not (out / "results.json").is_symlink() and not (out / "studies").exists()
    assert victim_file.read_text() == "keep" and _names(victim_folder) == ["thesis.docx"]


def test_force_into_a_project_folder_keeps_the_links_of_its_subfolders(files: dict, tmp_path: Path) -> None:
    """Was: `flexshaft runup --out . --force` in a project folder deleted every symbolic link of
    the whole tree, a virtual environment's `.venv/bin/python` included. README: "every link
    inside the folder, and inside the subfolders flexshaft wrote, is removed ...; your own
    subfolders are not entered" (writes are atomic renames, which replace a file link)."""
    out, a = files["out"], files["a"]
    victim = tmp_path / "victim.txt"
    victim.write_text("keep")
    (out / ".venv" / "bin").mkdir(parents=True)
    (out / ".venv" / "bin" / "python").symlink_to(victim)
    (out / "top-link").symlink_to(victim)
    assert _run(out, MINE, a, force=True, writes=["results.json"]) == 0
    assert (out / ".venv" / "bin" / "python").is_symlink() and not (out / "top-link").is_symlink()
    # a subfolder an earlier run wrote (listed in the marker) is flexshaft's: its links go
    (out / "studies").mkdir()
    marker = _marker(out)
    (out / MARKER).write_text(json.dumps({**marker, "entries": [*marker["entries"], "studies"]}), encoding="utf-8")
    (out / "studies" / "planted").symlink_to(victim)
    assert _run(out, MINE, a) == 0
    assert not (out / "studies" / "planted").is_symlink() and victim.read_text() == "keep"
    assert (out / ".venv" / "bin" / "python").is_symlink()


def test_a_linked_marker_does_not_make_a_folder_flexshafts(files: dict, tmp_path: Path) -> None:
    ours = tmp_path / "ours"
    assert _run(ours, MINE, files["a"]) == 0
    foreign = files["out"]
    foreign.mkdir()
    (foreign / "thesis.docx").write_text("mine")
    (foreign / MARKER).symlink_to(ours / MARKER)
    assert _run(foreign, MINE, files["a"]) == USER_ERROR
    assert (foreign / "thesis.docx").read_text() == "mine"


def test_the_marker_says_incomplete_until_the_command_has_written_everything(files: dict) -> None:
    out, a = files["out"], files["a"]
    seen = {}

    @guarded
    def watching() -> None:
        prepare_output_folder(out, MINE, "run", source=a)
        seen["before"] = _marker(out)["complete"]
        (out / "results.json").write_text("{}")
        seen["during"] = _marker(out)["complete"]

    watching()
    assert seen == {"before": False, "during": False} and _marker(out)["complete"] is True
    # a command that fails after writing part of its results: the marker still says incomplete
    full_disk = OSError(errno.ENOSPC, "No space left on device")
    assert _run(out, EDITED, a, writes=["results.json"], error=full_disk) == USER_ERROR
    assert _marker(out)["complete"] is False
