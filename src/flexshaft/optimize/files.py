"""Design files of the optimizer's best designs, and their re-verification with the full run.

:func:`design_toml` writes a validated design as a TOML design file (every field, so the file
stands alone; comments first); loading it back gives the same design, which
:func:`write_design_file` checks before it returns. :func:`verify_design_files` assesses each
file as ``flexshaft run`` does (:func:`~flexshaft.verdict.assess.assess` at the report's
resolution) on the sweep engine and returns its verdict: the same verdict ``flexshaft run
--strict`` turns into its exit code.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft.design import load_design
from flexshaft.files import atomic_write_text
from flexshaft.resolution import REPORT
from flexshaft.sweep import Output, Study, Variable, run_sweep
from flexshaft.verdict.assess import assess

__all__ = ["VERIFY_OUTPUTS", "design_toml", "verify_design_files", "verify_outputs", "write_design_file"]

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def _key(key: str) -> str:
    return key if _BARE_KEY.fullmatch(key) else json.dumps(key, ensure_ascii=False)


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
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, Mapping):
        items = ", ".join(f"{_key(k)} = {_scalar(v)}" for k, v in value.items() if v is not None)
        return "{ " + items + " }" if items else "{}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_scalar(v) for v in value) + "]"
    raise TypeError(f"cannot write {type(value).__name__} to TOML")


def _is_table_list(value: Any) -> bool:
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(isinstance(v, Mapping) for v in value)


def _emit(lines: list[str], header: str, table: Mapping[str, Any], array: bool = False) -> None:
    scalars = {k: v for k, v in table.items() if v is not None and not isinstance(v, Mapping) and not _is_table_list(v)}
    tables = {k: v for k, v in table.items() if isinstance(v, Mapping)}
    lists = {k: v for k, v in table.items() if _is_table_list(v)}
    if header and (array or scalars or not (tables or lists)):
        lines.append("")
        lines.append(f"[[{header}]]" if array else f"[{header}]")
    for k, v in scalars.items():
        lines.append(f"{_key(k)} = {_scalar(v)}")
    for k, v in tables.items():
        _emit(lines, f"{header}.{_key(k)}" if header else _key(k), v)
    for k, items in lists.items():
        for item in items:
            _emit(lines, f"{header}.{_key(k)}" if header else _key(k), item, array=True)


def design_toml(design, comments: Sequence[str] = ()) -> str:
    """The design as a TOML design file (every field; ``None`` fields left out).

    Parameters
    ----------
    design : Design
    comments : sequence of str
        Lines written first as ``#`` comments.
    """
    data = json.loads(design.model_dump_json())
    lines = [f"# {line}".rstrip() for text in comments for line in str(text).splitlines()]
    _emit(lines, "", data)
    return "\n".join(lines).lstrip("\n") + "\n"


def write_design_file(design, path: str | Path, comments: Sequence[str] = ()) -> Path:
    """Write ``design`` to ``path`` and check that the file loads back to the same design."""
    path = Path(path)
    atomic_write_text(path, design_toml(design, comments))
    loaded = load_design(path)
    if json.loads(loaded.model_dump_json()) != json.loads(design.model_dump_json()):
        raise RuntimeError(f"{path}: the written design file does not load back to the same design")
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
