"""The comments of a TOML design file, by the key or table they annotate.

A design file's comments carry its provenance ("assumed", "calibrated: <finding>", a source);
a design file the optimizer writes keeps them (:func:`flexshaft.optimize.files.design_toml`).
:func:`read_comments` reads them from the text by lines, without a TOML library that keeps
comments:

* a comment after a key's value, or after a table header, belongs to that key or table
  (``inline``), and so do the indented comment lines right under it (the continuation of a long
  note, as in the embedded designs);
* comment lines that stand alone belong to the next key or table header (``before``: a section's
  explanation goes with the table it precedes);
* the comment lines before the file's first blank line, when no key came yet, are its
  ``preamble``; those after its last key its ``trailing`` lines.

A key's path is a tuple of names and array indices, as the design's dump nests them:
``("bearings", 1, "kp")`` for ``kp`` in the second ``[[bearings]]``, ``("materials",
"t700_adiprene")`` for that table's header. The values themselves are not parsed (only scanned
to their end, strings and brackets across lines included); the file is valid TOML already (it
loaded as the base design).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

__all__ = ["FileComments", "KeyComments", "read_comments"]

Path = tuple  # of str and int

_BARE = re.compile(r"[A-Za-z0-9_-]+")


@dataclass
class KeyComments:
    """Comment texts (without ``#``) of one key or table: the lines ``before`` it and the note
    ``inline`` after its value (with its continuation lines)."""

    before: list[str] = field(default_factory=list)
    inline: list[str] = field(default_factory=list)


@dataclass
class FileComments:
    """Every comment of a design file: the preamble, by path, and the trailing lines."""

    preamble: list[str] = field(default_factory=list)
    keys: dict[Path, KeyComments] = field(default_factory=dict)
    trailing: list[str] = field(default_factory=list)


def _text(comment: str) -> str:
    """The text of a ``# ...`` comment (one leading space dropped, trailing space stripped)."""
    body = comment.lstrip()[1:]
    return (body[1:] if body.startswith(" ") else body).rstrip()


def _split_keys(text: str) -> list[str]:
    """A dotted key (``a."b.c".d``) as its parts."""
    parts, i, text = [], 0, text.strip()
    while i < len(text):
        if text[i] in "\"'":
            quote = text[i]
            j = i + 1
            while j < len(text) and text[j] != quote:
                j += 2 if quote == '"' and text[j] == "\\" else 1
            parts.append(text[i + 1 : j])
            i = j + 1
        else:
            match = _BARE.match(text, i)
            if match is None:
                raise ValueError(f"cannot read the key {text!r}")
            parts.append(match.group())
            i = match.end()
        while i < len(text) and text[i] in " \t":
            i += 1
        if i < len(text):
            if text[i] != ".":
                raise ValueError(f"cannot read the key {text!r}")
            i += 1
            while i < len(text) and text[i] in " \t":
                i += 1
    return parts


class _Scanner:
    """Scans a value across lines: strings, brackets and braces, then the comment after it."""

    def __init__(self) -> None:
        self.depth = 0
        self.string: str | None = None  # the open string's delimiter

    def scan(self, line: str, start: int) -> tuple[bool, str | None]:
        """Scan ``line`` from ``start``; returns (value finished, comment text or None)."""
        i = start
        while i < len(line):
            if self.string is not None:
                if self.string in ('"', '"""') and line[i] == "\\":
                    i += 2
                    continue
                if line.startswith(self.string, i):
                    i += len(self.string)
                    self.string = None
                    continue
                i += 1
                continue
            c = line[i]
            if line.startswith('"""', i) or line.startswith("'''", i):
                self.string = line[i : i + 3]
                i += 3
            elif c in "\"'":
                self.string = c
                i += 1
            elif c in "[{":
                self.depth += 1
                i += 1
            elif c in "]}":
                self.depth -= 1
                i += 1
            elif c == "#":
                return self.depth == 0 and self.string is None, _text(line[i:])
            else:
                i += 1
        if self.string in ('"', "'"):  # a one-line string cannot continue (valid TOML)
            self.string = None
        return self.depth == 0 and self.string is None, None


def read_comments(text: str) -> FileComments:
    """The comments of the TOML ``text`` by the key or table they annotate (module docstring)."""
    out = FileComments()
    table: Path = ()
    arrays: dict[tuple[str, ...], int] = {}  # array-of-tables path (names only) -> elements seen
    pending: list[str] = []
    last: KeyComments | None = None  # the item an indented comment line continues
    seen_item = False
    scanner: _Scanner | None = None  # a value spanning lines
    value_comments: KeyComments | None = None

    def resolve(names: list[str]) -> Path:
        """A header's path: each array-of-tables prefix indexed by its current element."""
        path: list = []
        for name in names:
            path.append(name)
            key = tuple(p for p in path if isinstance(p, str))
            if key in arrays:
                path.append(arrays[key] - 1)
        return tuple(path)

    def item(path: Path) -> KeyComments:
        nonlocal pending, seen_item
        entry = out.keys.setdefault(path, KeyComments())
        entry.before += pending
        pending = []
        seen_item = True
        return entry

    for line in text.splitlines():
        stripped = line.strip()
        if scanner is not None:  # inside a multi-line value
            done, comment = scanner.scan(line, 0)
            if comment is not None and value_comments is not None:
                value_comments.inline.append(comment)
            if done:
                scanner = None
            continue
        if not stripped:
            if not seen_item and pending and not out.preamble:
                out.preamble, pending = pending, []
            last = None
            continue
        if stripped.startswith("#"):
            if last is not None and line[:1] in (" ", "\t"):
                last.inline.append(_text(stripped))
            else:
                pending.append(_text(stripped))
                last = None
            continue
        if stripped.startswith("["):
            array = stripped.startswith("[[")
            close = stripped.index("]]" if array else "]")
            names = _split_keys(stripped[2 if array else 1 : close])
            if array:
                key = tuple(names)
                arrays[key] = arrays.get(key, 0) + 1
                # a new element forgets the indices of the arrays nested in the previous one
                for other in [a for a in arrays if len(a) > len(key) and a[: len(key)] == key]:
                    del arrays[other]
            table = resolve(names)
            entry = item(table)
            rest = stripped[close + (2 if array else 1) :].strip()
            if rest.startswith("#"):
                entry.inline.append(_text(rest))
            last = entry
            continue
        equals = _key_end(line)
        path = table + tuple(_split_keys(line[:equals]))
        entry = item(path)
        scanner = _Scanner()
        done, comment = scanner.scan(line, equals + 1)
        if comment is not None:
            entry.inline.append(comment)
        if done:
            scanner = None
            value_comments = None
        else:
            value_comments = entry
        last = entry
    out.trailing = pending
    return out


def _key_end(line: str) -> int:
    """Index of the ``=`` that ends the key of a key/value line (quotes in the key skipped)."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            if c == quote:
                quote = None
        elif c in "\"'":
            quote = c
        elif c == "=":
            return i
    raise ValueError(f"not a key/value line: {line!r}")
