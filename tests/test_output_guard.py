"""Writes that cannot hurt (issue 27, "Writes that cannot hurt"; the data-loss reproducers).

One guarded path for every command that writes a folder (``flexshaft.cli.output``) and atomic
files (``flexshaft.files``):

* ``optimize --out`` on a folder of the user's files is refused without ``--force`` (it
  replaced ``pareto.png``, ``pareto.svg`` and ``evaluations.nc``);
* a symbolic link planted in one's own output folder is replaced, never written through
  (``ln -sf ~/victim.txt o/results.json`` then a rerun overwrote ``victim.txt``; also through
  ``report.html`` and a linked sub-folder);
* every file appears complete or not at all, an error names the file, and the marker says
  ``"complete": false`` until the command has written everything (a full disk, simulated by
  the file-size limit ``RLIMIT_FSIZE``, left a folder that looked complete).

``run`` is exercised on the baseline with a coarse mesh and ``--studies none`` (about 2 s of CPU
a run); the other cases use ``study ply-angle`` with two angles (well under a second).
"""

from __future__ import annotations

import errno
import json
import os
import re
import resource
import shutil
import signal
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.cli.output import MARKER
from flexshaft.design import baseline_text
from flexshaft.files import append_line, atomic_write, atomic_write_text, writing

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
PLY = ["study", "ply-angle", "--step", "30"]


def _design(tmp_path: Path, name: str = "small.toml", text: str = SMALL) -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _marker(folder: Path) -> dict:
    return json.loads((folder / MARKER).read_text(encoding="utf-8"))


# ------------------------------------------------------------------------------------------------
# flexshaft.files


def test_an_atomic_write_replaces_a_link_and_leaves_its_target(tmp_path: Path) -> None:
    victim = tmp_path / "victim.txt"
    victim.write_text("keep")
    folder = tmp_path / "out"
    folder.mkdir()
    for name, write in (
        ("a.json", lambda p: atomic_write_text(p, "new")),
        ("b.bin", lambda p: atomic_write(p, b"new")),
        ("c.bin", lambda p: atomic_write(p, lambda handle: handle.write(b"new"))),
    ):
        link = folder / name
        link.symlink_to(victim)
        write(link)
        assert not link.is_symlink() and link.read_bytes() == b"new"
    assert victim.read_text() == "keep"
    assert sorted(p.name for p in folder.iterdir()) == ["a.json", "b.bin", "c.bin"]  # no temporary left


def test_a_failed_write_names_the_file_and_leaves_the_old_one(tmp_path: Path) -> None:
    target = tmp_path / "results.json"
    target.write_text("old")

    def disk_full(handle) -> None:
        handle.write(b"half")
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    with pytest.raises(OSError) as info:
        atomic_write(target, disk_full)
    assert info.value.errno == errno.ENOSPC and info.value.filename == str(target)
    assert target.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["results.json"]
    with pytest.raises(RuntimeError), writing(target) as tmp:  # any other error: removed, re-raised
        tmp.write_text("half")
        raise RuntimeError("writer failed")
    assert [p.name for p in tmp_path.iterdir()] == ["results.json"]


def test_appending_refuses_a_link(tmp_path: Path) -> None:
    victim = tmp_path / "victim.txt"
    victim.write_text("keep\n")
    log = tmp_path / "evaluations.jsonl"
    append_line(log, "one\n")
    append_line(log, "two\n", sync=False)
    assert log.read_text() == "one\ntwo\n"
    link = tmp_path / "linked.jsonl"
    link.symlink_to(victim)
    with pytest.raises(OSError) as info:
        append_line(link, "three\n")
    assert info.value.errno == errno.ELOOP and info.value.filename == str(link)
    assert victim.read_text() == "keep\n"


# ------------------------------------------------------------------------------------------------
# Data loss through the commands


def test_optimize_refuses_a_folder_of_user_files(tmp_path: Path) -> None:
    """Was: `mkdir u; echo keep > u/pareto.png; flexshaft optimize --budget 2 --fidelity
    screening --out u` replaced pareto.png, pareto.svg and evaluations.nc."""
    pytest.importorskip("pymoo")
    folder = tmp_path / "u"
    folder.mkdir()
    (folder / "pareto.png").write_text("keep")
    result = runner.invoke(app, ["optimize", "--budget", "2", "--fidelity", "screening", "--out", str(folder)])
    assert result.exit_code == 2, result.output
    assert "is not empty and was not written by flexshaft" in result.stderr and "--force" in result.stderr
    assert sorted(p.name for p in folder.iterdir()) == ["pareto.png"]
    assert (folder / "pareto.png").read_text() == "keep"


@pytest.mark.slow(
    reason="a `flexshaft run` of its own with the report's figures, each loop and root of the bearings "
    "(3-5 s of CPU; the session's small_run it copies is counted apart, tests/conftest.py)"
)
def test_a_link_planted_in_ones_own_run_folder_is_replaced(small_run: dict, tmp_path: Path) -> None:
    """Was: `flexshaft run b.toml --studies none -o o; ln -sf ~/victim.txt o/results.json;
    flexshaft run b.toml --studies none -o o` overwrote victim.txt (also via report.html). The
    first run is the session's (a small design at one envelope point), in a copy of its folder.

    The rerun is also tests/test_cli_outputs.py's second run of the same design (one run for
    both): a folder written for the same design by the same command is updated, results.json
    byte-identical to the first run's, and the markup in the actuators' names printed
    literally."""
    base, out = tmp_path, tmp_path / "o"
    shutil.copytree(small_run["out"], out, symlinks=True)
    victims = {name: base / f"victim-{name}" for name in ("results.json", "report.html", "campbell.png")}
    for name, victim in victims.items():
        victim.write_text("keep")
        (out / name).unlink()
        (out / name).symlink_to(victim)
    victim_folder = base / "victim-folder"
    victim_folder.mkdir()
    (out / "studies").symlink_to(victim_folder, target_is_directory=True)
    result = runner.invoke(app, ["run", str(small_run["design"]), "--studies", "none", "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert "[bold]amb_1[/]," in result.stdout or "[red]amb_2," in result.stdout  # printed literally
    for name, victim in victims.items():
        assert victim.read_text() == "keep", name
        assert not (out / name).is_symlink() and (out / name).stat().st_size > 100, name
    assert (out / "results.json").read_bytes() == small_run["results"]
    assert list(victim_folder.iterdir()) == [] and not (out / "studies").exists()
    marker = _marker(out)
    assert marker["complete"] is True and "results.json" in marker["entries"] and MARKER not in marker["entries"]


def test_a_linked_marker_is_not_taken_for_flexshafts(tmp_path: Path) -> None:
    """A marker that is a symbolic link (to another folder's marker) does not make a folder
    flexshaft's: the folder is refused as foreign, the link's target untouched."""
    design = _design(tmp_path)
    first = tmp_path / "first"
    assert runner.invoke(app, [*PLY, str(design), "--out", str(first)]).exit_code == 0
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / "thesis.docx").write_text("mine")
    (foreign / MARKER).symlink_to(first / MARKER)
    before = (first / MARKER).read_bytes()
    result = runner.invoke(app, [*PLY, str(design), "--out", str(foreign)])
    assert result.exit_code == 2 and "was not written by flexshaft" in result.stderr
    assert (first / MARKER).read_bytes() == before


def test_the_marker_is_written_last_and_says_incomplete_after_an_error(tmp_path: Path, monkeypatch) -> None:
    """The marker is ``complete: false`` while the command writes and after it failed; the
    next run of the same design recognises the folder and completes it."""
    import flexshaft.plot.studies as figures

    design = _design(tmp_path)
    out = tmp_path / "out"
    original = figures.ply_angle_figure
    seen = {}

    def failing(*args, **kwargs):
        seen["marker"] = _marker(out)  # while the command runs: results.nc written, figure not yet
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(out / "ply_angle.png"))

    monkeypatch.setattr(figures, "ply_angle_figure", failing)
    result = runner.invoke(app, [*PLY, str(design), "--out", str(out)])
    assert result.exit_code == 2, result.output
    assert f"cannot write or read {out / 'ply_angle.png'}: No space left on device" in result.stderr
    assert seen["marker"]["complete"] is False and (out / "results.nc").is_file()
    marker = _marker(out)
    assert marker["complete"] is False and marker["design_source"] == str(design.resolve())
    monkeypatch.setattr(figures, "ply_angle_figure", original)
    again = runner.invoke(app, [*PLY, str(design), "--out", str(out)])
    assert again.exit_code == 0, again.output
    assert _marker(out)["complete"] is True and (out / "ply_angle.png").is_file()


def _under_a_file_size_limit(limit: int, args: list[str]) -> dict:
    """``flexshaft *args`` in a child process whose files may not grow beyond ``limit`` bytes
    (``RLIMIT_FSIZE`` with ``SIGXFSZ`` ignored: a write beyond it fails with ``EFBIG``, as on a
    full disk), the limit the child's alone. The child is forked from this process, with the
    imports it already holds (a fresh interpreter spent about 1.3 s of CPU importing them);
    the command runs through the CLI's entry point as in every other test here. Returns the
    exit code, stderr and output, and any exception other than the exit's."""
    import multiprocessing

    context = multiprocessing.get_context("fork")
    receive, send = context.Pipe(duplex=False)

    def child() -> None:
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write beyond the limit then fails with EFBIG
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
        result = runner.invoke(app, args)
        exit_only = result.exception is None or isinstance(result.exception, SystemExit)
        raised = None if exit_only else repr(result.exception)  # text: any exception pickles as that
        send.send({"exit_code": result.exit_code, "stderr": result.stderr, "output": result.output, "raised": raised})

    process = context.Process(target=child)
    process.start()
    send.close()  # the child's end only: a child that dies without an answer ends recv with EOFError
    try:
        assert receive.poll(120), "the command did not end within 120 s"
        return receive.recv()
    finally:
        process.join(timeout=30)
        if process.is_alive():
            process.kill()
            process.join()


@pytest.mark.skipif(
    not hasattr(signal, "SIGXFSZ") or not hasattr(os, "fork"), reason="needs POSIX file-size limits and fork"
)
def test_a_full_disk_names_the_file_and_leaves_no_complete_looking_folder(tmp_path: Path) -> None:
    """Was: on a full disk the error named no file and the partial folder kept the "written by
    flexshaft" marker. A file-size limit of 20 kB (the PNG figure is ~40 kB; results.nc and the
    marker fit) makes the figure's write fail the way a full disk does."""
    design = _design(tmp_path)
    out = tmp_path / "out"
    result = _under_a_file_size_limit(20_000, [*PLY, str(design), "--out", str(out)])
    assert result["exit_code"] == 2, result["output"]
    assert f"error: cannot write or read {out / 'ply_angle.png'}: File too large" in result["stderr"]
    assert result["raised"] is None and "Traceback" not in result["output"], result
    assert _marker(out)["complete"] is False
    assert not (out / "ply_angle.png").exists()  # no half file
    assert not [p.name for p in out.iterdir() if p.name.startswith(".tmp-")]


def test_a_folder_marked_by_an_earlier_flexshaft_is_kept(tmp_path: Path) -> None:
    """A marker without ``entries`` and ``design_source`` (written before this change): the same
    design updates the folder; another one is refused, and with --force nothing is removed
    (there is no list of what the earlier run wrote; the user's notes must not go): the sweep
    finds the other design's chunks and, --force given, moves them aside (kept, not deleted)."""
    design = _design(tmp_path)
    other = _design(tmp_path, "other.toml", SMALL.replace("wall_thickness = 0.003", "wall_thickness = 0.0035", 1))
    out = tmp_path / "out"
    assert runner.invoke(app, [*PLY, str(design), "--out", str(out)]).exit_code == 0
    legacy = {k: v for k, v in _marker(out).items() if k not in ("entries", "design_source", "complete")}
    (out / MARKER).write_text(json.dumps(legacy), encoding="utf-8")
    (out / "notes.txt").write_text("mine")
    assert runner.invoke(app, [*PLY, str(design), "--out", str(out)]).exit_code == 0
    (out / MARKER).write_text(json.dumps(legacy), encoding="utf-8")
    refused = runner.invoke(app, [*PLY, str(other), "--out", str(out)])
    assert refused.exit_code == 2 and "source not recorded" in refused.stderr
    before = sorted(p.name for p in (out / "chunks").iterdir())
    forced = runner.invoke(app, [*PLY, str(other), "--out", str(out), "--force"])
    assert forced.exit_code == 0, forced.output
    assert (out / "notes.txt").read_text() == "mine"
    assert before and sorted(p.name for p in (out / "chunks.discarded-1").iterdir()) == before


def test_a_rerun_with_other_options_is_refused_and_starts_afresh_with_force(tmp_path: Path) -> None:
    """The same command on the same design with other options (here the ply-angle step: 2
    angles, then 1) finds the folder's chunks belong to another study. Was: refused even with
    --force ("use a new folder"). Now refused without it, naming --force; with it the old
    chunks are moved aside, never deleted, and the new study's are the only ones read: its
    results hold the new grid (α = 45° only) and the stored chunks of the old grid are intact."""
    design = _design(tmp_path)
    out = tmp_path / "out"
    assert runner.invoke(app, [*PLY, str(design), "--out", str(out)]).exit_code == 0
    old_chunks = {p.name: p.read_bytes() for p in (out / "chunks").iterdir()}
    other_step = ["study", "ply-angle", "--step", "45", str(design), "--out", str(out)]
    refused = runner.invoke(app, other_step)
    assert refused.exit_code == 2 and "holds a different study" in refused.stderr, refused.output
    assert "pass --force to start afresh" in refused.stderr and "Traceback" not in refused.output
    assert {p.name: p.read_bytes() for p in (out / "chunks").iterdir()} == old_chunks  # untouched
    forced = runner.invoke(app, [*other_step, "--force"])
    assert forced.exit_code == 0, forced.output
    assert {p.name: p.read_bytes() for p in (out / "chunks.discarded-1").iterdir()} == old_chunks
    import xarray as xr

    with xr.open_dataset(out / "results.nc") as ds:
        assert ds["alpha"].values.tolist() == [45.0]
