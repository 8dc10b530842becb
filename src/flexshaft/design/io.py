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
import types
import typing
from collections.abc import Mapping
from dataclasses import dataclass
from importlib import resources
from typing import Any, Literal, Union

from pydantic import BaseModel, ValidationError

from flexshaft.design.reading import read_design_bytes, text_problems
from flexshaft.design.schema import (
    LAYUP_ERROR_TYPE,
    PROBLEMS_ERROR_TYPE,
    Design,
    format_value,
)

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
    "tuned_design",
    "with_overrides",
]

#: Designs packaged with flexshaft, by name: the file in ``flexshaft/design`` and what it is
#: (docs/thesis-reproduction.md). ``"baseline"`` is the thesis's Table 3.1 study configuration.
EMBEDDED_DESIGNS: dict[str, tuple[str, str]] = {
    "baseline": ("baseline.toml", "thesis Table 3.1 study configuration (K_p 1e7 N/m, K_d 0); fails its requirements"),
    "tuned": ("tuned.toml", "tuned final design: Table 3.1 driveline with spin-up-tuned actuator gains; passes"),
    "current": ("current_driveline.toml", "today's segmented aluminium driveline of the same boom, power and speed "
                                          "(five tubes, four disc couplings, four hangers, a damper); passes"),
}
#: The embedded design ``flexshaft run`` analyses when given no design file.
DEFAULT_DESIGN = "tuned"


@dataclass(frozen=True)
class Problem:
    """One input problem: where (a field path such as ``bearings[2].x``, or a file) and what."""

    path: str
    message: str

    def __str__(self) -> str:
        return f"{self.path}: {self.message}"


class DesignError(ValueError):
    """A design file or design override that cannot be accepted.

    Attributes
    ----------
    problems
        Every problem found, each with a field path and a message.
    source
        The file the design came from, ``"<string>"`` or ``"<overrides>"``.
    """

    def __init__(self, problems: list[Problem] | tuple[Problem, ...], source: str = "<string>") -> None:
        unique = tuple(dict.fromkeys(Problem(_one_line(p.path), _one_line(p.message)) for p in problems))
        self.problems: tuple[Problem, ...] = unique
        self.source = source
        super().__init__("\n".join(str(problem) for problem in unique))

    def __reduce__(self) -> tuple[Any, ...]:  # picklable across worker processes
        return (type(self), (self.problems, self.source))


_LINE_BREAKS = re.compile("[\x00-\x1f\x7f\x85\u2028\u2029]")


def _one_line(text: str) -> str:
    """Escape control and line-break characters so that each problem stays on one line."""
    return _LINE_BREAKS.sub(lambda match: match.group().encode("unicode_escape").decode("ascii"), text)


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
        raise DesignError(_problems_from_validation(error, data), source) from None


def embedded_text(name: str) -> str:
    """The TOML text of a packaged design (a key of :data:`EMBEDDED_DESIGNS`).

    Raises
    ------
    DesignError
        When ``name`` is not a packaged design (the message lists the names allowed).
    """
    if not isinstance(name, str) or name not in EMBEDDED_DESIGNS:
        allowed = ", ".join(EMBEDDED_DESIGNS)
        raise DesignError([Problem("<embedded design>", f"no such embedded design (got {format_value(name)}; allowed: {allowed})")])
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


def _plain(value: Any) -> Any:
    """Deep copy into plain dicts/lists/scalars (numpy scalars and arrays become Python)."""
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


def _set_path(data: dict[str, Any], path: str, value: Any) -> Problem | None:
    parts = _parse_path(path)
    if parts is None:
        shown = path if re.fullmatch(r"[\x21-\x7e]+", path) else format_value(path)
        return Problem(
            shown,
            'malformed override path (expected keys joined by "." with optional [index], e.g. bearings[1].kp)',
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
            walked += f".{_key_text(part)}" if walked else _key_text(part)
        container = container[part]
    return None


# ------------------------------------------------------------------------------------------------
# Helpers: pydantic errors -> problems


@dataclass
class _Located:
    path: str
    annotation: Any  # type expected at the location (None if unknown)
    parent: Any  # model class or container type holding the location
    union: Any  # tagged union of models found at the location, if any
    keys: tuple[Any, ...]  # the location in the input data (union tags dropped)
    limits: dict[str, Any]  # bounds (ge, gt, le, lt) and unit of a number at the location


def _strip(annotation: Any) -> Any:
    """Remove Annotated and Optional wrappers."""
    while True:
        origin = typing.get_origin(annotation)
        if origin is typing.Annotated:
            annotation = typing.get_args(annotation)[0]
        elif origin in (Union, types.UnionType):
            members = [arg for arg in typing.get_args(annotation) if arg is not type(None)]
            if len(members) != 1:
                return annotation
            annotation = members[0]
        else:
            return annotation


def _is_model(annotation: Any) -> bool:
    return isinstance(annotation, type) and issubclass(annotation, BaseModel)


def _union_models(annotation: Any) -> list[type[BaseModel]]:
    if typing.get_origin(annotation) in (Union, types.UnionType):
        return [arg for arg in typing.get_args(annotation) if _is_model(arg)]
    return []


def _kind_of(model: type[BaseModel]) -> str:
    return str(typing.get_args(model.model_fields["kind"].annotation)[0])


def _key_text(key: str) -> str:
    return key if re.fullmatch(r"[A-Za-z0-9_-]+", key) else format_value(key)


def _locate(loc: tuple[Any, ...]) -> _Located:
    """Follow a pydantic error location through the schema, dropping union tags from the path."""
    path = ""
    annotation: Any = Design
    parent: Any = None
    keys: list[Any] = []
    field_info: Any = None  # the model field's FieldInfo when the last step was a model field
    for part in loc:
        current = _strip(annotation)
        union = _union_models(current)
        if union:
            matches = [model for model in union if _kind_of(model) == part]
            if matches:
                annotation = matches[0]
                continue
        if part == "[key]" and typing.get_origin(_strip(parent)) is dict:  # the key itself is invalid
            annotation = typing.get_args(_strip(parent))[0]
            continue
        parent = current
        keys.append(part)
        field_info = None
        if isinstance(part, int):
            path += f"[{part}]"
            args = typing.get_args(current)
            if typing.get_origin(current) in (tuple, list) and args:
                variadic = len(args) == 2 and args[1] is Ellipsis
                annotation = args[0] if variadic else args[min(part, len(args) - 1)]
            else:
                annotation = None
            continue
        key = str(part)
        path += ("." if path else "") + _key_text(key)
        if _is_model(current):
            field_info = current.model_fields.get(key)
            annotation = None if field_info is None else field_info.annotation
        elif typing.get_origin(current) is dict:
            annotation = typing.get_args(current)[1]
        else:
            annotation = None
    final = _strip(annotation)
    limits = _limits(field_info, annotation)
    return _Located(path, final, parent, final if _union_models(final) else None, tuple(keys), limits)


def _limits(field_info: Any, annotation: Any) -> dict[str, Any]:
    """Bounds (``ge``, ``gt``, ``le``, ``lt``) and ``unit`` of a number field, from its FieldInfo
    and from the Annotated metadata of its (optional) type."""
    infos = [field_info] if field_info is not None else []
    while True:
        origin = typing.get_origin(annotation)
        if origin is typing.Annotated:
            args = typing.get_args(annotation)
            infos += [arg for arg in args[1:] if hasattr(arg, "metadata")]
            annotation = args[0]
        elif origin in (Union, types.UnionType):
            members = [arg for arg in typing.get_args(annotation) if arg is not type(None)]
            if len(members) != 1:
                break
            annotation = members[0]
        else:
            break
    limits: dict[str, Any] = {}
    for info in infos:
        for constraint in info.metadata:
            for key in ("ge", "gt", "le", "lt"):
                if getattr(constraint, key, None) is not None:
                    limits[key] = getattr(constraint, key)
        extra = info.json_schema_extra if isinstance(info.json_schema_extra, dict) else {}
        if "unit" in extra:
            limits["unit"] = extra["unit"]
    return limits


def _allowed_range(limits: dict[str, Any]) -> str:
    """``"; allowed: [1e-05, 1] m"`` for a number bounded on both sides, else empty."""
    low = ("[", limits["ge"]) if "ge" in limits else ("(", limits["gt"]) if "gt" in limits else None
    high = ("]", limits["le"]) if "le" in limits else (")", limits["lt"]) if "lt" in limits else None
    if low is None or high is None:
        return ""
    unit = limits.get("unit", "-")
    unit = "" if unit == "-" else f" {unit}"
    return f"; allowed: {low[0]}{low[1]:g}, {high[1]:g}{high[0]}{unit} (see docs/limits.md)"


def _describe_type(annotation: Any) -> str:
    annotation = _strip(annotation)
    origin = typing.get_origin(annotation)
    if annotation is float:
        return "a number"
    if annotation is int:
        return "an integer"
    if annotation is bool:
        return "true or false"
    if annotation is str:
        return "a string"
    if origin is Literal:
        return "one of " + ", ".join(format_value(arg) for arg in typing.get_args(annotation))
    if origin is tuple:
        args = typing.get_args(annotation)
        if len(args) == 2 and args[1] is Ellipsis:
            inner = _describe_type(args[0])
            if inner.startswith("one of"):
                return f"an array of values, each {inner}"
            return f"an array of {inner}" if not inner.startswith("a table") else "an array of tables"
        return f"an array of {len(args)} {_plural(_describe_type(args[0]))}"
    if origin is dict:
        return "a table"
    if _is_model(annotation) or _union_models(annotation):
        return "a table"
    return "a value"


def _plural(description: str) -> str:
    plurals = {"a number": "numbers", "an integer": "integers", "a string": "strings"}
    return plurals.get(description, description)


def _got(value: Any) -> str:
    """The offending value, saying so when its type is the surprise (a string or a boolean)."""
    text = format_value(value)
    if isinstance(value, bool):
        return f"{text}, a boolean"
    if isinstance(value, str):
        return f"{text}, a string"
    return text


def _lookup(data: Any, keys: tuple[Any, ...]) -> Any:
    """The input value at ``keys``, or None if it cannot be found."""
    for key in keys:
        if isinstance(data, Mapping) and key in data:
            data = data[key]
        elif isinstance(data, (list, tuple)) and isinstance(key, int) and 0 <= key < len(data):
            data = data[key]
        else:
            return None
    return data


def _problems_from_validation(error: ValidationError, data: Any) -> list[Problem]:
    problems: list[Problem] = []
    for item in error.errors(include_url=False):
        loc = tuple(item["loc"])
        if item["type"] == PROBLEMS_ERROR_TYPE:
            for sub, message in item["ctx"]["problems"]:
                problems.append(Problem(_locate(loc + tuple(sub)).path or "design", message))
        else:
            problems.append(_translate(item, loc, data))
    return problems


def _translate(item: Any, loc: tuple[Any, ...], data: Any) -> Problem:
    kind = item["type"]
    ctx = item.get("ctx", {})
    value = item.get("input")
    located = _locate(loc)
    path = located.path or "design"

    if kind == "missing":
        parent = _strip(located.parent)
        if loc and isinstance(loc[-1], int) and typing.get_origin(parent) is tuple:
            count = len(typing.get_args(parent))
            return Problem(_locate(loc[:-1]).path, f"must have exactly {count} values (got {_got(value)})")
        return Problem(path, f"required key is missing (expected {_describe_type(located.annotation)})")
    if loc and loc[-1] == "[key]" and typing.get_origin(located.annotation) is Literal:
        allowed = ", ".join(str(arg) for arg in typing.get_args(located.annotation))
        return Problem(path, f"unknown key (got {_got(_lookup(data, located.keys))}; allowed: {allowed})")
    if kind == "extra_forbidden":
        parent = located.parent
        allowed = ", ".join(parent.model_fields) if _is_model(parent) else "none"
        return Problem(path, f"unknown key (got {_got(value)}; allowed: {allowed})")
    if kind in ("union_tag_invalid", "union_tag_not_found"):
        tags = ", ".join(format_value(_kind_of(model)) for model in (_union_models(located.annotation) or []))
        if not isinstance(value, dict):
            return Problem(path, f"must be a table (got {_got(value)})")
        tag_path = f"{path}.kind"
        if kind == "union_tag_not_found":
            return Problem(tag_path, f"required key is missing (allowed: {tags})")
        return Problem(tag_path, f"unknown kind (got {_got(value.get('kind'))}; allowed: {tags})")
    if kind == LAYUP_ERROR_TYPE:
        allowed = f"; allowed: {ctx['allowed']}" if ctx.get("allowed") else ""
        return Problem(path, f"{ctx.get('reason', item['msg'])} (got {_got(value)}{allowed})")
    if kind == "finite_number":
        return Problem(path, f"must be a finite number (got {_got(value)})")
    if kind in ("float_type", "float_parsing"):
        if isinstance(value, int) and not isinstance(value, bool):
            return Problem(path, f"is too large for a floating-point number (got {_got(value)})")
        return Problem(path, f"must be a number (got {_got(value)})")
    if kind in ("int_type", "int_parsing", "int_from_float"):
        return Problem(path, f"must be an integer (got {_got(value)})")
    comparisons = {"greater_than": ("gt", ">"), "greater_than_equal": ("ge", ">="),
                   "less_than": ("lt", "<"), "less_than_equal": ("le", "<=")}
    if kind in comparisons:
        key, symbol = comparisons[kind]
        bound = ctx.get(key)
        number = isinstance(value, (int, float)) and not isinstance(value, bool)
        if kind == "greater_than_equal" and number and isinstance(bound, (int, float)) and value <= 0 < bound:
            symbol, bound = ">", 0  # say first that the quantity is positive; the range follows
        shown = f"{bound:g}" if isinstance(bound, (int, float)) else format_value(bound)
        return Problem(path, f"must be {symbol} {shown} (got {_got(value)}){_allowed_range(located.limits)}")
    if kind == "bool_type":
        return Problem(path, f"must be true or false (got {_got(value)})")
    if kind == "string_type":
        return Problem(path, f"must be a string (got {_got(value)})")
    if kind == "string_too_short":
        return Problem(path, f"must not be empty (got {_got(value)})")
    if kind == "string_too_long":
        length = len(value) if isinstance(value, str) else "?"
        return Problem(path, f"is {length:,} characters long (got {_got(value)}; allowed: at most "
                             f"{ctx.get('max_length')} characters)")
    if kind == "literal_error":
        annotation = located.annotation
        if typing.get_origin(annotation) is Literal:
            allowed = ", ".join(format_value(arg) for arg in typing.get_args(annotation))
        else:
            allowed = str(ctx.get("expected", ""))
        return Problem(path, f"unknown value (got {_got(value)}; allowed: {allowed})")
    if kind in ("tuple_type", "list_type"):
        return Problem(path, f"must be {_describe_type(located.annotation)} (got {_got(value)})")
    if kind in ("too_short", "too_long"):
        annotation = located.annotation
        args = typing.get_args(annotation) if typing.get_origin(annotation) is tuple else ()
        if args and not (len(args) == 2 and args[1] is Ellipsis):
            return Problem(path, f"must have exactly {len(args)} values (got {_got(value)})")
        bound = ctx.get("min_length") if kind == "too_short" else ctx.get("max_length")
        word = "at least" if kind == "too_short" else "at most"
        return Problem(path, f"must have {word} {bound} items (got {ctx.get('actual_length', '?')})")
    if kind in ("dict_type", "model_type", "model_attributes_type", "mapping_type"):
        return Problem(path, f"must be a table (got {_got(value)})")
    return Problem(path, f"{item['msg']} (got {_got(value)})")
