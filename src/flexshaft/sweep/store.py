"""The run folder of a sweep: a manifest and self-checking chunk files.

Layout::

    RUN/manifest.json            the study (specification, fingerprint), chunk size, checksum
    RUN/chunks/chunk_NNNNNN.npz  one chunk: ``values`` and a JSON ``header``
    RUN/results.nc               written by :func:`flexshaft.sweep.run_sweep` at the end

A chunk file holds two arrays: ``values`` (float64, little-endian, ``(stop - start,
n_outputs)``) and ``header``, a JSON string with the format number, the study fingerprint, the
chunk index, its point range ``start..stop-1``, the shape and dtype of ``values`` and
``sha256``, the SHA-256 of the header's other fields (canonical JSON) followed by the values'
bytes. Every file is written to a temporary name and renamed, so a killed run leaves whole
files only.

On resume a chunk is reused only if it reads, carries this study's fingerprint, this chunk's
index and point range, the expected shape, and a checksum that matches its bytes. Any other
chunk is deleted and recomputed with a :class:`~flexshaft.sweep.study.SweepWarning` naming the
file and the reason; files that are not chunks are ignored (with a warning). A missing or
unreadable manifest means the folder's history is unknown: its chunks are moved aside to
``RUN/chunks.discarded-N`` and the run starts afresh. Integrity comes from the checksum and the
fingerprint only; the engine does not judge whether the values are physically plausible.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import warnings
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import IO, Any

import numpy as np

from flexshaft.files import atomic_write as write_file
from flexshaft.sweep.study import DifferentStudyError, Study, SweepError, SweepWarning

__all__ = [
    "ChunkError",
    "atomic_write",
    "chunk_path",
    "finished_chunks",
    "load_chunks",
    "open_run",
    "read_chunk",
    "start_afresh",
    "write_chunk",
]

MANIFEST = "manifest.json"
CHUNKS = "chunks"
FORMAT = 2  # 1: bare chunk_NNNNNN.npy without checksum or fingerprint (never reused)
_CHUNK_NAME = re.compile(r"chunk_(\d{6})\.npz")
_DTYPE = np.dtype("<f8")
_ZIP_MAGIC = b"PK\x03\x04"


class ChunkError(ValueError):
    """A chunk file that must not be reused; the message says why."""


def atomic_write(path: Path, write: Callable[[IO[bytes]], Any]) -> None:
    """Write ``path`` through a temporary file in the same folder, synced, then renamed
    (:func:`flexshaft.files.atomic_write`: a symbolic link at ``path`` is replaced, an error
    names ``path``)."""
    write_file(path, write, sync=True)


def _digest(fields: dict, values: np.ndarray) -> str:
    text = json.dumps(fields, sort_keys=True, separators=(",", ":"))
    sha = hashlib.sha256(text.encode())
    sha.update(np.ascontiguousarray(values).tobytes())
    return sha.hexdigest()


# ---------------------------------------------------------------------------------------------
# Chunks


def chunk_path(run_dir: str | os.PathLike, index: int) -> Path:
    """Path of chunk ``index`` in a run folder."""
    return Path(run_dir) / CHUNKS / f"chunk_{index:06d}.npz"


def finished_chunks(run_dir: str | os.PathLike) -> list[int]:
    """Indices of the chunk files present in a run folder (by name; verified only on reuse)."""
    folder = Path(run_dir) / CHUNKS
    if not folder.is_dir():
        return []
    return sorted(int(m.group(1)) for p in folder.iterdir() if (m := _CHUNK_NAME.fullmatch(p.name)))


def write_chunk(path: Path, values: np.ndarray, *, fingerprint: str, index: int, start: int, stop: int) -> None:
    """Store one chunk's values with its identity and checksum, atomically.

    Parameters
    ----------
    path : Path
        Destination, normally :func:`chunk_path` ``(run_dir, index)``.
    values : ndarray
        Outputs of points ``start..stop-1``, shape ``(stop - start, n_outputs)``.
    fingerprint : str
        :meth:`Study.fingerprint` of the study the values belong to.
    index, start, stop : int
        Chunk number and its half-open range of flat grid indices.
    """
    values = np.ascontiguousarray(values, dtype=_DTYPE)
    fields = {
        "format": FORMAT,
        "fingerprint": fingerprint,
        "chunk": int(index),
        "start": int(start),
        "stop": int(stop),
        "shape": list(values.shape),
        "dtype": _DTYPE.str,
    }
    header = dict(fields, sha256=_digest(fields, values))
    atomic_write(path, lambda fh: np.savez(fh, values=values, header=np.array(json.dumps(header))))


def read_chunk(path: Path, *, fingerprint: str, index: int, start: int, stop: int, n_outputs: int) -> np.ndarray:
    """The values of a stored chunk, after checking that it is exactly the chunk expected.

    Raises
    ------
    ChunkError
        The file cannot be read, belongs to another study, holds another chunk or range, has
        the wrong shape or dtype, or its bytes do not match its checksum.
    """
    try:
        with open(path, "rb") as fh:
            magic = fh.read(len(_ZIP_MAGIC))
        if magic != _ZIP_MAGIC:
            raise ChunkError("empty file" if not magic else "not an .npz archive")
        archive = np.load(path, allow_pickle=False)
        if not isinstance(archive, np.lib.npyio.NpzFile):  # pragma: no cover - magic checked
            raise ChunkError("not an .npz archive")
        with archive:
            members = sorted(archive.files)
            if members != ["header", "values"]:
                raise ChunkError(f"not a chunk archive (members {members})")
            header_text = archive["header"]
            values = archive["values"]
    except ChunkError:
        raise
    except Exception as exc:  # untrusted bytes: any failure to parse means "unreadable"
        raise ChunkError(f"unreadable ({type(exc).__name__}: {exc})") from exc
    try:
        header = json.loads(str(header_text[()]))
        fields = {k: header[k] for k in ("format", "fingerprint", "chunk", "start", "stop", "shape", "dtype")}
        checksum = header["sha256"]
    except Exception as exc:  # same: a header that is not the JSON we write
        raise ChunkError(f"unreadable header ({type(exc).__name__}: {exc})") from exc
    if fields["format"] != FORMAT:
        raise ChunkError(f"chunk format {fields['format']!r}, expected {FORMAT}")
    if fields["fingerprint"] != fingerprint:
        raise ChunkError(
            f"belongs to another study (fingerprint {str(fields['fingerprint'])[:12]}, this study {fingerprint[:12]})"
        )
    if (fields["chunk"], fields["start"], fields["stop"]) != (index, start, stop):
        raise ChunkError(
            f"holds chunk {fields['chunk']!r} (points {fields['start']!r}..{fields['stop']!r}), "
            f"expected chunk {index} (points {start}..{stop})"
        )
    expected_shape = (stop - start, n_outputs)
    if values.shape != expected_shape or values.dtype != _DTYPE:
        raise ChunkError(f"values of shape {values.shape} {values.dtype}, expected {expected_shape} float64")
    if fields["shape"] != list(expected_shape) or fields["dtype"] != _DTYPE.str:
        raise ChunkError(f"header declares shape {fields['shape']} {fields['dtype']}, expected {list(expected_shape)}")
    if _digest(fields, values) != checksum:
        raise ChunkError("checksum mismatch: the file changed after it was written")
    return values


def load_chunks(
    run_dir: Path, bounds: Sequence[tuple[int, int]], *, fingerprint: str, n_outputs: int
) -> dict[int, np.ndarray]:
    """The verified chunks of a run folder, by index.

    Chunks that fail :func:`read_chunk` are deleted (they will be recomputed) with a
    :class:`SweepWarning` naming each file and the reason. Other files are left alone; those
    that are not leftovers of an interrupted write (``.tmp-*``) are named in a warning.
    """
    folder = run_dir / CHUNKS
    if not folder.is_dir():
        return {}
    good: dict[int, np.ndarray] = {}
    rejected: list[str] = []
    stray: list[str] = []
    for path in sorted(folder.iterdir()):
        match = _CHUNK_NAME.fullmatch(path.name)
        if match is not None and not path.is_file():
            raise SweepError(f"run folder {run_dir}: {CHUNKS}/{path.name} is not a file; remove it and run again")
        if match is None or int(match.group(1)) >= len(bounds):
            if not path.name.startswith(".tmp-"):
                stray.append(path.name)
            continue
        k = int(match.group(1))
        start, stop = bounds[k]
        try:
            good[k] = read_chunk(path, fingerprint=fingerprint, index=k, start=start, stop=stop, n_outputs=n_outputs)
        except ChunkError as exc:
            rejected.append(f"{path.name}: {exc}")
            path.unlink()
    if rejected:
        warnings.warn(
            f"run folder {run_dir}: recomputing {len(rejected)} chunk(s) that cannot be reused:\n  "
            + "\n  ".join(rejected),
            SweepWarning,
            stacklevel=3,
        )
    if stray:
        warnings.warn(
            f"run folder {run_dir}: ignoring {len(stray)} file(s) in {CHUNKS}/ that are not chunks of "
            f"this run: {', '.join(stray)}",
            SweepWarning,
            stacklevel=3,
        )
    return good


# ---------------------------------------------------------------------------------------------
# Manifest


def _manifest_fields(study: Study, fingerprint: str, chunk_size: int) -> dict:
    return {
        "format": FORMAT,
        "fingerprint": fingerprint,
        "chunk_size": int(chunk_size),
        "size": study.size,
        "n_outputs": len(study.outputs),
        "study": study.spec(),
    }


def _read_manifest(path: Path) -> dict:
    """The stored manifest; raises ``ValueError`` (with the reason) when it cannot be trusted."""
    try:
        stored = json.loads(path.read_text())
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ValueError(f"unreadable ({type(exc).__name__}: {exc})") from exc
    if not isinstance(stored, dict):
        raise ValueError(f"not a JSON object but {type(stored).__name__}")
    keys = ("format", "fingerprint", "chunk_size", "size", "n_outputs", "study", "sha256")
    missing = [k for k in keys if k not in stored]
    if missing:
        raise ValueError(f"missing {missing} (an older or foreign manifest)")
    fields = {k: stored[k] for k in keys[:-1]}
    text = json.dumps(fields, sort_keys=True, separators=(",", ":"), default=repr)
    if hashlib.sha256(text.encode()).hexdigest() != stored["sha256"]:
        raise ValueError("checksum mismatch: the file changed after it was written")
    if stored["format"] != FORMAT:
        raise ValueError(f"format {stored['format']!r}, expected {FORMAT}")
    if not isinstance(stored["chunk_size"], int) or stored["chunk_size"] < 1:
        raise ValueError(f"chunk_size {stored['chunk_size']!r} is not a positive integer")
    return stored


def _write_manifest(path: Path, fields: dict) -> None:
    # The spec is JSON-able except for values it shows by repr; store it as it will read back.
    fields = json.loads(json.dumps(fields, default=repr))
    text = json.dumps(fields, sort_keys=True, separators=(",", ":"))
    record = dict(fields, sha256=hashlib.sha256(text.encode()).hexdigest())
    atomic_write(path, lambda fh: fh.write(json.dumps(record, indent=1).encode()))


def _discard_chunks(run_dir: Path, reason: str | None, moved: str = "its chunks cannot be trusted and were") -> None:
    """Start a run folder afresh: move ``RUN/chunks`` aside so none of it is ever reused.

    ``reason`` (why the folder's history is unknown) is warned about when chunks were moved
    or the manifest was unreadable; ``None`` (no manifest, no chunks: a new folder) is silent.
    """
    folder = run_dir / CHUNKS
    if folder.is_dir() and any(folder.iterdir()):
        n = 1
        while (aside := run_dir / f"{CHUNKS}.discarded-{n}").exists():
            n += 1
        os.replace(folder, aside)
        warnings.warn(
            f"run folder {run_dir}: {reason}; {moved} moved to {aside.name}/; computing every chunk afresh",
            SweepWarning,
            stacklevel=4,
        )
    elif reason is not None and not reason.endswith("is missing"):
        warnings.warn(f"run folder {run_dir}: {reason}; starting afresh", SweepWarning, stacklevel=4)


def start_afresh(run_dir: str | os.PathLike, reason: str) -> None:
    """Let the next run in ``run_dir`` start afresh: its chunks moved aside to
    ``chunks.discarded-N/`` (kept, never deleted; warned with ``reason``) and its manifest
    removed (e.g. ``flexshaft montecarlo --force`` with other options than the folder's)."""
    run_dir = Path(run_dir)
    _discard_chunks(run_dir, reason, "its chunks were")
    (run_dir / MANIFEST).unlink(missing_ok=True)


def open_run(run_dir: Path, study: Study, fingerprint: str, chunk_size: int | None, default_chunk_size: int) -> int:
    """Create or check a run folder; returns the chunk size in force.

    A folder whose manifest reads and matches ``study`` resumes with its stored chunk size. A
    manifest that reads but belongs to another study is refused (:class:`~flexshaft.sweep.study.DifferentStudyError`;
    :func:`start_afresh` moves its chunks aside). A
    missing or untrustworthy manifest starts the run afresh, its chunks moved aside.
    """
    manifest = run_dir / MANIFEST
    if manifest.exists():
        try:
            stored = _read_manifest(manifest)
        except ValueError as exc:
            _discard_chunks(run_dir, f"{MANIFEST} cannot be trusted ({exc})")
        else:
            if stored["fingerprint"] != fingerprint:
                name = stored["study"].get("name") if isinstance(stored["study"], dict) else None
                held = f"{name!r}, fingerprint {str(stored['fingerprint'])[:12]}"
                raise DifferentStudyError(
                    f"run folder {run_dir} holds a different study ({held}); use a new folder to run this one", held
                )
            if chunk_size is not None and chunk_size != stored["chunk_size"]:
                raise SweepError(
                    f"run folder {run_dir} was started with chunk_size={stored['chunk_size']}; "
                    f"resume with the same chunk size (got {chunk_size})"
                )
            if (stored["size"], stored["n_outputs"]) == (study.size, len(study.outputs)):
                (run_dir / CHUNKS).mkdir(parents=True, exist_ok=True)
                return stored["chunk_size"]
            _discard_chunks(run_dir, f"{MANIFEST} declares {stored['size']} points × {stored['n_outputs']} outputs")
    else:
        _discard_chunks(run_dir, f"{MANIFEST} is missing")
    chunk_size = int(chunk_size or default_chunk_size)
    (run_dir / CHUNKS).mkdir(parents=True, exist_ok=True)
    _write_manifest(manifest, _manifest_fields(study, fingerprint, chunk_size))
    return chunk_size
