"""What the explorer hands back to the page, with the assessment replaced by stand-ins (nothing
is assessed): the speeds of its "numbers" in rpm, and a sweep point's design.

References: the unit factor written out, 1 rpm = 2π/60 rad/s (4800 rpm = 502.6548 rad/s),
and the keys' documented units (``whirl_onset_rpm``, ``stable_to_rpm``, ``operating_speed_rpm``;
docs/explorer.md: the onset speed and the operating speed [rpm]); a sweep point is the base with
the point's overrides (module docstring of :mod:`flexshaft.explore.compute`).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

pytest.importorskip("starlette")
pytest.importorskip("plotly")

from flexshaft.design import tuned_design
from flexshaft.explore import compute
from flexshaft.verdict.checks import CHECK_KEYS

RPM = 2 * math.pi / 60  # rad/s per rpm


@pytest.fixture
def stand_ins(monkeypatch):
    """The table, inventory and figures of a payload replaced (they are tested elsewhere)."""
    monkeypatch.setattr(compute, "verdict_rows", lambda verdict: [])
    monkeypatch.setattr(compute, "driveline_inventory", lambda model: SimpleNamespace(total_mass=9.0, mass={}))
    monkeypatch.setattr(compute, "assessment_figures", lambda a: {})


def _assessment(onset: float | None) -> SimpleNamespace:
    """An assessment as update_payload reads it: a stability scan 0 to 628.3185 rad/s
    (6000 rpm), the operating speed 471.2389 rad/s (4500 rpm)."""
    return SimpleNamespace(
        design=SimpleNamespace(name="hand-made"),
        resolution=SimpleNamespace(name="explore"),
        verdict=SimpleNamespace(checks=[], passed=True, summary="PASS"),
        model=SimpleNamespace(shaft_mass=4.5),
        stability=SimpleNamespace(onset_speed=onset, speeds=np.linspace(0.0, 6000 * RPM, 21)),
        operating_speed=4500 * RPM,
    )


def test_the_numbers_are_in_rpm(stand_ins) -> None:
    """Onset at 502.6548 rad/s is 4800 rpm; with no onset, the scan to 628.3185 rad/s is stable
    to 6000 rpm (its last speed, not its first, 0); the operating speed 471.2389 rad/s is
    4500 rpm. Tolerance 1e-12 relative: one multiplication each."""
    numbers = compute.update_payload(_assessment(4800 * RPM))["numbers"]
    assert numbers["whirl_onset_rpm"] == pytest.approx(4800.0, rel=1e-12)
    assert numbers["operating_speed_rpm"] == pytest.approx(4500.0, rel=1e-12)
    assert (numbers["shaft_mass_kg"], numbers["driveline_mass_kg"]) == (4.5, 9.0)
    numbers = compute.update_payload(_assessment(None))["numbers"]
    assert numbers["whirl_onset_rpm"] is None
    assert numbers["stable_to_rpm"] == pytest.approx(6000.0, rel=1e-12)


def test_a_sweep_point_assesses_the_base_with_its_overrides(monkeypatch) -> None:
    """The sweep's K_p 2e5 N/m reaches the design assessed (the base has 5e5)."""
    assessed = []

    def assess(design, resolution):
        assessed.append(design)
        return SimpleNamespace(verdict=SimpleNamespace(checks=[]))

    metrics = {f"margin_{k}": 0.5 for k in CHECK_KEYS} | {f"status_{k}": "pass" for k in CHECK_KEYS}
    monkeypatch.setattr(compute, "assess", assess)
    monkeypatch.setattr(compute, "assessment_metrics", lambda a: metrics | {"shaft_mass": 4.5})
    base = tuned_design()
    assert base.bearings[1].kp == 5e5
    point = compute.sweep_point(base, {"bearings[1].kp": 2e5})
    assert [d.bearings[1].kp for d in assessed] == [2e5]
    assert point["margins"] == dict.fromkeys(CHECK_KEYS, 0.5) and point["shaft_mass_kg"] == 4.5
