"""Design files of the optimizer's best designs, and their re-verification with the full run.

:func:`design_toml` writes a validated design as a TOML design file (every field, so the file
stands alone; comments first), with the base design file's comments carried over to the keys
they annotate and every key that differs from the base marked ``# optimized: was <base
value>``; loading it back gives the same design, which :func:`write_design_file` checks before
it returns. :func:`verify_design_files` assesses each file as ``flexshaft run`` does
(:func:`~flexshaft.verdict.assess.assess` at the report's resolution) on the sweep engine and
returns its verdict: the same verdict ``flexshaft run --strict`` turns into its exit code.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft.design import load_design, loads_design
from flexshaft.design.io import value_at_path
from flexshaft.files import atomic_write_text
from flexshaft.optimize.toml_comments import FileComments, KeyComments, read_comments
from flexshaft.resolution import REPORT
from flexshaft.sweep import Output, Study, Variable, run_sweep
from flexshaft.verdict.assess import assess

__all__ = ["VERIFY_OUTPUTS", "design_toml", "verify_design_files", "verify_outputs", "write_design_file"]

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def _string(text: str) -> str:
    """``text`` as a TOML basic string: JSON's escapes are TOML's, but JSON leaves DEL (U+007F)
    bare, which a TOML basic string must escape (TOML v1.0.0, "String")."""
    return json.dumps(text, ensure_ascii=False).replace("\x7f", "\\u007f")


#: Characters a TOML comment may not hold (TOML v1.0.0, "Comment"): the controls but tab.
_COMMENT_CONTROL = re.compile(r"[\x00-\x08\x0a-\x1f\x7f]")


def _comment_text(text: str) -> str:
    """``text`` fit for a ``#`` comment: each control character shown as ``\\uXXXX`` (a design
    name holding one, written into the header, would make the file invalid TOML)."""
    return _COMMENT_CONTROL.sub(lambda m: f"\\u{ord(m.group()):04x}", text)


def _key(key: str) -> str:
    return key if _BARE_KEY.fullmatch(key) else _string(key)


def _float(value: float) -> str:
    """The shortest text that reads back as ``value``: Python's repr, or its scientific form
    when shorter (``1.15e+11``, not ``115000000000.0``)."""
    text = repr(value)
    scientific = np.format_float_scientific(value, unique=True, trim="0")
    return scientific if len(scientific) < len(text) else text


def _scalar(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return _float(value)
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, Mapping):
        items = ", ".join(f"{_key(k)} = {_scalar(v)}" for k, v in value.items() if v is not None)
        return "{ " + items + " }" if items else "{}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_scalar(v) for v in value) + "]"
    raise TypeError(f"cannot write {type(value).__name__} to TOML")


def _is_table_list(value: Any) -> bool:
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(isinstance(v, Mapping) for v in value)


_MISSING = object()


class _Notes:
    """The base file's comments by path (:mod:`flexshaft.optimize.toml_comments`) and the base
    design's values, to annotate the lines of the file written."""

    def __init__(self, comments: FileComments | None, base: Mapping | None) -> None:
        self.comments = comments
        self.base = base
        self.used: set[tuple] = set()

    def _entry(self, path: tuple) -> KeyComments | None:
        if self.comments is None or path not in self.comments.keys:
            return None
        self.used.add(path)
        return self.comments.keys[path]

    def before(self, lines: list[str], path: tuple) -> None:
        entry = self._entry(path)
        if entry is not None:
            lines.extend(f"# {text}".rstrip() for text in entry.before)

    def line(self, text: str, path: tuple, value: Any = _MISSING) -> list[str]:
        """``text`` with its note: the base file's inline comment, and for a value that differs
        from the base design's ``optimized: was <base value>``; continuation lines under it."""
        entry = self._entry(path)
        notes = list(entry.inline) if entry is not None else []
        if value is not _MISSING and self.base is not None and path != ("name",):
            was = value_at_path(self.base, path, _MISSING)
            if was is _MISSING or was is None:
                marker = "optimized: not set in the base design"
            elif was != value:
                marker = f"optimized: was {_scalar(was)}"
            else:
                marker = None
            if marker is not None:
                notes = [f"{marker}; base note: {notes[0]}" if notes else marker, *notes[1:]]
        if not notes:
            return [text]
        indent = " " * (len(text) + 2)
        return [f"{text}  # {notes[0]}".rstrip()] + [f"{indent}# {n}".rstrip() for n in notes[1:]]

    def standalone(self, lines: list[str], path: tuple) -> None:
        """The comments of a table written without a header of its own, as comment lines."""
        entry = self._entry(path)
        if entry is not None and (entry.before or entry.inline):
            lines.append("")
            lines.extend(f"# {text}".rstrip() for text in entry.before + entry.inline)

    def unused(self) -> list[str]:
        """Comments of keys the file written does not have (e.g. a key left at its default)."""
        if self.comments is None:
            return []
        out = []
        for path, entry in self.comments.keys.items():
            if path in self.used or not (entry.before or entry.inline):
                continue
            name = ".".join(f"[{p}]" if isinstance(p, int) else str(p) for p in path).replace(".[", "[")
            out += [f"{name}:", *(f"  {t}" for t in entry.before + entry.inline)]
        return out


def _emit(lines: list[str], header: str, path: tuple, table: Mapping[str, Any], notes: _Notes, array=False) -> None:
    scalars = {k: v for k, v in table.items() if v is not None and not isinstance(v, Mapping) and not _is_table_list(v)}
    tables = {k: v for k, v in table.items() if isinstance(v, Mapping)}
    lists = {k: v for k, v in table.items() if _is_table_list(v)}
    if header and (array or scalars or not (tables or lists)):
        lines.append("")
        notes.before(lines, path)
        lines.extend(notes.line(f"[[{header}]]" if array else f"[{header}]", path))
    elif header:  # no header of its own: its comments go before its first sub-table
        notes.standalone(lines, path)
    for k, v in scalars.items():
        notes.before(lines, (*path, k))
        lines.extend(notes.line(f"{_key(k)} = {_scalar(v)}", (*path, k), v))
    for k, v in tables.items():
        _emit(lines, f"{header}.{_key(k)}" if header else _key(k), (*path, k), v, notes)
    for k, items in lists.items():
        for i, item in enumerate(items):
            _emit(lines, f"{header}.{_key(k)}" if header else _key(k), (*path, k, i), item, notes, array=True)


def design_toml(design, comments: Sequence[str] = (), *, base=None, base_text: str | None = None) -> str:
    """The design as a TOML design file (every field; ``None`` fields left out).

    Parameters
    ----------
    design : Design
    comments : sequence of str
        Lines written first as ``#`` comments.
    base : Design, optional
        The design it was derived from: a key whose value differs from the base's is marked
        ``# optimized: was <base value>``.
    base_text : str, optional
        The base design file's text: its comments are carried over to the keys and tables they
        annotate (:func:`~flexshaft.optimize.toml_comments.read_comments`), its preamble after
        ``comments``, and the comments of keys not written at the end.
    """
    data = json.loads(design.model_dump_json())
    file_comments = read_comments(base_text) if base_text is not None else None
    notes = _Notes(file_comments, None if base is None else json.loads(base.model_dump_json()))
    lines = [f"# {_comment_text(line)}".rstrip() for text in comments for line in str(text).splitlines()]
    if file_comments is not None and file_comments.preamble:
        lines += [
            "#",
            "# The base design file's header (its other comments are kept at the keys they annotate;",
            '# a key the optimizer changed says "optimized: was <base value>"):',
            "#",
            *(f"#   {text}".rstrip() for text in file_comments.preamble),
        ]
    if lines:
        lines.append("")
    _emit(lines, "", (), data, notes)
    leftover = notes.unused() + (file_comments.trailing if file_comments is not None else [])
    if leftover:
        lines += [
            "",
            "# Comments of the base design file on keys not written here:",
            *(f"# {t}".rstrip() for t in leftover),
        ]
    return "\n".join(lines).lstrip("\n") + "\n"


def write_design_file(
    design, path: str | Path, comments: Sequence[str] = (), *, base=None, base_text: str | None = None
) -> Path:
    """Write ``design`` to ``path`` (:func:`design_toml`, the base's comments carried over),
    once its text is checked to load back to the same design: a text that does not (invalid
    TOML, another design) raises before anything is written, so no such file is left behind."""
    path = Path(path)
    text = design_toml(design, comments, base=base, base_text=base_text)
    loaded = loads_design(text, str(path))
    if json.loads(loaded.model_dump_json()) != json.loads(design.model_dump_json()):
        raise RuntimeError(f"{path}: the design file's text does not load back to the same design (not written)")
    atomic_write_text(path, text)
    return path


#: Outputs of :func:`verify_outputs`: (name, unit, long name).
VERIFY_OUTPUTS = (
    ("passed", "1", "1 when no requirement fails (flexshaft run --strict exits 0)"),
    ("n_failed", "1", "requirements that fail"),
    ("n_not_evaluated", "1", "requirements not evaluated"),
    ("shaft_mass", "kg", "shaft mass"),
    ("safety_factor", "1", "minimum ply Tsai-Wu safety factor"),
    ("buckling_safety_factor", "1", "torsional-buckling safety factor"),
    ("actuator_force", "N", "largest static + spin-up actuator force"),
    ("spinup_deflection", "m", "peak shaft orbit during spin-up"),
)


def verify_outputs(point) -> dict[str, float]:
    """Sweep output function: the ``flexshaft run`` verdict of the design file named by the
    point's special axis ``design_file``."""
    design = load_design(point.axes["design_file"])
    res = assess(design, REPORT)
    verdict = res.verdict

    def value(key: str) -> float:
        c = verdict.check(key)
        return float("nan") if c.value is None else float(c.value)

    return {
        "passed": float(verdict.passed),
        "n_failed": float(len(verdict.failed)),
        "n_not_evaluated": float(len(verdict.not_evaluated)),
        "shaft_mass": float(res.model.shaft_mass),
        "safety_factor": value("tsai_wu"),
        "buckling_safety_factor": value("buckling"),
        "actuator_force": value("actuator_force"),
        "spinup_deflection": value("spinup_deflection"),
    }


def verify_design_files(
    paths: Sequence[str | Path], *, jobs: int = 1, client: Any = None, run_dir: str | Path | None = None
):
    """Full-run verdict of each design file, in parallel on the sweep engine.

    Returns
    -------
    xarray.Dataset
        Over ``design_file``: the outputs of :data:`VERIFY_OUTPUTS`.
    """
    files = [str(Path(p).resolve()) for p in paths]
    study = Study(
        name="full-run verification of the optimized designs",
        variables=(Variable(name="design_file", values=files),),
        outputs=tuple(Output(*o) for o in VERIFY_OUTPUTS),
        evaluate=verify_outputs,
    )
    ds = run_sweep(study, run_dir, jobs=jobs, client=client, chunk_size=1, progress=False)
    ds["passed"] = ds["passed"].astype(np.int8) if np.all(np.isfinite(ds["passed"].values)) else ds["passed"]
    return ds
