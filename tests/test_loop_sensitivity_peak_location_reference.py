"""The sensitivity-peak check of the magnetic-bearing loops: value, limit, margin, status and the
location of each finding, worked by hand from stand-in loop evidence.

References (documented rules, docs/requirements.md):

* the `loop_sensitivity` row: value "peak of the sensitivity function of each axis of each
  magnetic bearing", limit `max_sensitivity_peak` (default 4.0, the top of ISO 14839-3's zone B),
  where "bearing and axis, frequency" (read here, not quoted: the frequency is that of the peak
  of |S(iω)| the value is);
* "The checks": the margin of a maximum is limit − value, negative fails, and the row shows the
  worst instance;
* the `loop_phase_margin` row, for contrast: "smallest phase margin over each axis's gain
  crossovers", located at that crossover (`min_phase_margin_deg` 30° = π/6 rad).

By hand, two axes of one bearing, each with its sensitivity peak and its gain crossover at
different frequencies (rad/s, as the evidence holds them):

* axis x: |S|max 2.5 at 300 rad/s: margin 4.0 − 2.5 = +1.5, located at 300 rad/s;
* axis y: |S|max 4.4 at 410 rad/s: margin 4.0 − 4.4 = −0.4, fails, located at 410 rad/s.

The check fails with the y axis's finding. Its phase margins, 0.7 rad at the x crossover
120 rad/s and 0.5 rad at the y crossover 150 rad/s, give a phase check located at 150 rad/s.
The numbers are one subtraction of short decimals: exact to a few ulps
(4.0 − 4.4 = −0.40000000000000036), hence rel 1e-12. Each finding's location is asserted by its
frequency and speed only, copied from the evidence without arithmetic, hence exact; the label of
its bearing and axis is not pinned, its format being undocumented.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.evidence import Evidence, LoopEvidence

SPEED = 500.0  # rad/s, the loops' spin speed
LOOPS = (
    LoopEvidence("front", "x", SPEED, 2.5, 300.0, phase_margin=0.7, phase_margin_frequency=120.0),
    LoopEvidence("front", "y", SPEED, 4.4, 410.0, phase_margin=0.5, phase_margin_frequency=150.0),
)


def _verdict():
    return evaluate(Evidence(operating_speed=SPEED, loops=LOOPS), Requirements())


def test_each_sensitivity_finding_is_located_at_its_peak_frequency():
    """Each axis's finding: its own |S|max, the 4.0 limit, limit − value, at its peak's
    frequency (300 and 410 rad/s), never at its gain crossover (120 and 150 rad/s)."""
    check = _verdict().check("loop_sensitivity")
    x, y = check.findings
    assert x.value == pytest.approx(2.5, rel=1e-12) and x.limit == pytest.approx(4.0, rel=1e-12)
    assert x.margin == pytest.approx(1.5, rel=1e-12) and x.passed
    assert x.location["frequency"] == 300.0
    assert x.location["speed"] == SPEED
    assert y.margin == pytest.approx(-0.4, rel=1e-12) and not y.passed
    assert y.location["frequency"] == 410.0
    assert y.location["speed"] == SPEED


def test_the_check_shows_the_failing_axis_at_its_peak():
    """The worst finding (margin −0.4) is the row: fail, 4.4 against 4.0, at 410 rad/s; the phase
    check of the same loops is located at the y axis's gain crossover, 150 rad/s."""
    verdict = _verdict()
    check = verdict.check("loop_sensitivity")
    assert check.status == "fail"
    assert check.value == pytest.approx(4.4, rel=1e-12)
    assert check.limit == pytest.approx(4.0, rel=1e-12)
    assert check.margin == pytest.approx(-0.4, rel=1e-12)
    assert check.location["frequency"] == pytest.approx(410.0, rel=1e-15)
    phase = verdict.check("loop_phase_margin")
    assert phase.status == "fail"
    assert phase.margin == pytest.approx(0.5 - math.pi / 6.0, rel=1e-12)
    assert phase.location["frequency"] == pytest.approx(150.0, rel=1e-15)
