"""Whose results an output folder holds: another command's, another file of the same name.

References, quoted verbatim:

* README.md, "Output folders (``--out``)": "Edit ``my.toml`` and run it again: its folder is
  replaced, no ``--force`` needed (the files the earlier run wrote are removed first, your own
  files in the folder are kept [...]). The folder is checked before anything is computed: a
  file, a folder that cannot be created or written, a non-empty folder that flexshaft did not
  write, or one it wrote for another command or another design (another file with other
  values; the message names both designs by title, file and fingerprint) is refused (exit 2)
  unless ``--force`` is given."
* The module docstring of :mod:`flexshaft.cli.output`: "The same design is the same values
  (fingerprint) *or* the same design file (its resolved path): a rerun of an edited design file
  replaces its own earlier results", and of its ``command`` parameter: "(a folder is reused only
  by the same one)".

So (1) a design file is the same file by its whole resolved path: ``a/my.toml`` and
``b/my.toml`` are two files, and the second, with other values, is refused in the first's
folder, whose results stay; (2) what a rerun removes is *its own* earlier results, those of the
same command: ``--force`` writes into another command's folder (the refusal says "pass --force
to write into it", not "to replace them", as it says for another design of the same command),
so that command's finished results are kept. The stand-in command, designs and helpers are
those of :mod:`test_output_folder_reference` (no analysis runs: a few file operations in
``tmp_path``; the whole file takes about 0.02 s of CPU).
"""

from __future__ import annotations

import json
from pathlib import Path

from test_output_folder_reference import MINE, TWIN, USER_ERROR, _marker, _names, _run

from flexshaft.cli.output import MARKER


def test_a_file_of_the_same_name_in_another_folder_is_another_design(tmp_path: Path, capsys) -> None:
    """``a/my.toml`` and ``b/my.toml`` (same title, other values) share a file name, not a file."""
    out = tmp_path / "my-results"
    a, b = tmp_path / "a" / "my.toml", tmp_path / "b" / "my.toml"
    assert _run(out, MINE, str(a), writes=["results.json", "report.html"]) == 0
    capsys.readouterr()
    assert _run(out, TWIN, str(b), writes=["results.json"]) == USER_ERROR
    err = capsys.readouterr().err
    assert f"from {a}" in err and f"from {b}" in err and "--force" in err
    assert _names(out) == sorted([MARKER, "report.html", "results.json"])  # nothing removed
    assert "0.003" in (out / "results.json").read_text() and "0.004" not in (out / "results.json").read_text()
    assert _marker(out)["design_source"] == str(a)


def test_force_into_another_commands_folder_keeps_its_results(tmp_path: Path, capsys) -> None:
    """``flexshaft run --force`` into a folder of ``flexshaft study wall`` on another design:
    the study's results are not the run's earlier results, so they stay, and so does the
    user's file; the run's own file is added beside them."""
    out = tmp_path / "my-study-wall"
    out.mkdir()
    (out / "results.nc").write_text("a study's results")
    (out / "notes.txt").write_text("mine")
    marker = {"written_by": "flexshaft", "command": "study wall", "design": TWIN.name, "entries": ["results.nc"]}
    marker.update(design_fingerprint="0" * 64, design_source=str(tmp_path / "other.toml"), complete=True)
    (out / MARKER).write_text(json.dumps(marker), encoding="utf-8")
    assert _run(out, MINE, str(tmp_path / "my.toml")) == USER_ERROR
    assert "write into it" in capsys.readouterr().err
    assert _run(out, MINE, str(tmp_path / "my.toml"), force=True, writes=["results.json"]) == 0
    assert (out / "results.nc").read_text() == "a study's results"
    assert (out / "notes.txt").read_text() == "mine"
    assert _names(out) == sorted([MARKER, "notes.txt", "results.json", "results.nc"])


def test_a_rerun_after_force_keeps_the_other_commands_results(tmp_path: Path) -> None:
    """Then the edited design's rerun (no ``--force``: the same file, the same command) removes
    "the files the earlier run wrote" (README) — the run's ``results.json`` — and not the study's
    ``results.nc``, which the run did not write (found by hunt h104a: the marker had taken the
    study's entries as the run's own, and the rerun deleted them)."""
    from test_output_folder_reference import EDITED

    out = tmp_path / "my-study-wall"
    out.mkdir()
    (out / "results.nc").write_text("a study's results")
    marker = {"written_by": "flexshaft", "command": "study wall", "design": TWIN.name, "entries": ["results.nc"]}
    marker.update(design_fingerprint="0" * 64, design_source=str(tmp_path / "other.toml"), complete=True)
    (out / MARKER).write_text(json.dumps(marker), encoding="utf-8")
    mine = str(tmp_path / "my.toml")
    assert _run(out, MINE, mine, force=True, writes=["results.json", "report.html"]) == 0
    assert "results.nc" not in _marker(out)["entries"]
    assert _run(out, EDITED, mine, writes=["results.json"]) == 0
    assert (out / "results.nc").read_text() == "a study's results"
    assert _names(out) == sorted([MARKER, "results.json", "results.nc"])  # the run's report.html removed
