"""The report states its inputs: the design file verbatim, its assumed values, a factual title.

The shipped baseline marks the values the thesis lost with "assumed" (and fitted ones with
"calibrated") in end-of-line comments; :func:`marked_inputs` finds every such value in any
design file, so a user's own file shows whatever it marks. The scan reads TOML lines, not the
TOML grammar: a marker on a table header marks every key of that table, a marker on the
continuation line of a multi-line value marks the key it continues, and comment-only lines are
ignored.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass

from flexshaft.report.html import Preformatted, Section, Table
from flexshaft.units import rad_s_to_rpm

__all__ = ["MARKERS", "MarkedInput", "inputs_section", "marked_inputs", "report_title"]

#: Comment words that mark an input as not data.
MARKERS = ("assumed", "calibrated")
_MARKER = re.compile(r"\b(" + "|".join(MARKERS) + r")\b", re.IGNORECASE)
_HEADER = re.compile(r"^\s*(\[\[?)\s*([^\[\]]+?)\s*\]\]?\s*(?:#.*)?$")
_KEY = re.compile(r'^\s*((?:[A-Za-z0-9_\-]+|"[^"]*"|\'[^\']*\')(?:\s*\.\s*(?:[A-Za-z0-9_\-]+|"[^"]*"))*)\s*=(.*)$')


@dataclass(frozen=True)
class MarkedInput:
    """A design-file value marked in its comment.

    Attributes
    ----------
    key : str
        Dotted path, array-of-tables elements by name (``bearings[amb_1].gap``) or index.
    value : str
        The value as written in the file.
    marker : str
        "assumed" or "calibrated".
    comment : str
        The comment that marks it.
    line : int
        Line number in the file (1-based).
    """

    key: str
    value: str
    marker: str
    comment: str
    line: int


def _split_comment(line: str) -> tuple[str, str]:
    """(code, comment) of one TOML line; a # inside a string is not a comment."""
    quote = None
    i = 0
    while i < len(line):
        char = line[i]
        if quote:
            if char == "\\" and quote == '"':
                i += 1
            elif char == quote:
                quote = None
        elif char in "\"'":
            quote = char
        elif char == "#":
            return line[:i], line[i + 1 :].strip()
        i += 1
    return line, ""


class _Element:
    """Label of the current table or array-of-tables element, resolved once its name is read."""

    def __init__(self, path: str, index: int | None):
        self.path, self.index = path, index
        self.name: str | None = None

    def label(self) -> str:
        if self.index is None:
            return self.path
        return f"{self.path}[{self.name if self.name is not None else self.index}]"


def marked_inputs(text: str) -> list[MarkedInput]:
    """Every value of a design file whose comment says "assumed" or "calibrated".

    Parameters
    ----------
    text : str
        The design file (TOML).

    Returns
    -------
    list of MarkedInput
        In file order.
    """
    found: list[tuple[_Element, str, str, str, str, int]] = []
    table = _Element("", None)
    table_marker = ""
    table_comment = ""
    counts: dict[str, int] = {}
    last_key: tuple[str, str] | None = None
    for number, line in enumerate(text.splitlines(), 1):
        code, comment = _split_comment(line)
        if not code.strip():
            continue  # blank or comment-only line
        marker = _MARKER.search(comment)
        header = _HEADER.match(line) if code.strip().startswith("[") and "=" not in code else None
        if header:
            path = re.sub(r"\s*\.\s*", ".", header.group(2))
            if header.group(1) == "[[":
                counts[path] = counts.get(path, 0) + 1
                table = _Element(path, counts[path] - 1)
            else:
                table = _Element(path, None)
            table_marker = marker.group(1).lower() if marker else ""
            table_comment = comment if marker else ""
            last_key = None
            continue
        key_match = _KEY.match(code)
        if key_match:
            key = re.sub(r"\s*\.\s*", ".", key_match.group(1)).strip("\"'")
            value = key_match.group(2).strip()
            if key == "name" and table.index is not None:
                table.name = value.strip("\"'")
            last_key = (key, value)
            if marker:
                found.append((table, key, value, marker.group(1).lower(), comment, number))
            elif table_marker:
                found.append((table, key, value, table_marker, f"table: {table_comment}", number))
        elif marker and last_key is not None:  # continuation line of a multi-line value
            found.append((table, last_key[0], last_key[1] + " ...", marker.group(1).lower(), comment, number))
    out = []
    for element, key, value, kind, comment, number in found:
        prefix = element.label()
        if key == "name" and element.index is not None:  # a marked name marks its whole table
            out.append(MarkedInput(prefix, "(the whole table)", kind, comment, number))
            continue
        out.append(MarkedInput(f"{prefix}.{key}" if prefix else key, value, kind, comment, number))
    return out


def report_title(design) -> str:
    """A title from what the design is: layup, material, section, speed, power, supports."""
    shaft = design.shaft
    material = f"{shaft.layup} {shaft.material}" if shaft.layup else f"{shaft.material} (isotropic)"
    actives = sum(b.kind == "active" for b in design.bearings)
    support = "on a flexible tailboom" if design.tailboom is not None else "on rigid supports"
    return (
        f"{material} shaft, Ø {shaft.outer_diameter * 1e3:.1f} mm × {shaft.wall_thickness * 1e3:.2f} mm wall, "
        f"{rad_s_to_rpm(design.operating.speed_rad_s):.0f} rpm, {design.operating.power / 1e3:.0f} kW, {support}, "
        f"{actives} active bearing{'s' if actives != 1 else ''}"
    )


def inputs_section(design, design_text: str | None, source: str) -> Section:
    """The inputs: the marked (assumed, calibrated) values and the design file verbatim.

    Parameters
    ----------
    design : Design
        The validated design.
    design_text : str or None
        The design file as read; None renders the validated design as JSON instead.
    source : str
        Where the file came from (a path, or "embedded baseline").
    """
    paragraphs = [f"Design file: {source}."]
    tables = []
    if design_text is None:
        paragraphs.append(
            "The original file was not passed to the report; the block below is the validated "
            "design (JSON, SI units), without the file's comments, so no assumed value can be listed."
        )
        text = json.dumps(design.model_dump(mode="json"), indent=2)
    else:
        text = design_text
        marked = marked_inputs(design_text)
        if marked:
            paragraphs.append(
                f"{len(marked)} input values are marked in the file as assumed or calibrated: they "
                "are not data, and every result that depends on them inherits their uncertainty; "
                "replace them with measured values when available."
            )
            tables.append(
                Table(
                    "Inputs marked in the design file as assumed or calibrated",
                    ["key", "value", "marked", "comment", "line"],
                    [[m.key, m.value, m.marker, m.comment, m.line] for m in marked],
                )
            )
        else:
            paragraphs.append(
                "The file marks no value as assumed or calibrated (a comment containing the word "
                '"assumed" or "calibrated" marks the value on its line).'
            )
    return Section(
        "Inputs and assumptions",
        paragraphs=paragraphs,
        tables=tables,
        blocks=[Preformatted(f"Design file ({source}, {len(text.splitlines())} lines)", text)],
    )
