"""Output folders (``--out``): checked before any computation, marked as flexshaft's.

A command that writes a folder first calls :func:`prepare_output_folder`, which

* refuses a path that is a file (or lies below one), and a folder it cannot create or write;
* refuses a non-empty folder that flexshaft did not write, unless ``--force``;
* refuses a folder flexshaft wrote for another design or another command, unless ``--force``;
  one written for the same design by the same command is updated in place;
* writes the marker file :data:`MARKER` (``.flexshaft-output.json``: command, design name and
  fingerprint, flexshaft version; no timestamp) so that the next run recognises the folder.

Every refusal is a user error (exit code 2) naming the folder and what to do.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import Any

from flexshaft.cli.common import design_fingerprint, fail

__all__ = ["MARKER", "prepare_output_folder", "read_marker"]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).

#: Marker file of a folder written by flexshaft.
MARKER = ".flexshaft-output.json"


def read_marker(folder: Path) -> dict | None:
    """The marker of ``folder`` if it is a readable flexshaft marker, else None."""
    try:
        data = json.loads((folder / MARKER).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or data.get("written_by") != "flexshaft":
        return None
    return data


def _entries(folder: Path, option: str) -> list[str]:
    try:
        return sorted(p.name for p in folder.iterdir())
    except PermissionError:
        fail(f"{option}: cannot read the folder {folder} (permission denied); choose another folder")
    except OSError as exc:
        fail(f"{option}: cannot read the folder {folder} ({exc.strerror}); choose another folder")


def _check_writable(folder: Path, option: str) -> None:
    try:
        handle, probe = tempfile.mkstemp(prefix=".flexshaft-write-test-", dir=folder)
    except PermissionError:
        fail(f"{option}: the folder {folder} is not writable (permission denied); choose another folder")
    except OSError as exc:
        fail(f"{option}: cannot write into the folder {folder} ({exc.strerror}); choose another folder")
    os.close(handle)
    os.unlink(probe)


def prepare_output_folder(
    folder: Path, design: Any, command: str, *, force: bool = False, option: str = "--out"
) -> Path:
    """Check (and create) an output folder for ``command`` on ``design``; write its marker.

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

    Raises
    ------
    flexshaft.cli.common.UserError
        Naming the folder and what to change.
    """
    folder = Path(folder)
    fingerprint = design_fingerprint(design)
    if folder.exists() and not folder.is_dir():
        fail(f"{option}: {folder} is a file, not a folder; give a folder path (it is created if missing)")
    if folder.is_dir():
        entries = [name for name in _entries(folder, option) if not name.startswith(".flexshaft-write-test-")]
        marker = read_marker(folder)
        if entries and not force:
            if marker is None:
                fail(
                    f"{option}: the folder {folder} is not empty and was not written by flexshaft "
                    f"({len(entries)} entries, no {MARKER}); choose a new or empty folder, or pass --force "
                    "to write into it anyway"
                )
            if marker.get("command") != command:
                fail(
                    f"{option}: the folder {folder} holds the output of 'flexshaft {marker.get('command')}', "
                    f"not of 'flexshaft {command}'; choose another folder, or pass --force to write into it"
                )
            if marker.get("design_fingerprint") != fingerprint:
                fail(
                    f"{option}: the folder {folder} holds the results of another design "
                    f"({marker.get('design')!r}, not {str(design.name)!r}); choose another folder, or pass "
                    "--force to replace them"
                )
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
    _write_marker(folder, design, fingerprint, command, option)
    return folder


def _write_marker(folder: Path, design: Any, fingerprint: str, command: str, option: str) -> None:
    from flexshaft import __version__

    data = {
        "written_by": "flexshaft",
        "version": __version__,
        "command": command,
        "design": str(design.name),
        "design_fingerprint": fingerprint,
    }
    try:
        (folder / MARKER).write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    except OSError as exc:
        fail(f"{option}: cannot write {folder / MARKER} ({exc.strerror}); choose another folder")
