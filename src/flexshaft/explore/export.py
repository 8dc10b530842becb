"""The explored design out of the page: a design file and the ``flexshaft run`` command for it.

:func:`explored_toml` writes the edited design through the optimizer's one TOML writer
(:func:`flexshaft.optimize.files.design_toml`: every field, loads back to the same design) with
comments first: the changed keys marked with their new and former values, the verdict the page
showed, and the base file's provenance (its header comments, and every value its comments mark
"assumed" or "calibrated", :func:`flexshaft.report.inputs.marked_inputs`). :func:`run_command` is
the command line that judges the file as ``flexshaft run`` does.
"""

from __future__ import annotations

import json
import shlex
from collections.abc import Mapping
from typing import Any

from flexshaft.design import Design
from flexshaft.design.io import value_at_path
from flexshaft.optimize.files import design_toml
from flexshaft.report.inputs import marked_inputs

__all__ = ["changed_keys", "explored_toml", "header_comments", "run_command"]

_MISSING = object()


def changed_keys(base: Design, design: Design, overrides: Mapping[str, Any]) -> list[tuple[str, Any, Any]]:
    """``(path, new, former)`` of each override whose value differs from the base's."""
    before = json.loads(base.model_dump_json())
    after = json.loads(design.model_dump_json())
    out = []
    for path in overrides:
        old, new = value_at_path(before, path, _MISSING), value_at_path(after, path, _MISSING)
        if old != new:
            out.append((path, new, None if old is _MISSING else old))
    return out


def header_comments(text: str | None) -> list[str]:
    """The comment lines that open a design file (its provenance header), without ``#``."""
    out = []
    for line in (text or "").splitlines():
        stripped = line.strip()
        if not stripped.startswith("#"):
            if stripped:
                break
            out.append("")
            continue
        out.append(stripped[1:].removeprefix(" "))
    while out and not out[-1]:
        out.pop()
    return out


def explored_toml(
    design: Design,
    base: Design,
    overrides: Mapping[str, Any],
    *,
    base_text: str | None = None,
    base_source: str = "",
    verdict_summary: str = "",
    filename: str = "explored.toml",
) -> str:
    """The design file of an explored design (see the module docstring).

    Parameters
    ----------
    design : Design
        The edited design (the base with ``overrides``).
    base : Design
        The design the page started from.
    overrides : mapping
        Design paths set in the page (SI, as in a design file).
    base_text : str, optional
        The base's design file, for its provenance comments.
    base_source : str
        Where the base came from (a file name or "embedded tuned design").
    verdict_summary : str
        The verdict the page showed (:attr:`flexshaft.verdict.result.Verdict.summary`).
    filename : str
        The file's name, for the command in its comments.
    """
    changes = changed_keys(base, design, overrides)
    lines = [
        "flexshaft design file written by `flexshaft explore`.",
        f"Base design: {base.name}" + (f" ({base_source})" if base_source else ""),
    ]
    if changes:
        lines.append("Keys changed in the explorer (CHANGED; SI units as in the file, ply angles in degrees):")
        lines += [f"  CHANGED {path} = {json.dumps(new)}  (was {json.dumps(old)})" for path, new, old in changes]
    else:
        lines.append("No key changed from the base design.")
    if verdict_summary:
        lines.append(f"Verdict in the explorer (screening grids): {verdict_summary}")
    lines.append("Judge it as the report does: " + run_command(filename))
    provenance = header_comments(base_text)
    if provenance:
        lines += ["", "Provenance: the base file's header, kept:", *[f"| {line}".rstrip() for line in provenance]]
    marked = marked_inputs(base_text) if base_text else []
    if marked:
        lines += ["", "Provenance: values the base file marks as assumed or calibrated (its comments):"]
        for m in marked:
            flag = " (CHANGED above)" if any(_same_key(m.key, path) for path, _, _ in changes) else ""
            lines.append(f"  {m.key} = {m.value}  # {m.comment}{flag}")
    lines.append("")
    return design_toml(design, lines)


def _same_key(marked: str, path: str) -> bool:
    """Whether a marked input's key (array elements by name or index) may be the changed path."""
    return (
        marked == path
        or marked.split("[", 1)[0] == path.split("[", 1)[0]
        and marked.rsplit(".", 1)[-1] == (path.rsplit(".", 1)[-1])
    )


def run_command(filename: str, out: str | None = None) -> str:
    """The ``flexshaft run`` command that judges the design file ``filename`` as the report does
    (``--strict``: exit code 3 when a requirement fails)."""
    stem = filename.rsplit("/", 1)[-1].removesuffix(".toml") or "design"
    folder = out if out is not None else f"{stem}-results"
    return f"flexshaft run {shlex.quote(filename)} --strict --out {shlex.quote(folder)}"
