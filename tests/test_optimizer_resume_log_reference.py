"""The optimizer's evaluation log on resume: a torn last line does not swallow the next record,
and a stored evaluation is only reused by the same evaluation.

References: the documented contract of the run folder (docs/optimizer.md, "Parallel, cached,
resumable": "A design's key is the SHA-256 of the evaluation (function, outputs, fidelity,
flexshaft version) and of the design itself (all fields but its name), so a design met again
... a resumed run — is read, not computed"; and, under "Verification": "An interrupted run ...
resumes with no evaluation repeated ...; a damaged record is skipped with a warning and
recomputed"), and :class:`flexshaft.optimize.store.EvaluationCache`'s docstring (code): "A line
that does not parse (not UTF-8, not JSON: a damaged or overwritten file) or whose checksum
``sum`` does not match (a run killed while writing it) is skipped with a warning".
Consequences derived here: a log whose last line was torn holds exactly one damaged record
however many times it is resumed and extended; a candidate evaluated at the ``screening``
fidelity is computed again (one new evaluation) at ``verdict``, and read (none) at
``screening``. Counts are integers: exact comparisons. Cheap: hand-built records and the
analytic ZDT1 function (:mod:`flexshaft.optimize.reference`), no design analysis.
"""

from __future__ import annotations

import pytest

pytest.importorskip("xarray")

from flexshaft.optimize.reference import zdt1_problem
from flexshaft.optimize.store import EVALUATIONS, EvaluationCache, evaluate_candidates


def _record(key: str, f1: float) -> dict:
    return {"key": key, "overrides": {"shaft.wall_thickness": 0.003}, "outputs": {"f1": f1}, "error": None}


def test_a_record_written_after_a_torn_line_survives_the_next_resume(tmp_path):
    """Record a intact, record b torn mid-line (no newline: the run was killed while writing
    it). The resumed run skips b (one damaged record), appends c; the next resume still finds
    a and c and still exactly one damaged line (b): c was not glued onto the torn text."""
    log = tmp_path / EVALUATIONS
    EvaluationCache(log).add([_record("a", 1.0)])
    with log.open("a") as handle:
        handle.write('{"key":"b","overrides":{"shaft.wall')  # torn: no closing brace, no newline
    with pytest.warns(RuntimeWarning, match="1 damaged evaluation record"):
        resumed = EvaluationCache(log)
    assert "a" in resumed and "b" not in resumed
    resumed.add([_record("c", 2.0)])
    with pytest.warns(RuntimeWarning, match="1 damaged evaluation record"):
        again = EvaluationCache(log)
    assert set(again.records) == {"a", "c"}
    assert again.get("c")["outputs"]["f1"] == 2.0


def test_a_stored_evaluation_is_reused_only_by_the_same_fidelity(tmp_path):
    """One ZDT1 candidate evaluated at ``screening``: the same candidate at ``verdict`` (another
    evaluation fingerprint) is computed (1), at ``screening`` again it is read (0); the log then
    holds two evaluations, one per fidelity."""
    values = {"wall_thickness": 0.0025, "kd_1": 0.0, "kd_2": 500.0, "kp_1": 1e5, "zero_plies": 3}
    screening = zdt1_problem(fidelity="screening")
    candidate = screening.overrides(values)
    log = tmp_path / EVALUATIONS
    _, computed = evaluate_candidates(screening, [candidate], EvaluationCache(log))
    assert computed == 1
    verdict = zdt1_problem(fidelity="verdict")
    _, computed = evaluate_candidates(verdict, [verdict.overrides(values)], EvaluationCache(log))
    assert computed == 1  # another evaluation: nothing of the screening run is read as its result
    _, computed = evaluate_candidates(screening, [candidate], EvaluationCache(log))
    assert computed == 0
    assert len(EvaluationCache(log)) == 2
