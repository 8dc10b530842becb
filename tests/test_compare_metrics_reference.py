"""``Comparison.metrics`` on two hand-built verdicts whose answers are written by hand.

The embedded comparison (tests/test_compare.py) checks the inventories against the design
files; the metrics that pick one value out of many are checked here, on fake assessments
(plain namespaces holding a :class:`~flexshaft.verdict.result.Verdict`) so that every answer
is known without running an analysis:

* the governing value of a requirement is the worst one: the smallest strength safety factor
  of Tsai-Wu 2.0 and metal strength 1.5 is 1.5; the largest of one shaft temperature is it;
* the lateral critical speeds nearest the operating speed Ω_op = 100 rad/s on each side: of
  50, 80, 120 and 200 rad/s, the highest below is 80 and the lowest above is 120;
* the static shaft deflection is the orbit radius √(v² + w²) at the worst station: v = 3 mm,
  w = 4 mm gives 5 mm, larger than the 4.5 mm of a station deflected in v only.

The selections are exact; the deflection √(v² + w²) is 5 mm up to the binary rounding of
3 mm, 4 mm and of the square root, a few 1e-16 (rel 1e-14).  CPU: a few milliseconds.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.comparison import PART_KINDS, Comparison, Inventory
from flexshaft.verdict.result import Check, Finding, Verdict


def _check(key: str, kind: str, value: float, limit: float, findings=()) -> Check:
    return Check(key, key, kind, "at least", "pass", value, limit, value - limit, findings=tuple(findings))


def _run(checks, v, w):
    """A fake assessment: its verdict, Ω_op = 100 rad/s and a static displacement whose shaft
    v and w values are ``v`` and ``w`` [m] (one entry per station)."""
    values = {"v": np.asarray(v, dtype=float), "w": np.asarray(w, dtype=float)}
    dofs = SimpleNamespace(values=lambda q, part, field: values[field] if part == "shaft" else None)
    return SimpleNamespace(
        verdict=Verdict(tuple(checks)),
        model=SimpleNamespace(speed=100.0, dofs=dofs),
        resolution=SimpleNamespace(scan_top=2.0),
        static_displacement=np.zeros(3),
    )


def _comparison() -> Comparison:
    criticals = [
        Finding(speed, 0.15, abs(speed - 100.0) / 100.0 - 0.15, {"speed": speed, "amplification_factor": 3.0})
        for speed in (200.0, 50.0, 120.0, 80.0)
    ]
    design_a = [
        _check("tsai_wu", "ratio", 2.0, 1.0),
        _check("metal_strength", "ratio", 1.5, 1.0),
        _check("separation", "fraction", 0.2, 0.15, criticals),
        _check("temperature", "temperature", 350.0, 400.0),
    ]
    design_b = [_check("metal_strength", "ratio", 4.0, 1.0)]
    inventory = Inventory(dict.fromkeys(PART_KINDS, 1.0), dict.fromkeys(PART_KINDS, 1))
    return Comparison(
        labels=("a", "b"),
        runs=(_run(design_a, [0.0, 0.003, 0.0045], [0.0, 0.004, 0.0]), _run(design_b, [0.0], [0.0])),
        inventories=(inventory, inventory),
    )


@pytest.fixture(scope="module")
def metrics():
    return {m.key: m for m in _comparison().metrics()}


def test_the_governing_value_is_the_worst_of_the_checks(metrics):
    assert metrics["strength"].values == (1.5, 4.0)
    assert metrics["shaft_temperature"].values == (350.0, None)


def test_the_criticals_reported_are_the_nearest_on_each_side_of_the_operating_speed(metrics):
    assert metrics["critical_below"].values == (80.0, None)
    assert metrics["critical_above"].values == (120.0, None)


def test_the_static_deflection_is_the_orbit_radius_of_both_planes(metrics):
    assert metrics["static_deflection"].values[0] == pytest.approx(0.005, rel=1e-14)
    assert metrics["static_deflection"].values[1] == 0.0
