"""The comparison's whirl metrics read the requirement they are named after
(:meth:`flexshaft.comparison.Comparison.metrics`).

Reference, written by hand here: the metric titled "whirl onset speed" [rad/s] is the value of
each verdict's whirl-onset requirement (key ``whirl_onset``, kind speed), and the metric titled
"smallest log decrement at Ω_op" [1] the value of its whirl-damping requirement (key
``whirl_damping``, kind ratio): the module docstring lists "whirl onset and the smallest log
decrement" as two of the quantities a designer weighs. Each design's verdict is made by hand
with an onset actually found (not a lower bound at the scan's top) at 600 rad/s (design A) and
450 rad/s (design B), and log decrements 0.12 and 0.30: dimensionless numbers three orders of
magnitude from the speeds, so a metric reading the other requirement cannot pass. The values
are copied, not computed, so the comparison is exact (== on the hand floats).

CPU: milliseconds (no analysis runs; the runs are hand-made stand-ins).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from flexshaft.comparison import PART_KINDS, Comparison, Inventory
from flexshaft.verdict.result import Check, Verdict


def _run(onset: float, log_decrement: float) -> SimpleNamespace:
    checks = (
        Check("whirl_onset", "whirl onset", "speed", "at least", "pass", onset, 300.0, onset - 300.0),
        Check("whirl_damping", "whirl damping", "ratio", "at least", "pass", log_decrement, 0.1, log_decrement - 0.1),
    )
    values = {"v": np.zeros(2), "w": np.zeros(2)}
    return SimpleNamespace(
        verdict=Verdict(checks),
        model=SimpleNamespace(
            speed=200.0,
            dofs=SimpleNamespace(values=lambda q, part, field: values[field]),
            design=SimpleNamespace(name="stand-in"),
        ),
        resolution=SimpleNamespace(scan_top=1.5),
        static_displacement=np.zeros(2),
    )


def test_onset_and_log_decrement_metrics_read_their_own_requirements():
    """whirl_onset = (600, 450) rad/s, not lower bounds; log_decrement = (0.12, 0.30)."""
    inventory = Inventory(dict.fromkeys(PART_KINDS, 1.0), dict.fromkeys(PART_KINDS, 1))
    result = Comparison(
        labels=("a", "b"), runs=(_run(600.0, 0.12), _run(450.0, 0.30)), inventories=(inventory, inventory)
    )
    metrics = {m.key: m for m in result.metrics()}
    onset = metrics["whirl_onset"]
    assert (onset.unit, onset.values, onset.lower_bounds) == ("rad/s", (600.0, 450.0), (False, False))
    damping = metrics["log_decrement"]
    assert (damping.unit, damping.values) == ("1", (0.12, 0.30))
