"""Pydantic validation errors worded as design-file problems.

:func:`problems_from_validation` turns each error of a :class:`pydantic.ValidationError` into a
:class:`~flexshaft.design.problems.Problem` with the TOML path of the field (``bearings[2].x``),
what was expected, the value found and the allowed range (from the schema's own limits).
"""

from __future__ import annotations

import re
import types
import typing
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, Literal, Union

from pydantic import BaseModel, ValidationError

from flexshaft.design.problems import Problem
from flexshaft.design.schema import LAYUP_ERROR_TYPE, PROBLEMS_ERROR_TYPE, Design, format_value

__all__ = ["key_text", "problems_from_validation"]


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


def key_text(key: str) -> str:
    """A TOML key as written in a field path: bare if it can be, else quoted."""
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
        path += ("." if path else "") + key_text(key)
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


def problems_from_validation(error: ValidationError, data: Any) -> list[Problem]:
    problems: list[Problem] = []
    for item in error.errors(include_url=False):
        loc = tuple(item["loc"])
        if item["type"] == PROBLEMS_ERROR_TYPE:
            for sub, message in item["ctx"]["problems"]:
                problems.append(Problem(_locate(loc + tuple(sub)).path or "design", message))
        elif _short_only_by_invalid_items(item):
            continue
        else:
            problems.append(_translate(item, loc, data))
    return problems


def _short_only_by_invalid_items(item: Any) -> bool:
    """Whether a list reported too short has enough items, only some of them invalid.

    pydantic counts the items that validated (``bearings: must have at least 1 items (got 0)``
    for a single bearing with a bad field); the items' own problems say what is wrong.
    """
    value = item.get("input")
    minimum = item.get("ctx", {}).get("min_length")
    if item["type"] != "too_short" or not isinstance(value, (list, tuple)) or minimum is None:
        return False
    return len(value) >= minimum


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
    comparisons = {
        "greater_than": ("gt", ">"),
        "greater_than_equal": ("ge", ">="),
        "less_than": ("lt", "<"),
        "less_than_equal": ("le", "<="),
    }
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
        return Problem(
            path,
            f"is {length:,} characters long (got {_got(value)}; allowed: at most {ctx.get('max_length')} characters)",
        )
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
        actual = len(value) if isinstance(value, (list, tuple, dict)) else ctx.get("actual_length", "?")
        return Problem(path, f"must have {word} {bound} items (got {actual})")
    if kind in ("dict_type", "model_type", "model_attributes_type", "mapping_type"):
        return Problem(path, f"must be a table (got {_got(value)})")
    return Problem(path, f"{item['msg']} (got {_got(value)})")
