"""Writing files that cannot hurt: atomic, never through a symbolic link, errors naming the file.

Every file the package writes into an output folder goes through :func:`atomic_write` (bytes or
text), or :func:`writing` for a writer that wants a path (matplotlib's ``savefig``, xarray's
``to_netcdf``):

* the data go to a temporary file in the same folder (``.tmp-*``), which is then renamed onto
  the target with :func:`os.replace`. A reader never sees half a file, and a crash or a full
  disk leaves the previous file (or none), never a truncated one;
* the rename replaces the directory entry: an existing symbolic link at the target is replaced
  by the new file, and the file it pointed to is left untouched (writing ``results.json`` over
  ``results.json -> ~/victim.txt`` used to overwrite ``victim.txt``);
* an :class:`OSError` while writing (no space left, quota, permission) names the target file,
  not the temporary one, and the temporary file is removed.

:func:`append_line` appends to a log file without following a symbolic link (``O_NOFOLLOW``).
"""

from __future__ import annotations

import contextlib
import functools
import os
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import IO, Any

__all__ = ["TEMPORARY_PREFIX", "append_line", "atomic_write", "atomic_write_text", "writing"]

#: Prefix of the temporary files (a crash can leave one; the next write ignores it).
TEMPORARY_PREFIX = ".tmp-"


def _named(error: OSError, path: Path) -> OSError:
    """``error`` with ``path`` as its file name (the temporary file means nothing to a user)."""
    if error.errno is None:
        return error
    renamed = OSError(error.errno, error.strerror or os.strerror(error.errno), os.fspath(path))
    renamed.__cause__ = error
    return renamed


@contextlib.contextmanager
def writing(path: str | os.PathLike, *, suffix: str | None = None) -> Iterator[Path]:
    """A temporary path next to ``path`` to write to; renamed onto ``path`` when the block ends
    without an error, removed otherwise.

    Parameters
    ----------
    path
        The file to write (its folder must exist).
    suffix
        Suffix of the temporary file (default: that of ``path``; some writers choose their
        format by it).
    """
    path = Path(path)
    try:
        fd, name = tempfile.mkstemp(
            dir=path.parent, prefix=TEMPORARY_PREFIX, suffix=path.suffix if suffix is None else suffix
        )
    except OSError as error:
        raise _named(error, path) from None
    tmp = Path(name)
    try:
        os.fchmod(fd, _file_mode())  # as open() would create it (mkstemp makes it private, 0600)
    except (OSError, AttributeError):  # pragma: no cover - a file system without modes
        pass
    finally:
        os.close(fd)
    try:
        yield tmp
        os.replace(tmp, path)
    except OSError as error:
        _remove(tmp)
        raise _named(error, path) from None
    except BaseException:
        _remove(tmp)
        raise


def atomic_write(path: str | os.PathLike, data: bytes | Callable[[IO[bytes]], Any], *, sync: bool = False) -> Path:
    """Write ``data`` (bytes, or a function writing to a binary file handle) to ``path`` through a
    temporary file and a rename (see the module docstring); ``sync`` flushes it to the disk
    before the rename. Returns ``path``."""
    path = Path(path)
    with writing(path) as tmp:
        with open(tmp, "wb") as handle:
            if callable(data):
                data(handle)
            else:
                handle.write(data)
            if sync:
                handle.flush()
                os.fsync(handle.fileno())
    return path


def atomic_write_text(path: str | os.PathLike, text: str, *, encoding: str = "utf-8") -> Path:
    """:func:`atomic_write` of ``text`` in ``encoding``."""
    return atomic_write(path, text.encode(encoding))


def append_line(path: str | os.PathLike, text: str, *, sync: bool = True) -> None:
    """Append ``text`` (UTF-8) to ``path``, created if missing; a symbolic link at ``path`` is
    refused (``OSError`` ``ELOOP`` naming the file), never followed."""
    path = Path(path)
    flags = os.O_WRONLY | os.O_APPEND | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0)
    try:
        fd = os.open(path, flags, 0o644)
        try:
            os.write(fd, text.encode("utf-8"))
            if sync:
                os.fsync(fd)
        finally:
            os.close(fd)
    except OSError as error:
        raise _named(error, path) from None


@functools.lru_cache(maxsize=1)
def _file_mode() -> int:
    """The mode a new file gets from ``open()``: 0666 less the process's umask (read once; the
    umask can only be read by setting it)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return 0o666 & ~mask


def _remove(path: Path) -> None:
    with contextlib.suppress(OSError):
        path.unlink()
