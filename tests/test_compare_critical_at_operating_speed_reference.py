"""A lateral critical exactly at the operating speed, in the comparison's "below"/"above" columns.

Reference: API 684's classification as :func:`flexshaft.analyses.separation.api684_separation`
makes it for the verdict's separation check (a critical below the operating speed when
N_c < N_op, otherwise above, where it needs the larger margin, min(26, 10 + 17(1 − 1/(AF −
1.5))) %). The comparison's "highest critical below" and "lowest critical above" must split the
criticals as the verdict judged them: of 80, 100 and 130 rad/s at Ω_op = 100 rad/s, the highest
below is 80 and the lowest above is 100 (the one the verdict judged "above"), not 130.

Fake assessments holding the verdict's findings, as in tests/test_compare_metrics_reference.py;
the selection is exact. CPU: milliseconds.

Written for the mutation h39b-compare-critical-below-inclusive of scripts/mutations.toml.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from flexshaft.analyses.separation import api684_separation
from flexshaft.comparison import PART_KINDS, Comparison, Inventory
from flexshaft.verdict.result import Check, Finding, Verdict

OPERATING = 100.0


def _run(checks):
    values = {"v": np.zeros(1), "w": np.zeros(1)}
    return SimpleNamespace(
        verdict=Verdict(tuple(checks)),
        model=SimpleNamespace(speed=OPERATING, dofs=SimpleNamespace(values=lambda q, part, field: values[field])),
        resolution=SimpleNamespace(scan_top=2.0),
        static_displacement=np.zeros(2),
    )


def test_a_critical_at_the_operating_speed_is_the_lowest_above():
    findings = []
    for speed in (80.0, 100.0, 130.0):
        sep = api684_separation(speed, 3.0, OPERATING)
        location = {"speed": speed, "amplification_factor": 3.0, "position": sep.position}
        findings.append(Finding(sep.margin, sep.required_margin, sep.margin - sep.required_margin, location))
    assert [f.location["position"] for f in findings] == ["below", "above", "above"]
    worst = min(findings, key=lambda f: f.margin)
    separation = Check(
        "separation",
        "separation",
        "fraction",
        "at least",
        "fail",
        worst.value,
        worst.limit,
        worst.margin,
        findings=tuple(findings),
    )
    inventory = Inventory(dict.fromkeys(PART_KINDS, 1.0), dict.fromkeys(PART_KINDS, 1))
    comparison = Comparison(labels=("a", "b"), runs=(_run([separation]), _run([])), inventories=(inventory, inventory))
    metrics = {m.key: m for m in comparison.metrics()}
    assert metrics["critical_below"].values == (80.0, None)
    assert metrics["critical_above"].values == (100.0, None)
