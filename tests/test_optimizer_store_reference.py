"""The optimizer's evaluation log: what a resumed run trusts, and what it evaluates again.

References: the log's documented contract (:mod:`flexshaft.optimize.store`: a record whose
checksum does not match is skipped with a warning and evaluated again; an evaluation that raised
is evaluated again on resume; floats round-trip exactly) and the ZDT1 output function worked by
hand (:mod:`flexshaft.optimize.reference`): wall 2.5 mm -> u1 = (2.5 - 1)/3 = 0.5, K_d of the
second active bearing 2000 N s/m -> u3 = 1 (> 0.9: ``margin_probe`` not evaluated, NaN),
K_d1 = 0 -> u2 = 0, K_p1 = 1e5 N/m -> u4 = 0, three 0° plies -> n = 3; so g = 1 + 3 (0 + 1 + 0)
+ 0 = 4, f1 = 0.5, f2 = g (1 − √(f1/g)) = 4 − √2, margin_lower = u1 − 0.1 = 0.4. The values
go through a unit conversion of the wall (a few ulp), hence rtol = 1e-12.

Cheap: hand-built records, and one evaluation of the analytic ZDT1 function through the engine.
"""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest

pytest.importorskip("xarray")

from flexshaft.optimize.reference import zdt1_problem
from flexshaft.optimize.store import EVALUATIONS, FAILED, EvaluationCache, evaluate_candidates


def _record(key: str, f1: float, error: str | None = None) -> dict:
    return {"key": key, "overrides": {"shaft.wall_thickness": 0.003}, "outputs": {"f1": f1}, "error": error}


def test_records_round_trip_and_an_edited_one_is_skipped(tmp_path):
    log = tmp_path / EVALUATIONS
    EvaluationCache(log).add([_record("a", 0.1 + 0.2), _record("b", 1.5)])
    reread = EvaluationCache(log)
    assert reread.get("a")["outputs"]["f1"] == 0.30000000000000004  # 0.1 + 0.2 in IEEE double, exactly
    assert reread.get("b")["outputs"]["f1"] == 1.5
    # record b edited after it was written (still valid JSON): its checksum no longer matches
    text = log.read_text()
    assert text.count('"f1":1.5') == 1
    log.write_text(text.replace('"f1":1.5', '"f1":2.5'))
    with pytest.warns(RuntimeWarning, match="1 damaged evaluation record"):
        edited = EvaluationCache(log)
    assert "a" in edited and "b" not in edited


def test_an_evaluation_that_raised_is_evaluated_again_on_resume(tmp_path):
    log = tmp_path / EVALUATIONS
    EvaluationCache(log).add([_record("ok", 1.0), _record("raised", math.nan, FAILED)])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # both records are intact: no warning
        reread = EvaluationCache(log)
    assert "ok" in reread and "raised" not in reread and len(reread) == 1


def test_one_output_not_evaluated_is_a_result_not_a_failure(tmp_path):
    problem = zdt1_problem()
    values = {"wall_thickness": 0.0025, "kd_1": 0.0, "kd_2": 2000.0, "kp_1": 1e5, "zero_plies": 3}
    candidate = problem.overrides(values)
    records, computed = evaluate_candidates(problem, [candidate], EvaluationCache(tmp_path / EVALUATIONS))
    assert computed == 1
    (record,) = records
    outputs = record["outputs"]
    np.testing.assert_allclose(
        [outputs["f1"], outputs["f2"], outputs["margin_lower"]], [0.5, 4 - math.sqrt(2), 0.4], rtol=1e-12
    )
    assert math.isnan(outputs["margin_probe"])
    assert record["error"] is None  # one NaN margin: the check was not evaluated, the design was
    # resumed: the record is read back from the log, nothing is computed again
    resumed = EvaluationCache(tmp_path / EVALUATIONS)
    again, computed = evaluate_candidates(problem, [candidate], resumed)
    assert computed == 0 and again[0]["key"] == record["key"]
    line = json.loads((tmp_path / EVALUATIONS).read_text().splitlines()[0])
    assert line["error"] is None
