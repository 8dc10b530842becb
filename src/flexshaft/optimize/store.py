"""Every optimizer evaluation on disk, and batches of candidates evaluated on the sweep engine.

Layout of an optimizer run folder::

    RUN/problem.json             the search (variables, objectives, constraints, seed, population)
    RUN/evaluations.jsonl        one line per evaluated candidate: key, overrides, outputs, checksum
    RUN/batches/<id>/            the sweep run folder of the batch being evaluated (chunks of one
                                 evaluation each); removed once the batch is in evaluations.jsonl
    RUN/evaluations.nc, pareto.nc, pareto.png, designs/   written at the end

A candidate's key is the SHA-256 of the evaluation fingerprint (evaluation function, outputs,
fidelity, flexshaft version) and of the design it makes, so a design met again (a duplicate, the
base design, a resumed run, a longer budget) is read, not recomputed. A batch is a
:class:`~flexshaft.sweep.Study` over one special axis, ``candidate`` (its JSON overrides), with
chunks of one point: an interrupted batch keeps every finished evaluation, and the resumed run
(which asks for the same candidates, the search being deterministic for a seed) reuses them
through the sweep engine's own resume.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import shutil
import warnings
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft.design import DesignError, with_overrides
from flexshaft.files import append_line
from flexshaft.optimize.problem import DesignProblem
from flexshaft.optimize.variables import OptimizeError
from flexshaft.sweep import Output, Study, Variable, evaluate_chunk, finished_chunks, run_sweep

__all__ = ["EVALUATIONS", "EvaluationCache", "candidate_key", "candidate_overrides", "evaluate_candidates"]

EVALUATIONS = "evaluations.jsonl"
BATCHES = "batches"


def _canonical(overrides: Mapping[str, Any]) -> str:
    return json.dumps(dict(overrides), sort_keys=True, separators=(",", ":"), allow_nan=False)


#: Error text of a candidate whose evaluation raised (every output NaN): infeasible in this run,
#: evaluated again when the run is resumed.
FAILED = "the evaluation raised an error (every output NaN); evaluated again on resume"


def candidate_key(fingerprint: str, design_json: str) -> str:
    """Cache key of a candidate: SHA-256 of the evaluation fingerprint and its design (canonical
    JSON), so candidates that make the same design share one evaluation."""
    return hashlib.sha256(f"{fingerprint}\n{design_json}".encode()).hexdigest()


def _design_json(design) -> str:
    """Canonical JSON of everything in a design but its name (which no result depends on)."""
    data = json.loads(design.model_dump_json())
    data.pop("name", None)
    return json.dumps(data, sort_keys=True, separators=(",", ":"))


def candidate_overrides(value: str) -> dict[str, Any]:
    """Sweep ``overrides`` function of the ``candidate`` axis: its JSON overrides."""
    return json.loads(value)


def _line_checksum(record: dict) -> str:
    text = json.dumps(record, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:16]


class EvaluationCache:
    """Evaluated candidates by key, kept in ``RUN/evaluations.jsonl`` (or in memory).

    Each line is a JSON record ``{"key", "overrides", "outputs", "error", "sum"}``; floats are
    written with ``repr`` (exact round trip), NaN as ``NaN``. A line that does not parse (not
    UTF-8, not JSON: a damaged or overwritten file) or whose checksum ``sum`` does not match (a
    run killed while writing it) is skipped with a warning and the candidate is evaluated again.
    Records are appended without following a symbolic link (:func:`flexshaft.files.append_line`).
    """

    def __init__(self, path: str | os.PathLike | None = None) -> None:
        self.path = Path(path) if path is not None else None
        self.records: dict[str, dict] = {}
        if self.path is not None and self.path.exists():
            self._load()

    def _load(self) -> None:
        assert self.path is not None  # called for an existing log file only (__init__)
        try:
            data = self.path.read_bytes()
        except IsADirectoryError:
            raise OptimizeError(f"{self.path}: a folder, not the evaluation log; use another run folder") from None
        bad = 0
        for raw in data.split(b"\n"):
            if not raw.strip():
                continue
            try:
                record = json.loads(raw.decode("utf-8"))
                check = record.pop("sum")
                if check != _line_checksum(record):
                    raise ValueError("checksum")
                key = record["key"]
                if not isinstance(key, str) or not isinstance(record["outputs"], dict):
                    raise ValueError("record")
            except (ValueError, KeyError, TypeError, AttributeError):  # UnicodeDecodeError is a ValueError
                bad += 1
                continue
            if record.get("error") == FAILED:
                continue  # an evaluation that raised (possibly a transient fault) is tried again on resume
            self.records[key] = record
        if bad:
            warnings.warn(
                f"{self.path}: {bad} damaged evaluation record(s) skipped; those candidates are evaluated again",
                RuntimeWarning,
                stacklevel=3,
            )
        if data and not data.endswith(b"\n"):
            append_line(self.path, "\n", sync=False)  # start the next record on a new line

    def __contains__(self, key: str) -> bool:
        return key in self.records

    def __len__(self) -> int:
        return len(self.records)

    def get(self, key: str) -> dict | None:
        return self.records.get(key)

    def add(self, records: Sequence[dict]) -> None:
        """Store records (appended to the file and synced before returning)."""
        lines = []
        for record in records:
            record = {k: record[k] for k in ("key", "overrides", "outputs", "error")}
            self.records[record["key"]] = record
            lines.append(json.dumps({**record, "sum": _line_checksum(record)}, separators=(",", ":")))
        if self.path is not None and lines:
            append_line(self.path, "\n".join(lines) + "\n")  # synced; a symbolic link is refused


def _design_or_reason(problem: DesignProblem, overrides: Mapping[str, Any]):
    """The candidate's design, or the schema's message when it is invalid."""
    try:
        return with_overrides(problem.base, overrides), None
    except DesignError as exc:
        return None, str(exc).strip()


def evaluate_candidates(
    problem: DesignProblem,
    candidates: Sequence[Mapping[str, Any]],
    cache: EvaluationCache,
    run_dir: Path | None = None,
    *,
    jobs: int = 1,
    client: Any = None,
) -> tuple[list[dict], int]:
    """Outputs of every candidate (design overrides), from the cache or computed.

    New, valid candidates are computed as one sweep (``jobs`` processes or the Dask
    ``client``), one evaluation per chunk, in ``run_dir/batches/<id>`` so that an interrupted
    batch keeps its finished evaluations; then stored in ``cache``.

    Returns
    -------
    records : list of dict
        Per candidate: ``key``, ``overrides``, ``outputs`` (name -> float, NaN where the
        evaluation failed or the design is invalid), ``error`` (the schema's message for an
        invalid design, else None).
    n_computed : int
        Evaluations computed now (not found in the cache nor in an interrupted batch).
    """
    fingerprint = problem.evaluation_fingerprint()
    names = problem.output_names
    keys: list[str] = []
    new: dict[str, Mapping[str, Any]] = {}
    invalid: dict[str, dict] = {}
    for ov in candidates:
        design, reason = _design_or_reason(problem, ov)
        if design is not None:
            key = candidate_key(fingerprint, _design_json(design))
            if key not in cache and key not in new:
                new[key] = ov
        else:
            key = candidate_key(
                fingerprint, json.dumps({"invalid": _canonical(ov), "base": _design_json(problem.base)})
            )
            if key not in cache:
                invalid[key] = {
                    "key": key,
                    "overrides": dict(ov),
                    "outputs": dict.fromkeys(names, math.nan),
                    "error": reason,
                }
        keys.append(key)
    stored = 0
    cache.add(list(invalid.values()))
    if new:
        order = list(new)
        study = Study(
            name=f"{problem.name}: {len(order)} candidates",
            variables=(
                Variable(name="candidate", values=[_canonical(new[k]) for k in order], overrides=candidate_overrides),
                Variable(name="fidelity", values=[problem.fidelity]),
            ),
            outputs=tuple(Output(n) for n in names),
            evaluate=problem.evaluate,
            base=problem.base,
        )
        batch_dir = None
        if run_dir is not None:
            batch_dir = Path(run_dir) / BATCHES / study.fingerprint()[:20]
            stored = len(finished_chunks(batch_dir))  # an interrupted batch's evaluations (one per chunk)
        ds = run_sweep(study, batch_dir, jobs=jobs, client=client, chunk_size=1, progress=False, on_error="nan")
        values = np.stack([np.asarray(ds[n].values, dtype=float).reshape(len(order)) for n in names], axis=1)
        if not any(np.isfinite(list(r["outputs"].values())).any() for r in cache.records.values()):
            _raise_if_all_failed(study, values)
        cache.add(
            [
                {
                    "key": k,
                    "overrides": dict(new[k]),
                    "outputs": dict(zip(names, map(float, row))),
                    "error": FAILED if np.all(np.isnan(row)) else None,
                }
                for k, row in zip(order, values)
            ]
        )
        if batch_dir is not None:
            shutil.rmtree(batch_dir, ignore_errors=True)
    return [cache.records[k] for k in keys], len(new) - stored  # every key is in the cache now


def _raise_if_all_failed(study, values: np.ndarray) -> None:
    """Every evaluation of the first batches failed (nothing has ever been evaluated): evaluate
    the first candidate again here, to show the user the error instead of an empty front."""
    if values.size == 0 or not np.all(np.isnan(values)):
        return
    try:
        evaluate_chunk(study, 0, 1, on_error="raise")
    except Exception as exc:  # the evaluation's own error, shown to the user
        raise OptimizeError(
            f"every evaluation of the batch failed; the first one raised {type(exc).__name__}: {exc}"
        ) from exc
