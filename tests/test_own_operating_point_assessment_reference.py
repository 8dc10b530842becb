"""A design without an ``[envelope]``, assessed at its own operating point: the report's detail
by the resolution, and the operating speed the notebook display states, against documented rules
and closed forms (derived here).

References:

* **The report's detail at the design's own point.** docs/requirements.md ("The operating
  envelope"): "A design without an ``[envelope]`` is judged at its own operating point";
  docs/optimizer.md ("Evaluation: only what the checks need"): "``flexshaft run`` computes
  everything its report shows (Campbell diagram, thermal design sweeps, modes at rest, ...)",
  an evaluation "at a ``Resolution`` that leaves out what only the report shows
  (``report_detail=False``)". So ``assess`` of a design without an envelope, at a resolution
  with ``report_detail=True``, carries the modes at rest, and at one with ``report_detail=False``
  does not. The modes at rest are checked on physics: the Jeffcott rotor of tests/rotors.py (a
  heavy midspan disk m on a pinned-pinned steel tube, undamped) whirls at rest at
  ω_n = √(48 E I / (L³ m)) (``rotors.WN``), the Euler-Bernoulli midspan stiffness held exactly
  by the Hermite cubics; the tube's own mass, 3.5e-6 of the disk's, moves ω_n by Rayleigh's
  −(17/70)(3.5e-6) = −8.5e-7 (measured −8.6e-7), so 1e-5 holds with ten times room and lies far
  below the next mode's distance (axial, 12.8 ω_n). The rotor spins at 1000 rpm = 104.7 rad/s,
  about a third of ω_n = 302 rad/s (away from the undamped resonance the spin-up would warn of).
* **The operating speed shown.** ``Assessment`` is in SI (rad/s); the notebook display
  (``_repr_html_``) states "assessed at N rpm". 1000 rpm = 1000 · 2π/60 rad/s = 104.72 rad/s, so
  the display reads "assessed at 1000 rpm" (rounded to whole rpm: exact text), and the speed in
  rad/s, "assessed at 105 rpm", would be a unit slip. The SI speed is compared with 1000 · 2π/60
  to 1e-12 relative (one rpm-to-rad/s conversion, round-off ~1e-16).

CPU: about 0.1 s per assessment of the 8-element rotor at the smallest grids (plus the modes at
rest for the detail), once per module.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from conftest import SMALLEST
from rotors import WN, jeffcott_text

import flexshaft as fs
from flexshaft.design import loads_design

RPM = 1000.0


@pytest.fixture(scope="module")
def design():
    text = jeffcott_text(0.0, 0.0)
    assert "speed_rpm = 0.0" in text
    found = loads_design(text.replace("speed_rpm = 0.0", f"speed_rpm = {RPM}"))
    assert found.envelope is None  # the branch under test: the design's own operating point
    return found


@pytest.fixture(scope="module")
def detailed(design):
    return fs.assess(design, dataclasses.replace(SMALLEST, report_detail=True))


def test_a_design_without_an_envelope_gets_the_report_detail_its_resolution_asks_for(design, detailed):
    assert detailed.governing_point == "operating point" and len(detailed.points) == 1
    found = detailed.modes_at_rest
    assert found is not None
    s = np.asarray(found.eigenvalues)[np.asarray(found.kind) == "lateral"][:2]
    assert s.size == 2
    assert np.abs(s) == pytest.approx(np.full(2, WN), rel=1e-5)


def test_a_design_without_an_envelope_at_a_resolution_without_the_detail_has_none(design):
    assert not SMALLEST.report_detail
    assert fs.assess(design, SMALLEST).modes_at_rest is None


def test_the_notebook_display_states_the_operating_speed_in_rpm(detailed):
    assert detailed.operating_speed == pytest.approx(RPM * 2.0 * math.pi / 60.0, rel=1e-12)
    page = detailed._repr_html_()
    assert "assessed at 1000 rpm" in page
    assert "assessed at 105 rpm" not in page
