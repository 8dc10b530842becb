"""Two inputs the point recipe's tasks hand to their analyses (:mod:`flexshaft.verdict.point_tasks`),
each against an independent result. Written for the mutations tasks-criticals-searched-to-the-
operating-speed and tasks-loop-grid-at-rest-poles (scripts/mutations.toml).

* **The lateral criticals are searched above the operating speed.** API 684's separation margin
  is about the criticals on both sides of Ω_op, up to 26 % above it: the resolution's scan top
  (1.3 Ω_op). On the Jeffcott rotor (tests/rotors.py) with light external damping (ζ = 0.01)
  and ω_n = 1.15 Ω_op the one critical lies above the operating speed; the unbalance peak of a
  damped one-DOF oscillator is at ω_n/√(1 − 2ζ²) (a displacement amplitude U Ω²/|k − mΩ² + icΩ|
  peaks there: Den Hartog, *Mechanical Vibrations*, the rotating-unbalance response), 1.0001 ω_n;
  the tube's mass (7e-6 of the disk's) moves it by less; measured 6e-7, 1e-4 asserted (the peak's
  refinement to its half-power band, docs/requirements.md, fixes it far better than that). With
  ω_n = 2 Ω_op no peak lies in range, and the separation check says how far it looked: 1.3 Ω_op.
* **The loops are gridded at the closed-loop poles of the operating speed.** The bearing loops'
  frequency grid sits at the lightly damped closed-loop poles; the every-root check hands over
  its roots at Ω_op, which must be the damped modes at Ω_op of the modal analysis (another
  code path: :func:`flexshaft.analyses.modal.modes`), to its eigenvalue tolerance 1e-6 (measured
  5e-8 at most); at rest the gyroscopic split moves the tuned driveline's poles by up to 5e-3.
"""

from __future__ import annotations

import numpy as np
from conftest import SMALLEST
from rotors import M_DISK, WN, jeffcott_text

from flexshaft.analyses.modal import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design, tuned_design, with_overrides
from flexshaft.resolution import SCREENING
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict import point_tasks
from flexshaft.verdict.assess import assess
from flexshaft.verdict.operating_point import analyse_point

ZETA = 0.01


def test_a_critical_above_the_operating_speed_is_found():
    """At the screening resolution (its scan of 261 speeds; the smallest one's 3 show no peak)."""
    c_e = 2.0 * ZETA * M_DISK * WN  # the damper at the disk: ζ = c/(2 m ω_n)
    text = jeffcott_text(0.0, c_e).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(WN / 1.15)}")
    design = loads_design(text + "\n[loads]\neccentricity = 1.0e-5\n")
    p = analyse_point(design, SCREENING, detail=False)
    assert p.model.speed < WN < 1.3 * p.model.speed
    speeds = [c.speed for c in p.criticals.criticals]
    peak = WN / np.sqrt(1.0 - 2.0 * ZETA**2)
    assert len(speeds) >= 1 and min(abs(s / peak - 1.0) for s in speeds) < 1e-4, speeds


def test_the_loops_are_gridded_at_the_poles_of_the_operating_speed(monkeypatch):
    handed = {}

    def recorded(model, poles=None, **options):
        handed["poles"] = np.asarray(poles)
        return ()

    monkeypatch.setattr(point_tasks, "bearing_loops", recorded)
    model = build_model(with_overrides(tuned_design(), {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}))
    point_tasks._roots_and_loops(model, SMALLEST)
    poles = handed["poles"][np.argsort(np.abs(handed["poles"]))][:16]
    at_speed = np.asarray(modes(model, model.speed, 40).eigenvalues)
    errors = [np.min(np.abs(at_speed - s)) / abs(s) for s in poles]
    assert poles.size == 16 and max(errors) < 1e-6, errors


def test_no_critical_in_range_says_how_far_it_was_searched():
    """ω_n = 2 Ω_op: no peak below 1.3 Ω_op, and the separation check passes saying it looked up
    to the scan's top, 1.3 Ω_op (the resolution's documented range: API 684's largest margin,
    26 %, lies inside it), not up to the operating speed only."""
    text = jeffcott_text(0.0, 2.0 * ZETA * M_DISK * WN).replace(
        "speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(WN / 2)}"
    )
    design = loads_design(text + "\n[loads]\neccentricity = 1.0e-5\n")
    verdict = assess(design, SCREENING).verdict
    check = verdict.check("separation")
    assert check.status == "pass" and "no resonance peak" in check.note
    assert f"up to {rad_s_to_rpm(1.3 * WN / 2):.0f} rpm" in check.note, check.note
