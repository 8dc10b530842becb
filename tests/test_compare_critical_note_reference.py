"""The comparison's critical-speed notes (``flexshaft compare``'s note columns and results.json's
metric notes): each design's nearest lateral critical below and above the operating speed, with
its amplification factor, its actual API 684 separation margin and the margin it needs.

References (documented rule, docs/requirements.md "Separation margin (API 684 / API 617)"): with
one operating speed N_op the actual margin is |N_c − N_op|/N_op; the required one is, for AF ≥
2.5, min(16, 17 (1 − 1/(AF − 1.5))) % below the operating speed and min(26, 10 + 17 (1 − 1/(AF −
1.5))) % above it. Worked here by hand for stand-in verdicts (no analysis, about 1 ms of CPU):

* design A, N_op = 500 rad/s: a critical at 400 rad/s with AF 5, margin 100/500 = 20.0 %,
  needs 17 (1 − 1/3.5) = 12.14 %; one at 650 rad/s with AF 4, margin 150/500 = 30.0 %, needs
  10 + 17 (1 − 1/2.5) = 20.2 %;
* design B, N_op = 600 rad/s: a critical at 420 rad/s with AF 3, margin 180/600 = 30.0 %,
  needs 17 (1 − 1/1.5) = 5.67 %; none above.

Notes print one decimal of the percentages, so the expected text is exact.
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.comparison import PART_KINDS, Comparison, Inventory
from flexshaft.verdict.result import Check, Finding, Verdict


def _required(af: float, below: bool) -> float:
    """API 684's required separation margin [fraction] (docs/requirements.md)."""
    if af < 2.5:
        return 0.0
    term = 17.0 * (1.0 - 1.0 / (af - 1.5))
    return (min(16.0, term) if below else min(26.0, 10.0 + term)) / 100.0


def _run(op: float, criticals: list[tuple[float, float]]):
    """A stand-in assessment at ``op`` [rad/s] whose separation check lists ``criticals`` (N_c, AF)."""
    findings = []
    for speed, af in criticals:
        margin, required = abs(speed - op) / op, _required(af, speed < op)
        findings.append(
            Finding(margin, required, margin - required, {"speed": speed, "amplification_factor": af, "mode": 1})
        )
    worst = min(findings, key=lambda f: f.margin)
    separation = Check(
        "separation",
        "API 684 separation margin",
        "fraction",
        "at least",
        "pass",
        worst.value,
        worst.limit,
        worst.margin,
        findings=tuple(findings),
    )
    dofs = NS(values=lambda q, member, which: np.zeros(3))
    return NS(
        model=NS(speed=op, dofs=dofs),
        verdict=Verdict((separation,)),
        static_displacement=np.zeros(6),
        resolution=NS(scan_top=1.5),
    )


@pytest.fixture(scope="module")
def metrics():
    inventory = Inventory(dict.fromkeys(PART_KINDS, 1.0), dict.fromkeys(PART_KINDS, 1))
    comparison = Comparison(
        labels=("A", "B"),
        runs=(_run(500.0, [(400.0, 5.0), (650.0, 4.0)]), _run(600.0, [(420.0, 3.0)])),  # type: ignore[arg-type]
        inventories=(inventory, inventory),
    )
    return {m.key: m for m in comparison.metrics()}


def test_nearest_criticals_each_side_of_each_design(metrics):
    assert metrics["critical_below"].values == (400.0, 420.0)
    assert metrics["critical_above"].values == (650.0, None)
    assert metrics["separation"].values == pytest.approx((0.2, 0.3), rel=1e-12)


def test_critical_notes_give_the_margin_and_what_it_needs(metrics):
    below, above = metrics["critical_below"].notes, metrics["critical_above"].notes
    assert below == ("AF 5, margin 20.0 % (needs 12.1 %)", "AF 3, margin 30.0 % (needs 5.7 %)")
    assert above[0] == "AF 4, margin 30.0 % (needs 20.2 %)"
    assert above[1] == "none up to 1.5 × Ω_op"
