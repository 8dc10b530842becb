"""Guards on design files and TOML text, applied before the TOML parser sees them.

A design file is a few kilobytes of text (the baseline is 9 KB). These limits refuse inputs
that would otherwise block or exhaust memory before any schema check could run:

* only regular files are read (``/dev/zero`` would be read until memory runs out, a FIFO
  blocks the reader forever); the file is opened without blocking and checked with ``fstat``;
* at most :data:`MAX_DESIGN_BYTES` (1 MB, a hundred times the baseline) are read;
* no line longer than :data:`MAX_LINE_LENGTH` characters;
* no dotted key or table header with more than :data:`MAX_KEY_DEPTH` parts (Python's
  ``tomllib`` needs memory quadratic in the depth of a dotted key: 5,000 levels cost 100 MB,
  20,000 levels 1.6 GB; the schema's deepest key has 4 parts);
* arrays and inline tables nested at most :data:`MAX_NESTING` deep.

Each limit is reported as one :class:`~flexshaft.design.io.Problem` line naming the file
(and the line), the value found and the limit.
"""

from __future__ import annotations

import os
import re
import stat

__all__ = ["MAX_DESIGN_BYTES", "MAX_LINE_LENGTH", "MAX_KEY_DEPTH", "MAX_NESTING", "read_design_bytes", "text_problems"]

#: Largest design file or text [bytes / characters].
MAX_DESIGN_BYTES = 1_000_000
#: Longest line of a design file [characters].
MAX_LINE_LENGTH = 10_000
#: Most parts of a dotted key or table header (``a.b.c`` has 3).
MAX_KEY_DEPTH = 32
#: Deepest nesting of arrays and inline tables.
MAX_NESTING = 32

_QUOTED = re.compile(r'"""[\s\S]*?"""|\'\'\'[\s\S]*?\'\'\'|"(?:[^"\\\n]|\\.)*"|\'[^\'\n]*\'')
_HEADER = re.compile(r"^\s*\[\[?([^\]]*)\]")
_KEY_BOUNDARY = re.compile(r"[{,=]")


def read_design_bytes(path: str | os.PathLike[str]) -> bytes:
    """The bytes of a design file: a regular file of at most :data:`MAX_DESIGN_BYTES`.

    Raises
    ------
    OSError
        When the file cannot be opened or read (the caller reports it).
    ValueError
        With the reason when the path is not a regular file or the file is too large.
    """
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    descriptor = os.open(path, flags)  # never blocks, even on a FIFO without a writer
    try:
        info = os.fstat(descriptor)
        if stat.S_ISDIR(info.st_mode):
            raise IsADirectoryError(21, "is a directory")
        if not stat.S_ISREG(info.st_mode):
            kind = (
                "a FIFO (named pipe)"
                if stat.S_ISFIFO(info.st_mode)
                else "a character device"
                if stat.S_ISCHR(info.st_mode)
                else "a block device"
                if stat.S_ISBLK(info.st_mode)
                else "a socket"
                if stat.S_ISSOCK(info.st_mode)
                else "not a regular file"
            )
            raise ValueError(
                f"is {kind}, not a design file (allowed: a regular file of at most {MAX_DESIGN_BYTES:,} bytes)"
            )
        if info.st_size > MAX_DESIGN_BYTES:
            raise ValueError(
                f"is {info.st_size:,} bytes long (allowed: at most {MAX_DESIGN_BYTES:,} bytes; "
                "a design file is a few kilobytes)"
            )
        if hasattr(os, "set_blocking"):
            os.set_blocking(descriptor, True)
        chunks, size = [], 0
        while size <= MAX_DESIGN_BYTES:  # the file may grow after fstat
            chunk = os.read(descriptor, MAX_DESIGN_BYTES + 1 - size)
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        if size > MAX_DESIGN_BYTES:
            raise ValueError(
                f"is more than {MAX_DESIGN_BYTES:,} bytes long (allowed: at most "
                f"{MAX_DESIGN_BYTES:,} bytes; a design file is a few kilobytes)"
            )
        return b"".join(chunks)
    finally:
        os.close(descriptor)


def _keys(line: str) -> list[str]:
    """The key text before each ``=`` of a line: from the line start, a ``{`` or a ``,`` to the
    ``=`` (one linear pass; values never end in ``=``, so their dots are not counted)."""
    keys, start = [], 0
    for match in _KEY_BOUNDARY.finditer(line):
        if match.group() == "=":
            keys.append(line[start : match.start()])
        start = match.end()
    return keys


def text_problems(text: str) -> list[str]:
    """Reasons why ``text`` is refused before parsing (empty when it may be parsed).

    Quoted strings are blanked first, so dots, brackets and ``=`` inside them do not count.
    """
    if len(text) > MAX_DESIGN_BYTES:
        return [f"the text is {len(text):,} characters long (allowed: at most {MAX_DESIGN_BYTES:,})"]
    for number, line in enumerate(text.split("\n"), start=1):
        if len(line) > MAX_LINE_LENGTH:
            return [
                f"line {number} is {len(line):,} characters long (allowed: at most {MAX_LINE_LENGTH:,}; a "
                "design file has short lines)"
            ]
    problems: list[str] = []
    blanked = _QUOTED.sub(lambda match: "\x00" + "\n" * match.group().count("\n"), text)
    depth = 0
    for number, line in enumerate(blanked.split("\n"), start=1):
        line = line.split("#", 1)[0]
        header = _HEADER.match(line) if depth == 0 else None
        keys = [header.group(1)] if header else _keys(line)
        for key in keys:
            parts = key.count(".") + 1
            if parts > MAX_KEY_DEPTH:
                problems.append(f"line {number}: a dotted key with {parts:,} parts (allowed: at most {MAX_KEY_DEPTH})")
                return problems
        body = line[header.end() :] if header else line
        for char in body:
            if char in "[{":
                depth += 1
                if depth > MAX_NESTING:
                    problems.append(
                        f"line {number}: arrays or inline tables nested more than {MAX_NESTING} deep "
                        f"(allowed: at most {MAX_NESTING})"
                    )
                    return problems
            elif char in "]}":
                depth = max(depth - 1, 0)
    return problems
