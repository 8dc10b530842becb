"""An output folder's rerun removes a linked folder inside its own subfolders and the
temporary files a crash left.

References, quoted:

* README.md, "Output folders (``--out``)": "every link inside the folder, and inside the
  subfolders flexshaft wrote, is removed, never followed, before anything is written, so that
  no write can land outside the folder"; "Files are written under a temporary name and renamed
  into place, so a crash or a full disk never leaves half a file"; "The temporary files
  (``.tmp-*``) a crash left directly in a folder flexshaft wrote are removed on the next run
  into it."
* :mod:`flexshaft.cli.output`'s docstring: the folder check "removes every symbolic link
  inside the folder and inside the subfolders an earlier run wrote [...] and removes the
  temporary files a crash left"; at the end the marker records "``"complete": true`` and the
  entries the command wrote".

Folders are built by hand (a planted link to a folder, a half-written ``.tmp-`` file); the
command is a stand-in wrapped by the CLI's real error boundary (as in
``tests/test_output_folder_reference.py``), so no analysis runs: about 0.05 s of CPU.
"""

from __future__ import annotations

import json
from pathlib import Path

import click
import typer

# a validated design as the folder rules see it (a title and its values)
from test_output_folder_reference import MINE

from flexshaft.cli.common import guarded
from flexshaft.cli.output import MARKER, prepare_output_folder


@guarded
def _command(folder: Path, source: str, writes=()) -> None:
    """A command that writes the files ``writes`` (paths relative to its folder)."""
    prepare_output_folder(folder, MINE, "run", source=source)
    for name in writes:
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_text("results", encoding="utf-8")


def _run(*args, **kwargs) -> int:
    try:
        _command(*args, **kwargs)
    except (typer.Exit, click.exceptions.Exit) as exit_:
        return exit_.exit_code
    return 0


def test_a_linked_folder_inside_a_subfolder_flexshaft_wrote_is_removed(tmp_path: Path) -> None:
    """``studies/`` is flexshaft's (listed in the marker); a link ``studies/wall -> victim/``
    planted in it is removed, not followed: the next run writes ``studies/wall/results.nc``
    inside the output folder and the victim folder keeps exactly its own file."""
    out, source = tmp_path / "my-results", str(tmp_path / "my.toml")
    assert _run(out, source, writes=["results.json", "studies/summary.json"]) == 0
    assert json.loads((out / MARKER).read_text())["entries"] == ["results.json", "studies"]
    victim = tmp_path / "victim"
    victim.mkdir()
    (victim / "thesis.docx").write_text("keep")
    (out / "studies" / "wall").symlink_to(victim, target_is_directory=True)
    assert _run(out, source, writes=["studies/wall/results.nc"]) == 0
    assert not (out / "studies" / "wall").is_symlink()
    assert (out / "studies" / "wall" / "results.nc").read_text() == "results"
    assert sorted(p.name for p in victim.iterdir()) == ["thesis.docx"]
    assert (victim / "thesis.docx").read_text() == "keep"


def test_a_temporary_file_a_crash_left_is_removed_on_the_next_run(tmp_path: Path) -> None:
    """A ``.tmp-*`` file directly in flexshaft's own folder is half a file of a write that
    never finished: the next run of the same design removes it (README), keeps the results and
    the user's own file, and the marker lists only the entries the command wrote."""
    out, source = tmp_path / "my-results", str(tmp_path / "my.toml")
    assert _run(out, source, writes=["results.json"]) == 0
    (out / ".tmp-k2j4x9.json").write_bytes(b'{"half": ')  # a killed atomic write
    (out / "notes.txt").write_text("mine")
    assert _run(out, source) == 0
    assert sorted(p.name for p in out.iterdir()) == [MARKER, "notes.txt", "results.json"]
    marker = json.loads((out / MARKER).read_text())
    assert marker["complete"] is True and marker["entries"] == ["results.json"]
