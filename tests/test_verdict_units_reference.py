"""Reference: the units a verdict's results file states are those of its numbers (hunt h40a).

A check's ``unit`` and a location's keys (``frequency_rad_s``) are what a reader of results.json
or of the CLI's ``--json`` converts with; a label that disagrees with the number is a silent
factor 57.3 (deg/rad) or 2π (Hz/rad s⁻¹). The numbers are typed by hand in SI, so the checks'
values are known exactly:

* a loop with a 45° phase margin at a 50 Hz gain crossover: the phase-margin check holds
  45° = π/4 rad against the default 30° = π/6 rad (docs/requirements.md), its unit must be
  ``rad``, and the crossover, 2π · 50 = 314.159… rad/s, must be written as ``frequency_rad_s``;
  the report's display (``format_quantity``: angles in degrees) reads 45°, not 2578°;
* the sensitivity peak of that loop at 80 Hz: ``frequency_rad_s`` = 2π · 80 rad/s.

Exact to round-off (1e-15 relative: one multiplication by π/180 or 2π).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.design.requirements import Requirements
from flexshaft.units import format_quantity
from flexshaft.verdict import checks
from flexshaft.verdict.evidence import Evidence, LoopEvidence

OMEGA = 600.0  # rad/s
LOOP = LoopEvidence("amb", "y", OMEGA, 2.5, 2.0 * math.pi * 80.0, 12.0, -8.0, math.radians(45.0), 2.0 * math.pi * 50.0)


def test_a_phase_margin_is_stated_in_radians_with_its_crossover_in_rad_s():
    check = checks.loop_phase_margin(Evidence(OMEGA, None, loops=(LOOP,)), Requirements())
    out = check.to_dict()
    assert out["kind"] == "angle" and out["unit"] == "rad"
    assert out["value"] == pytest.approx(math.pi / 4.0, rel=1e-15)
    assert out["limit"] == pytest.approx(math.pi / 6.0, rel=1e-15)
    assert out["margin"] == pytest.approx(math.pi / 12.0, rel=1e-14)
    assert out["location"]["frequency_rad_s"] == pytest.approx(100.0 * math.pi, rel=1e-15)
    assert out["findings"][0]["location"]["frequency_rad_s"] == pytest.approx(100.0 * math.pi, rel=1e-15)
    assert format_quantity(check.kind, check.value) == "45°"


def test_a_sensitivity_peak_frequency_is_written_in_rad_s():
    out = checks.loop_sensitivity(Evidence(OMEGA, None, loops=(LOOP,)), Requirements()).to_dict()
    assert out["unit"] == "-" and out["value"] == 2.5
    assert out["location"]["frequency_rad_s"] == pytest.approx(160.0 * math.pi, rel=1e-15)
    assert out["location"]["speed_rad_s"] == OMEGA
    assert "frequency" not in out["location"]
