"""The design-file reference, generated from the schema: Markdown for people, JSON Schema for editors.

Regenerate both committed files after changing the schema (``tests/test_docs.py`` fails until
they agree with it)::

    python -m flexshaft.design.reference > docs/design-reference.md
    python -m flexshaft.design.reference --json > docs/design.schema.json

Every table of the design file is a pydantic model of :mod:`flexshaft.design.schema`; every
key a field. What the reference shows for a key comes from the schema only:

* type, default, allowed range (the field's constraints, ``Literal`` choices, lengths);
* unit: the ``unit`` entry of the field's JSON-schema extras, else the first ``[unit]`` in its
  description;
* description: the field's ``description`` when it has its own, else its entry in the
  ``Attributes`` section of the model's numpydoc docstring; a description carried by the
  quantity's type (what its range means) is shown beside it.

Only pydantic, the standard library and the design package are imported: this module stays in
the design layer (a data leaf).

>>> from flexshaft.design.reference import design_tables
>>> [table.header for table in design_tables()][:4]
['(top level)', '[materials.<name>]', '[materials.<name>.temperature_table]', '[materials.<name>]']
"""

from __future__ import annotations

import functools
import inspect
import json
import operator
import re
import sys
import types
import typing
from dataclasses import dataclass
from typing import Annotated, Any, Literal, Union

from pydantic import BaseModel
from pydantic.fields import FieldInfo
from pydantic_core import PydanticUndefined

from flexshaft.design.schema import Design

__all__ = ["FieldDoc", "TableDoc", "design_json_schema", "design_reference", "design_tables", "main"]

#: JSON Schema dialect of the export (what pydantic generates).
JSON_SCHEMA_DIALECT = "https://json-schema.org/draft/2020-12/schema"

#: The commands that regenerate the committed files.
REGENERATE_MARKDOWN = "python -m flexshaft.design.reference > docs/design-reference.md"
REGENERATE_JSON = "python -m flexshaft.design.reference --json > docs/design.schema.json"


@dataclass(frozen=True)
class FieldDoc:
    """One key of a design-file table, as the reference shows it."""

    key: str
    type: str
    unit: str
    default: str
    allowed: str
    description: str
    note: str  # what the range of the quantity means, when its type says so


@dataclass(frozen=True)
class TableDoc:
    """One table of the design file (one model of the schema)."""

    header: str  # TOML header, e.g. "[[bearings]]"; "(top level)" for the file itself
    anchor: str  # HTML anchor of its section
    kind: str  # the ``kind`` of a tagged table ("lamina", "active", ...), else ""
    model: type[BaseModel]
    intro: str  # the model's docstring without its Attributes section, as Markdown
    fields: tuple[FieldDoc, ...]

    @property
    def title(self) -> str:
        return self.header + (f' with kind = "{self.kind}"' if self.kind else "")


# ------------------------------------------------------------------------------------------------
# Reading annotations


def _unwrap(annotation: Any) -> tuple[Any, list[Any]]:
    """(bare type, constraint and FieldInfo metadata) of a possibly ``Annotated`` type."""
    metadata: list[Any] = []
    while typing.get_origin(annotation) is Annotated:
        base, *extras = typing.get_args(annotation)
        for extra in extras:
            metadata.append(extra)
            if isinstance(extra, FieldInfo):
                metadata.extend(extra.metadata)
        annotation = base
    return annotation, metadata


def _optional(annotation: Any) -> tuple[Any, bool]:
    """(the non-None member, True) of ``X | None``; else (annotation, False)."""
    if typing.get_origin(annotation) in (Union, types.UnionType):
        members = [arg for arg in typing.get_args(annotation) if arg is not type(None)]
        if len(members) < len(typing.get_args(annotation)):
            return functools.reduce(operator.or_, members), True
    return annotation, False


def _models(annotation: Any) -> list[type[BaseModel]]:
    """The models of a model type or of a union of models (tagged tables)."""
    annotation, _ = _unwrap(annotation)
    if inspect.isclass(annotation) and issubclass(annotation, BaseModel):
        return [annotation]
    if typing.get_origin(annotation) in (Union, types.UnionType):
        found = [_models(arg) for arg in typing.get_args(annotation)]
        if all(found):
            return [model for group in found for model in group]
    return []


def _field_infos(metadata: list[Any]) -> list[FieldInfo]:
    return [item for item in metadata if isinstance(item, FieldInfo)]


def _number(value: float) -> str:
    text = f"{value:g}"
    return re.sub(r"e([+-])0*(\d)", lambda m: "e" + ("-" if m.group(1) == "-" else "") + m.group(2), text)


def _bounds(metadata: list[Any]) -> str:
    """Interval of the numeric constraints (ge, gt, le, lt), e.g. ``[0, 1)``; empty if none."""
    found: dict[str, float] = {}
    for item in metadata:
        for name in ("ge", "gt", "le", "lt"):
            value = getattr(item, name, None)
            if isinstance(value, (int, float)) and not isinstance(value, bool):
                found[name] = value
    extras = [info.json_schema_extra for info in _field_infos(metadata) if isinstance(info.json_schema_extra, dict)]
    for extra in extras:  # bounds a model checks itself, published for the JSON schema
        minimum, maximum = extra.get("minimum"), extra.get("maximum")
        if isinstance(minimum, (int, float)) and "ge" not in found and "gt" not in found:
            found["ge"] = minimum
        if isinstance(maximum, (int, float)) and "le" not in found and "lt" not in found:
            found["le"] = maximum
    low = ("[", found["ge"]) if "ge" in found else ("(", found["gt"]) if "gt" in found else None
    high = ("]", found["le"]) if "le" in found else (")", found["lt"]) if "lt" in found else None
    if low and high:
        return f"{low[0]}{_number(low[1])}, {_number(high[1])}{high[0]}"
    if low:
        return ("≥ " if low[0] == "[" else "> ") + _number(low[1])
    if high:
        return ("≤ " if high[0] == "]" else "< ") + _number(high[1])
    return ""


def _lengths(metadata: list[Any], noun: str) -> str:
    low = high = None
    for item in metadata:
        low = getattr(item, "min_length", None) if getattr(item, "min_length", None) is not None else low
        high = getattr(item, "max_length", None) if getattr(item, "max_length", None) is not None else high
    if low is not None and high is not None:
        return f"{low} to {high} {noun}"
    if low == 1:
        return "non-empty"
    if low is not None:
        return f"at least {low} {noun}"
    if high is not None:
        return f"at most {high} {noun}"
    return ""


def _unit_of(metadata: list[Any]) -> str:
    for info in _field_infos(metadata):
        if isinstance(info.json_schema_extra, dict) and "unit" in info.json_schema_extra:
            return str(info.json_schema_extra["unit"])
    return ""


def _type_description(metadata: list[Any]) -> str:
    for info in _field_infos(metadata):
        if info.description:
            return info.description
    return ""


@dataclass
class _Shape:
    """What one annotation says: type words, allowed values, unit and description of its type."""

    type: str
    allowed: list[str]
    unit: str = ""
    note: str = ""


_SCALARS = {
    bool: ("boolean", "booleans"),
    int: ("integer", "integers"),
    float: ("float", "floats"),
    str: ("string", "strings"),
}


def _shape(annotation: Any, links: dict[type[BaseModel], str], extra: tuple[Any, ...] = ()) -> _Shape:
    """``extra``: constraints given on the field itself (``x: T = Field(min_length=1)``)."""
    annotation, optional = _optional(annotation)
    base, metadata = _unwrap(annotation)
    metadata += list(extra)
    base, inner_optional = _optional(base)
    optional = optional or inner_optional
    if inner_optional:
        base, more = _unwrap(base)
        metadata += more
    unit, note = _unit_of(metadata), _type_description(metadata)
    origin = typing.get_origin(base)
    models = _models(base)
    if models:
        shape = _Shape("table", [" or ".join(f"[{_kind(m) or m.__name__}](#{links[m]})" for m in models)])
    elif base in _SCALARS:
        noun = "characters"
        allowed = [_bounds(metadata)] if base in (int, float) else [_lengths(metadata, noun)]
        shape = _Shape(_SCALARS[base][0], allowed)
    elif origin is Literal:
        values = typing.get_args(base)
        choices = ", ".join(f'`"{value}"`' for value in values)
        shape = _Shape("string", [f"one of {choices}" if len(values) > 1 else choices])
    elif origin is tuple:
        args = typing.get_args(base)
        variable = len(args) == 2 and args[1] is Ellipsis
        element = _shape(args[0], links)
        if _models(args[0]):
            shape = _Shape("array of tables", [element.allowed[0], _lengths(metadata, "tables")])
        else:
            count = "" if variable else f"{len(args)} "
            plural = _plural(element.type)
            each = [f"each {text}" for text in element.allowed if text]
            shape = _Shape(
                f"array of {count}{plural}",
                [_lengths(metadata, "items")] + each,
                unit or element.unit,
                note or element.note,
            )
    elif origin is dict:
        key, value = typing.get_args(base)
        key_base, _ = _unwrap(key)
        element = _shape(value, links)
        if _models(value):
            shape = _Shape("tables by name", [element.allowed[0], _lengths(metadata, "tables")])
        else:
            keys = (
                ", ".join(f"`{k}`" for k in typing.get_args(key_base))
                if typing.get_origin(key_base) is Literal
                else "any name"
            )
            each = [f"values {text}" for text in element.allowed if text]
            shape = _Shape(
                f"inline table of {_plural(element.type)}",
                [f"keys {keys}"] + each,
                unit or element.unit,
                note or element.note,
            )
    else:
        shape = _Shape(getattr(base, "__name__", str(base)), [])
    if not shape.unit:
        shape.unit = unit
    if not shape.note:
        shape.note = note
    if optional:
        shape.type += ", optional"
    return shape


def _plural(type_words: str) -> str:
    for singular, plural in _SCALARS.values():
        if type_words == singular:
            return plural
    return type_words + "s" if not type_words.endswith("s") else type_words


def _kind(model: type[BaseModel]) -> str:
    field = model.model_fields.get("kind")
    if field is not None and typing.get_origin(field.annotation) is Literal:
        return str(typing.get_args(field.annotation)[0])
    return ""


# ------------------------------------------------------------------------------------------------
# Reading docstrings


_SECTION = re.compile(r"^(?P<title>[A-Z][A-Za-z ]+)\n-{3,}\n", re.MULTILINE)


def _split_docstring(model: type) -> tuple[str, str]:
    """(prose, Attributes section body) of a class's own docstring."""
    doc = inspect.cleandoc(model.__dict__.get("__doc__") or "")
    prose, attributes = doc, ""
    for match in _SECTION.finditer(doc):
        if match.group("title") == "Attributes":
            prose = doc[: match.start()].rstrip()
            rest = doc[match.end() :]
            following = _SECTION.search(rest)
            attributes = rest[: following.start()] if following else rest
            break
    return prose, attributes


def _attribute_docs(model: type[BaseModel]) -> dict[str, str]:
    """Field name -> description from the numpydoc ``Attributes`` sections of the model and its bases."""
    docs: dict[str, str] = {}
    for cls in reversed(model.__mro__):
        _, section = _split_docstring(cls)
        name_line = re.compile(r"^(?P<names>[A-Za-z_][\w, ]*?)\s*:\s*.*$")
        entries: list[tuple[list[str], list[str]]] = []  # (the names of one entry, its description lines)
        for line in section.splitlines():
            match = name_line.match(line) if line and not line[0].isspace() else None
            if match:
                entries.append(([name.strip() for name in match.group("names").split(",")], []))
            elif entries:
                entries[-1][1].append(line)
        for names, lines in entries:
            text = " ".join(line.strip() for line in lines).strip()
            for name in names:
                docs[name] = text
    return docs


def _markdown(text: str) -> str:
    """reStructuredText roles and literals of a docstring as Markdown."""
    text = re.sub(
        r":[a-z]+:`~?([^`]+)`",
        lambda m: f"`{m.group(1).rpartition('.')[2] if '~' in m.group(0) else m.group(1)}`",
        text,
    )
    return text.replace("``", "`")


_UNIT = re.compile(r"\[(?P<unit>[^\[\],`<>]{1,40})\]")


def _unit_in(description: str) -> str:
    """The first bracketed unit of a description, outside code literals, e.g. ``[N/m]``."""
    plain = re.sub(r"``[^`]*``", "", description)
    match = _UNIT.search(plain)
    return match.group("unit").strip() if match else ""


# ------------------------------------------------------------------------------------------------
# Tables


def _default(info: FieldInfo) -> str:
    value = info.default
    if value is PydanticUndefined:
        return "required"
    return _toml(value)


def _toml(value: Any) -> str:
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return _number(value)
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, (tuple, list)):
        return "[" + ", ".join(_toml(item) for item in value) + "]"
    if isinstance(value, BaseModel):
        return "(its defaults)"
    if isinstance(value, dict):
        return "{}" if not value else "{" + ", ".join(f"{k} = {_toml(v)}" for k, v in value.items()) + "}"
    return str(value)


def _walk(model: type[BaseModel], path: str, array: bool, found: list[tuple[type[BaseModel], str]]) -> None:
    """Every (model, TOML header) reachable from ``model``, depth first, in field order."""
    header = "(top level)" if not path else (f"[[{path}]]" if array else f"[{path}]")
    found.append((model, header))
    for name, info in model.model_fields.items():
        annotation, _ = _optional(info.annotation)
        base, _ = _unwrap(annotation)
        origin = typing.get_origin(base)
        child = f"{path}.{name}" if path else name
        if origin is tuple and _models(typing.get_args(base)[0]):
            for sub in _models(typing.get_args(base)[0]):
                _walk(sub, child, True, found)
        elif origin is dict and _models(typing.get_args(base)[1]):
            for sub in _models(typing.get_args(base)[1]):
                _walk(sub, f"{child}.<name>", False, found)
        else:
            for sub in _models(base):
                _walk(sub, child, False, found)


def _anchor(header: str, kind: str) -> str:
    words = re.sub(r"[^a-z0-9]+", "-", header.lower().replace("<name>", "")).strip("-") or "top-level"
    return f"{words}-{kind}" if kind else words


def design_tables() -> list[TableDoc]:
    """Every table of the design file with its keys, in the order of the schema."""
    found: list[tuple[type[BaseModel], str]] = []
    _walk(Design, "", False, found)
    links = {model: _anchor(header, _kind(model)) for model, header in found}
    tables = []
    for model, header in found:
        hints = typing.get_type_hints(model, include_extras=True)
        docs = _attribute_docs(model)
        fields = []
        for name, info in model.model_fields.items():
            shape = _shape(hints[name], links, tuple(info.metadata))
            extras = info.json_schema_extra if isinstance(info.json_schema_extra, dict) else {}
            note = shape.note
            own = info.description if info.description and info.description != note else ""
            description = own or docs.get(name, "")
            fields.append(
                FieldDoc(
                    key=name,
                    type=shape.type,
                    unit=shape.unit or str(extras.get("unit", "")) or _unit_in(description),
                    default=_default(info),
                    allowed="; ".join(text for text in shape.allowed if text),
                    description=_markdown(description),
                    note=_markdown(note),
                )
            )
        prose, _ = _split_docstring(model)
        tables.append(TableDoc(header, links[model], _kind(model), model, _markdown(prose), tuple(fields)))
    return tables


# ------------------------------------------------------------------------------------------------
# Markdown


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ") or " "


_PREAMBLE = f"""\
# Design-file reference

<!-- Generated from the schema by `{REGENERATE_MARKDOWN}`; do not edit by hand. -->

A design file is a [TOML](https://toml.io) file validated by one schema
(`flexshaft.design.Design`). This page lists every table and key of it, generated from that
schema: the type, the unit, the default (*required* keys have none; *—* means omitted, i.e.
not set), the allowed values and what the key means.

* Units are SI (m, kg, s, N, Pa, W, K) except where the key says otherwise: `speed_rpm` is in
  rev/min, keys ending in `_c` in °C, `_deg` and the layup string in degrees, frequencies of
  active-bearing filters in Hz.
* Every number must be finite; floats are strict (`"3"` and `true` are refused; integers are
  accepted). Unknown keys are refused everywhere. Problems are reported before any
  computation, each with the field path, the value and what is allowed
  (`flexshaft check my_design.toml`).
* Checks that involve several keys (a bearing on the shaft, a material reference, exactly one
  of two keys) are stated in the descriptions.
* `flexshaft baseline > my_design.toml` prints an annotated example, the thesis baseline.

**Editor support.** [`design.schema.json`](design.schema.json) is the same schema as JSON
Schema ({JSON_SCHEMA_DIALECT.removeprefix("https://")}), with these descriptions and a `unit`
on each key. Editors with a TOML language server (Taplo, used by the *Even Better TOML*
extension of VS Code; Tombi) check a design file against it and show the descriptions on
hover when the file starts with a schema directive, a path relative to the design file or a
URL (flexshaft reads it as a comment):

```toml
#:schema ./design.schema.json
name = "my driveline"
```

Copy `docs/design.schema.json` beside your designs, or write it from an installed flexshaft
with `python -m flexshaft.design.reference --json > design.schema.json`. Without the directive,
a `.taplo.toml` rule does the same for a folder:

```toml
[[rule]]
include = ["designs/*.toml"]
schema = {{ path = "./design.schema.json" }}
```

The command line does the same check: `taplo check --schema file://$PWD/design.schema.json
my_design.toml`. The schema checks each key on its own (types, ranges, choices, unknown keys);
the checks across keys are made by `flexshaft check`.
"""


def design_reference() -> str:
    """The design-file reference as Markdown (``docs/design-reference.md``)."""
    tables = design_tables()
    out = [_PREAMBLE, "## Tables\n"]
    for table in tables:
        out.append(f"* [`{table.title}`](#{table.anchor})")
    out.append("")
    for table in tables:
        out.append(f'<a id="{table.anchor}"></a>\n')
        out.append("## Top level\n" if table.model is Design else f"## `{table.title}`\n")
        if table.intro:
            out.append(table.intro + "\n")
        out.append("| key | type | unit | default | allowed | description |")
        out.append("|---|---|---|---|---|---|")
        for field in table.fields:
            description = field.description
            if field.note:
                label = "Range" if "float" in field.type or "integer" in field.type else "Limit"
                description += f" *{label}:* {field.note.rstrip('.')}."
            out.append(
                "| "
                + " | ".join(
                    _cell(text)
                    for text in (f"`{field.key}`", field.type, field.unit, field.default, field.allowed, description)
                )
                + " |"
            )
        out.append("")
    return "\n".join(out).rstrip() + "\n"


# ------------------------------------------------------------------------------------------------
# JSON Schema


def design_json_schema() -> dict[str, Any]:
    """The schema as JSON Schema for editors (``docs/design.schema.json``).

    pydantic's export of :class:`~flexshaft.design.schema.Design`, with every property's
    description (as in the Markdown reference) and ``unit``, and each table's description.
    """
    schema = Design.model_json_schema(mode="validation")
    definitions = schema.get("$defs", {})
    for table in design_tables():
        node = schema if table.model is Design else definitions[table.model.__name__]
        if table.intro:
            node["description"] = table.intro
        for field in table.fields:
            prop = node["properties"][field.key]
            text = " ".join(
                part for part in (field.description, field.note.rstrip(".") + "." if field.note else "") if part
            )
            if text:
                prop["description"] = text
            if field.unit and "unit" not in prop:
                prop["unit"] = field.unit
    first = {"$schema": JSON_SCHEMA_DIALECT, "title": "flexshaft design file"}
    return {
        **first,
        **{key: value for key, value in schema.items() if key not in first and key != "$defs"},
        "$defs": definitions,
    }


def main(argv: list[str] | None = None) -> int:
    """``python -m flexshaft.design.reference [--json]``: print the reference or the JSON schema."""
    args = sys.argv[1:] if argv is None else argv
    if args not in ([], ["--json"]):
        print("usage: python -m flexshaft.design.reference [--json]", file=sys.stderr)
        return 2
    if args == ["--json"]:
        sys.stdout.write(json.dumps(design_json_schema(), indent=2, ensure_ascii=False) + "\n")
    else:
        sys.stdout.write(design_reference())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
