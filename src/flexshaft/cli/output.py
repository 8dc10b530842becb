"""Output folders (``--out``): one guarded path for every command that writes a folder.

``run``, ``compare``, ``runup``, ``montecarlo``, ``optimize`` and every ``study`` command call
:func:`prepare_output_folder` before computing anything. It

* refuses a path that is a file (or lies below one), and a folder it cannot create or write;
* refuses a non-empty folder that flexshaft did not write, unless ``--force``;
* refuses a folder flexshaft wrote for another command, or for another design, unless
  ``--force``. The same design is the same values (fingerprint) *or* the same design file
  (its resolved path): a rerun of an edited design file replaces its own earlier results (the
  files that run wrote are removed first, so none of the old design's results linger); the
  message of a refusal names both designs by title, file and fingerprint;
* removes every symbolic link inside the folder and inside the subfolders an earlier run wrote
  (never following it: the file it points to is untouched; the user's own subfolders are not
  entered), and removes the temporary files a crash left;
* writes the marker file :data:`MARKER` (``.flexshaft-output.json``: command, design name,
  fingerprint and source, flexshaft version, no timestamp) with ``"complete": false``.

Every file is then written atomically (:mod:`flexshaft.files`: a temporary name in the folder
renamed into place, so a symbolic link planted during the run is replaced too, and an error
names the file). When the command ends, its error boundary
(:func:`flexshaft.cli.common.guarded`) rewrites the marker *last*: ``"complete": true`` and the
entries the command wrote, or, after an error, a full disk or Ctrl-C, still
``"complete": false``, so a partial folder never looks complete (the next run of the same
design still recognises it and resumes or replaces it).

Every refusal is a user error (exit code 2) naming the folder and what to do.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any

from flexshaft.cli.common import at_command_end, design_fingerprint, fail, plain

__all__ = ["MARKER", "default_output_folder", "prepare_output_folder", "read_marker"]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).

#: Marker file of a folder written by flexshaft.
MARKER = ".flexshaft-output.json"
#: Prefixes of the files flexshaft makes for a moment (write probe, atomic writes).
_PROBE = ".flexshaft-write-test-"
_TEMPORARY = ".tmp-"


def default_output_folder(design: Path | None, suffix: str, embedded: str = "flexshaft") -> Path:
    """The default ``--out`` of a command: ``<design-stem>-<suffix>`` for a design file (so
    that each design file has its own folder), ``<embedded>-<suffix>`` without one
    (``flexshaft-results`` for ``flexshaft run`` on the embedded design)."""
    stem = embedded if design is None else (Path(design).stem or "design")
    return Path(f"{stem}-{suffix}")


def marker_source(path: Path | None, embedded: str) -> str:
    """Where a design came from, as the marker records it: the design file's resolved path, or
    ``embedded NAME``."""
    if path is None:
        return f"embedded {embedded}"
    try:
        return os.fsdecode(Path(path).resolve())
    except (OSError, RuntimeError):  # a loop of links: the path as given
        return os.fsdecode(os.path.abspath(path))


def read_marker(folder: Path) -> dict | None:
    """The marker of ``folder`` if it is a readable flexshaft marker (a regular file, not a
    symbolic link), else None."""
    try:
        fd = os.open(Path(folder) / MARKER, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
        with os.fdopen(fd, "rb") as handle:
            data = json.loads(handle.read(1 << 20).decode("utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or data.get("written_by") != "flexshaft":
        return None
    return data


def _entries(folder: Path, option: str) -> list[str]:
    try:
        names = sorted(p.name for p in folder.iterdir())
    except PermissionError:
        fail(f"{option}: cannot read the folder {folder} (permission denied); choose another folder")
    except OSError as exc:
        fail(f"{option}: cannot read the folder {folder} ({exc.strerror}); choose another folder")
    return [n for n in names if not n.startswith(_PROBE)]


def _check_writable(folder: Path, option: str) -> None:
    try:
        handle, probe = tempfile.mkstemp(prefix=_PROBE, dir=folder)
    except PermissionError:
        fail(f"{option}: the folder {folder} is not writable (permission denied); choose another folder")
    except OSError as exc:
        fail(f"{option}: cannot write into the folder {folder} ({exc.strerror}); choose another folder")
    os.close(handle)
    os.unlink(probe)


def _describe(name: Any, source: Any, fingerprint: Any) -> str:
    """A design as a refusal names it: title, file and fingerprint (two designs of one title
    differ by the other two)."""
    where = f"from {source}" if source else "source not recorded"
    return f"{plain(name)!r} ({where}, fingerprint {str(fingerprint)[:12]})"


def _remove_links(folder: Path, own: list[str]) -> None:
    """Remove every symbolic link among the entries of ``folder`` and below its subfolders
    ``own`` (those an earlier run of flexshaft wrote); links are never followed: the file or
    folder a link points to is untouched. The user's own subfolders (``--force`` into a project
    folder) are not entered: their links are not flexshaft's to remove (``runup --out .
    --force`` used to delete every link of the tree, a virtual environment's ``bin/python``
    included)."""
    for name in os.listdir(folder):
        path = folder / name
        if path.is_symlink():
            path.unlink()
        elif name in own and path.is_dir():
            for root, dirs, files in os.walk(path, followlinks=False):
                for inner in dirs + files:
                    if (Path(root) / inner).is_symlink():
                        (Path(root) / inner).unlink()


def _remove_entries(folder: Path, names: list[str]) -> None:
    """Remove the entries ``names`` of ``folder`` that an earlier run wrote (folders with their
    content; links were removed before, so nothing outside ``folder`` is touched)."""
    for name in names:
        path = folder / name
        if Path(name).name != name or name in ("", ".", "..", MARKER):
            continue
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path)
        elif path.exists() or path.is_symlink():
            path.unlink()


def prepare_output_folder(
    folder: Path, design: Any, command: str, *, force: bool = False, option: str = "--out", source: str | None = None
) -> Path:
    """Check (and create) an output folder for ``command`` on ``design``; mark it as being
    written (see the module docstring).

    Parameters
    ----------
    folder
        The folder given with ``--out``.
    design
        The validated design the command will write results of.
    command
        The command, e.g. ``"run"`` or ``"study wall"`` (a folder is reused only by the same one).
    force
        Write into a non-empty folder that flexshaft did not write, or wrote for another design
        or command.
    source
        Where the design came from (:func:`marker_source`): a folder written for the same
        source by the same command is the same design's, whatever its values now.

    Raises
    ------
    flexshaft.cli.common.UserError
        Naming the folder and what to change.
    """
    folder = Path(folder)
    fingerprint = design_fingerprint(design)
    previous: list[str] = []  # entries an earlier run of flexshaft wrote
    replace: list[str] = []  # ... of which the results of an earlier version of the design
    same_command = False  # whether that run was this command's (else its entries stay its own)
    if folder.is_symlink() and not folder.is_dir():
        target = "a file, not a folder" if folder.exists() else "a missing target"
        fail(f"{option}: {folder} is a symbolic link to {target}; give a folder path")
    if folder.exists() and not folder.is_dir():
        fail(f"{option}: {folder} is a file, not a folder; give a folder path (it is created if missing)")
    if folder.is_dir():
        entries = _entries(folder, option)
        marker = read_marker(folder)
        same_command = marker is not None and marker.get("command") == command
        same_values = same_command and marker is not None and marker.get("design_fingerprint") == fingerprint
        same_source = (
            same_command and marker is not None and source is not None and marker.get("design_source") == source
        )
        if entries and not force:
            if marker is None:
                shown = [n for n in entries if n != MARKER]
                fail(
                    f"{option}: the folder {folder} is not empty and was not written by flexshaft "
                    f"({len(shown)} entries, no {MARKER}); choose a new or empty folder, or pass --force "
                    "to write into it anyway"
                )
            if not same_command:
                fail(
                    f"{option}: the folder {folder} holds the output of 'flexshaft {plain(marker.get('command'))}', "
                    f"not of 'flexshaft {command}'; choose another folder, or pass --force to write into it"
                )
            if not (same_values or same_source):
                theirs = _describe(marker.get("design"), marker.get("design_source"), marker.get("design_fingerprint"))
                fail(
                    f"{option}: the folder {folder} holds the results of another design: {theirs}, not "
                    f"{_describe(design.name, source, fingerprint)}; choose another folder, or pass --force to "
                    "replace them"
                )
        if marker is not None:
            listed = marker.get("entries")
            if isinstance(listed, list) and all(isinstance(n, str) for n in listed):
                previous = [n for n in listed if n in entries]
                if marker.get("command") == command and not same_values:
                    replace = previous  # results of another version of the design (same file, or --force)
            else:  # a marker of an earlier flexshaft, without its list: nothing is removed
                previous = [n for n in entries if n != MARKER]
        _remove_links(folder, previous)
        if marker is not None:
            for name in _entries(folder, option):
                if name.startswith(_TEMPORARY):  # left by a crash during an atomic write
                    (folder / name).unlink(missing_ok=True)
        _remove_entries(folder, replace)
    else:
        try:
            folder.mkdir(parents=True, exist_ok=True)
        except FileExistsError:
            fail(f"{option}: cannot create the folder {folder}: a part of the path is a file")
        except NotADirectoryError:
            fail(f"{option}: cannot create the folder {folder}: a part of the path is a file, not a folder")
        except PermissionError:
            fail(f"{option}: cannot create the folder {folder} (permission denied); choose another folder")
        except OSError as exc:
            fail(f"{option}: cannot create the folder {folder} ({exc.strerror}); choose another folder")
    _check_writable(folder, option)
    # another command's entries (kept by --force) are not this command's to remove on a rerun
    ours = [n for n in previous if n not in replace] if same_command else []
    foreign = set(_entries(folder, option)) - set(ours) - {MARKER}
    data = {
        "written_by": "flexshaft",
        "version": _version(),
        "command": command,
        "design": str(design.name),
        "design_fingerprint": fingerprint,
        "design_source": source,
        "complete": False,
        "entries": sorted(ours),
    }
    _write_marker(folder, data, option)

    def finish(complete: bool) -> None:
        written = [
            n for n in _entries(folder, option) if n not in foreign and n != MARKER and not n.startswith(_TEMPORARY)
        ]
        _write_marker(folder, {**data, "complete": complete, "entries": sorted(set(written) | set(ours))}, option)

    at_command_end(finish)
    return folder


def into_run_folder(compute, run_dir: Path, force: bool):
    """``compute()``, a sweep into ``run_dir`` (a study's folder, or montecarlo's ``sweep/``).

    A folder holding the chunks of the same command on the same design with other options (a
    Monte-Carlo of 20 samples rerun with 30, other ply angles) is refused, as the sweep engine
    does, with the way out: ``--force`` moves its chunks aside (``chunks.discarded-N/``: finished
    work is never deleted) and starts afresh, as a rerun of an edited design does.
    """
    from flexshaft.sweep import DifferentStudyError

    try:
        return compute()
    except DifferentStudyError as exc:
        if not force:
            fail(f"{exc}, or pass --force to start afresh in it (its chunks are moved aside, not deleted)")
        from flexshaft.sweep.store import start_afresh

        start_afresh(run_dir, f"it held another study ({exc.held}) and --force was given")
        return compute()


def _version() -> str:
    from flexshaft import __version__

    return __version__


def _write_marker(folder: Path, data: dict, option: str) -> None:
    from flexshaft.files import atomic_write_text

    try:
        atomic_write_text(folder / MARKER, json.dumps(data, indent=2) + "\n")
    except OSError as exc:
        fail(f"{option}: cannot write {folder / MARKER} ({exc.strerror}); choose another folder")
