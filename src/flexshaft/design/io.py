"""Reading design files, and turning every input problem into one readable :class:`DesignError`.

Every entry point here (:func:`load_design`, :func:`loads_design`, :func:`design_from_dict`,
:func:`with_overrides`) either returns a validated :class:`~flexshaft.design.schema.Design` or
raises :class:`DesignError`; no pydantic ``ValidationError``, ``TOMLDecodeError`` or ``OSError``
escapes for bad user input. The error message lists every problem found, one per line::

    shaft.wall_thickness: must be less than outer_diameter/2 = 0.0508 m (got 0.06)
    bearings[2].x: 9.1 is outside the shaft [0.79, 8.05] m
    shaft.colour: unknown key (got "red"; allowed: x_start, x_end, ...)

File-level problems (missing file, non-UTF-8 bytes, TOML syntax) are reported with the file
name (or ``<string>``) in place of the field path, plus the line and column where known.
"""

from __future__ import annotations

import copy
import os
import re
import tomllib
from collections.abc import Mapping, Sequence
from importlib import resources
from typing import Any

from pydantic import BaseModel, ValidationError

from flexshaft.design.messages import key_text, problems_from_validation
from flexshaft.design.problems import DesignError, Problem
from flexshaft.design.reading import read_design_bytes, text_problems
from flexshaft.design.schema import Design, format_value

__all__ = [
    "DEFAULT_DESIGN",
    "EMBEDDED_DESIGNS",
    "DesignError",
    "Problem",
    "baseline_design",
    "baseline_text",
    "design_from_dict",
    "embedded_design",
    "embedded_text",
    "load_design",
    "loads_design",
    "path_replaces",
    "paths_overlap",
    "tuned_design",
    "value_at_path",
    "with_overrides",
]

#: Designs packaged with flexshaft, by name: the file in ``flexshaft/design`` and what it is
#: (docs/thesis-reproduction.md). ``"baseline"`` is the thesis's Table 3.1 study configuration.
EMBEDDED_DESIGNS: dict[str, tuple[str, str]] = {
    "baseline": ("baseline.toml", "thesis Table 3.1 study configuration (K_p 1e7 N/m, K_d 0); fails its requirements"),
    "tuned": ("tuned.toml", "tuned final design: Table 3.1 driveline with spin-up-tuned actuator gains; passes"),
    "current": (
        "current_driveline.toml",
        "today's segmented aluminium driveline of the same boom, power and speed "
        "(five tubes, four disc couplings, four hangers, a damper); passes",
    ),
}
#: The embedded design ``flexshaft run`` analyses when given no design file.
DEFAULT_DESIGN = "tuned"


# ------------------------------------------------------------------------------------------------
# Public entry points


def loads_design(text: str | bytes, source: str = "<string>") -> Design:
    """Parse and validate a design from TOML text.

    Parameters
    ----------
    text
        The TOML document (``bytes`` are decoded as UTF-8).
    source
        Name used for the document in error messages.

    Raises
    ------
    DesignError
        On a TOML syntax error or any schema violation.
    """
    if isinstance(text, (bytes, bytearray)):
        text = _decode(bytes(text), source)
    if not isinstance(text, str):
        raise DesignError([Problem(source, f"expected TOML text, got {type(text).__name__}")], source)
    refused = text_problems(text)
    if refused:
        raise DesignError([Problem(source, reason) for reason in refused], source)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise DesignError([Problem(source, f"TOML syntax error: {error}")], source) from None
    except RecursionError:
        raise DesignError([Problem(source, "TOML syntax error: values nested too deeply")], source) from None
    return design_from_dict(data, source)


def load_design(path: str | os.PathLike[str]) -> Design:
    """Read, parse and validate a design file [TOML, UTF-8].

    Only a regular file of at most 1 MB is read (:mod:`flexshaft.design.reading`: a device such
    as ``/dev/zero`` or a FIFO is refused without reading or blocking).

    Raises
    ------
    DesignError
        When the file cannot be read, is not a regular file, is too large, is not UTF-8 text,
        is not valid TOML or breaks the schema.
    """
    try:
        source = os.fsdecode(path)
    except TypeError:
        raise DesignError([Problem("<path>", f"expected a file path, got {format_value(path)}")]) from None
    try:
        raw = read_design_bytes(path)
    except FileNotFoundError:
        raise DesignError([Problem(source, "no such design file")], source) from None
    except IsADirectoryError:
        raise DesignError([Problem(source, "is a directory, not a design file")], source) from None
    except PermissionError:
        raise DesignError([Problem(source, "permission denied")], source) from None
    except ValueError as error:  # not a regular file, too large
        raise DesignError([Problem(source, str(error))], source) from None
    except OSError as error:
        raise DesignError([Problem(source, f"cannot read the file ({error})")], source) from None
    return loads_design(_decode(raw, source), source)


def design_from_dict(data: Any, source: str = "<dict>") -> Design:
    """Validate a design given as nested dicts and lists (the parsed TOML document).

    Raises
    ------
    DesignError
        Listing every schema violation with its field path.
    """
    try:
        return Design.model_validate(data)
    except ValidationError as error:
        raise DesignError(problems_from_validation(error, data), source) from None


def embedded_text(name: str) -> str:
    """The TOML text of a packaged design (a key of :data:`EMBEDDED_DESIGNS`).

    Raises
    ------
    DesignError
        When ``name`` is not a packaged design (the message lists the names allowed).
    """
    if not isinstance(name, str) or name not in EMBEDDED_DESIGNS:
        allowed = ", ".join(EMBEDDED_DESIGNS)
        raise DesignError(
            [Problem("<embedded design>", f"no such embedded design (got {format_value(name)}; allowed: {allowed})")]
        )
    filename = EMBEDDED_DESIGNS[name][0]
    return resources.files("flexshaft.design").joinpath(filename).read_text(encoding="utf-8")


def embedded_design(name: str) -> Design:
    """A packaged design by name, validated: ``"baseline"`` (thesis Table 3.1) or ``"tuned"``.

    Raises
    ------
    DesignError
        When ``name`` is not a packaged design.
    """
    return loads_design(embedded_text(name), source=EMBEDDED_DESIGNS[name][0])


def baseline_text() -> str:
    """The packaged thesis-baseline design file (thesis Table 3.1 configuration), as TOML text."""
    return embedded_text("baseline")


def baseline_design() -> Design:
    """The packaged thesis-baseline design (thesis Table 3.1, K_p 1e7, K_d 0; docs/thesis-reproduction.md)."""
    return embedded_design("baseline")


def tuned_design() -> Design:
    """The packaged tuned final design (the default of ``flexshaft run``), validated."""
    return embedded_design("tuned")


def with_overrides(design: Design, overrides: Mapping[str, Any]) -> Design:
    """A new validated design with some values replaced.

    Parameters
    ----------
    design
        The design to start from (left unchanged).
    overrides
        Field paths mapped to new values in SI units, e.g.
        ``{"shaft.wall_thickness": 0.002, "bearings[1].kp": 2e6, "shaft.layup": "(45/-45)s"}``.
        Paths use dots for table keys and ``[i]`` for list items; a key containing dots or
        brackets can be quoted: ``materials."my.ply".E_L``. A value of ``None`` removes an
        optional key (e.g. ``{"tailboom": None}``). numpy scalars and arrays are accepted.

    Raises
    ------
    DesignError
        When a path does not exist in the design, or the result breaks the schema.
    """
    source = "<overrides>"
    if not isinstance(overrides, Mapping):
        message = f"overrides must be a mapping of path to value, got {format_value(overrides)}"
        raise DesignError([Problem(source, message)], source)
    data = _plain(design.model_dump(mode="python"))
    problems: list[Problem] = []
    for path, value in overrides.items():
        if not isinstance(path, str):
            problems.append(Problem(format_value(path), "override path must be a string"))
            continue
        problem = _set_path(data, path, _plain(value))
        if problem is not None:
            problems.append(problem)
    if problems:
        raise DesignError(problems, source)
    return design_from_dict(data, source)


# ------------------------------------------------------------------------------------------------
# Helpers: file decoding, override paths


def _decode(raw: bytes, source: str) -> str:
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        line = raw[: error.start].count(b"\n") + 1
        message = f"not UTF-8 text: invalid byte {raw[error.start]:#04x} at line {line} (byte {error.start})"
        raise DesignError([Problem(source, message)], source) from None


#: Immutable leaf types, returned as they are (``copy.deepcopy`` would return them unchanged).
_ATOMS = frozenset({str, int, float, bool, complex, type(None)})


def _plain(value: Any) -> Any:
    """Deep copy into plain dicts/lists/scalars (numpy scalars and arrays become Python)."""
    kind = type(value)
    if kind in _ATOMS:  # most of a design's values (a sweep copies the whole design per point)
        return value
    if kind is dict:
        return {key: _plain(item) for key, item in value.items()}
    if isinstance(value, BaseModel):
        return _plain(value.model_dump(mode="python"))
    if isinstance(value, Mapping):
        return {key: _plain(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(item) for item in value]
    if type(value).__module__ == "numpy" and hasattr(value, "tolist"):
        plain = value.tolist()
        if type(plain).__module__ == "numpy":  # np.longdouble.tolist() is itself: keep its float value
            return _numpy_scalar(plain)
        return _plain(plain)
    return copy.deepcopy(value)


def _numpy_scalar(value: Any) -> Any:
    """A Python number for a numpy scalar that ``tolist`` leaves as numpy (extended precision)."""
    kind = getattr(getattr(value, "dtype", None), "kind", "")
    if kind == "f":
        return float(value)
    if kind == "c":
        return complex(value)
    return value  # left to the schema, which names the field and the type


_PATH_TOKEN = re.compile(r'(?P<key>[^.\[\]"\s]+)|"(?P<quoted>[^"]*)"|\[\s*(?P<index>\d+)\s*\]|(?P<dot>\.)')


def _parse_path(path: str) -> list[str | int] | None:
    """Split ``a.b[2]."c.d"`` into ["a", "b", 2, "c.d"]; None if malformed."""
    parts: list[str | int] = []
    position = 0
    expect_key = True  # a key must come first and after every dot
    while position < len(path):
        match = _PATH_TOKEN.match(path, position)
        if match is None:
            return None
        if match.group("dot") is not None:
            if expect_key:
                return None
            expect_key = True
        elif match.group("index") is not None:
            if expect_key:
                return None
            parts.append(int(match.group("index")))
        else:
            if not expect_key:
                return None
            key = match.group("key") if match.group("key") is not None else match.group("quoted")
            parts.append(key)
            expect_key = False
        position = match.end()
    return None if expect_key or not parts else parts


def paths_overlap(first: str, second: str) -> bool:
    """Whether two override paths of :func:`with_overrides` reach the same value, in either
    order: the same field however written (``shaft."wall_thickness"``, ``bearings[01]``) or a
    table and a key inside it (:func:`path_replaces` says which replaces which). A malformed
    path overlaps nothing (:func:`with_overrides` reports it)."""
    return path_replaces(first, second) or path_replaces(second, first)


def path_replaces(later: str, earlier: str) -> bool:
    """Whether override path ``later``, applied after ``earlier``, replaces the value ``earlier``
    set: the same field however written, or a table holding it. A key inside a table set
    earlier refines that table (its other keys stay), which is not a replacement."""
    a, b = _parse_path(later), _parse_path(earlier)
    return a is not None and b is not None and len(a) <= len(b) and b[: len(a)] == a


def value_at_path(data: Any, path: str | Sequence[str | int], missing: Any = None) -> Any:
    """The value at a design path of a model dump (``a.b[2]."c.d"``, the grammar of
    :func:`with_overrides`: a quoted key may hold dots; or the path's keys and indices, already
    split), or ``missing`` when the path is malformed or absent from ``data``."""
    parts = _parse_path(path) if isinstance(path, str) else list(path)
    if parts is None:
        return missing
    for part in parts:
        if isinstance(part, int):
            if not isinstance(data, list) or part >= len(data):
                return missing
        elif not isinstance(data, Mapping) or part not in data:
            return missing
        data = data[part]
    return data


def _set_path(data: dict[str, Any], path: str, value: Any) -> Problem | None:
    parts = _parse_path(path)
    if parts is None:
        shown = path if re.fullmatch(r"[\x21-\x7e]+", path) else format_value(path)
        return Problem(
            shown, 'malformed override path (expected keys joined by "." with optional [index], e.g. bearings[1].kp)'
        )
    container: Any = data
    walked = ""
    for depth, part in enumerate(parts):
        last = depth == len(parts) - 1
        if isinstance(part, int):
            if not isinstance(container, list):
                return Problem(path, f"{walked or 'the design'} is not a list, cannot index [{part}]")
            if part >= len(container):
                return Problem(path, f"index {part} is out of range ({walked} has {len(container)} items)")
            if last:
                container[part] = value
                return None
            walked += f"[{part}]"
        else:
            if container is None:
                message = f"{walked} is not present in this design; override the whole table instead"
                return Problem(path, message)
            if not isinstance(container, dict):
                return Problem(path, f"{walked} is not a table, it has no key {format_value(part)}")
            if last:
                container[part] = value  # an unknown key is refused by the schema, naming its path
                return None
            if part not in container:
                allowed = ", ".join(str(key) for key in container)
                where = walked or "the design"
                return Problem(path, f"no such key {format_value(part)} in {where} (allowed: {allowed})")
            walked += f".{key_text(part)}" if walked else key_text(part)
        container = container[part]
    return None
