"""Where the evidence of a point reads its numbers: each active bearing's own orbit, each metal
segment's own safety factors, the refined peak of an undamped resonance between the spin-up's
samples, and the point's operating speed (not the top of its range) for the whirl-onset
requirement.

References (documented rules of docs/requirements.md, hand computations derived here):

* `actuator_orbit`: "static relative offset + largest spin-up orbit amplitude, per actuator, up
  to the highest operating speed", held against that actuator's `gap`;
* `metal_strength`: "smaller of the von Mises yield and modified-Goodman fatigue safety factors
  of each metal segment", against `min_safety_factor`;
* `spinup_deflection`: "largest shaft orbit amplitude during spin-up ... (the scan's speeds, each
  refined critical speed's peak, ...)", against `max_spinup_deflection`;
* `whirl_onset`: required speed "(1 + `min_onset_margin`) × operating speed" (15 % by default).

No analysis runs: the point's analyses are stand-ins whose answers are written by hand. The
values compared are sums or copies of a few binary floats (one rounding each): rel 1e-12 leaves
room for the ulps of a sum and the rpm → rad/s factor, far below every margin asserted (≥ 1 %).
"""

from __future__ import annotations

import math
from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.analyses.criticals import LateralCritical
from flexshaft.design.loads import Operating
from flexshaft.design.requirements import Requirements
from flexshaft.verdict import gather
from flexshaft.verdict.checks import actuator_orbit, evaluate, metal_strength
from flexshaft.verdict.evidence import Evidence

RPM = 2.0 * math.pi / 60.0  # [rad/s] per rpm


def _up_to(speeds: np.ndarray):
    """The scan's indices at or below a speed (the spin-up's own ``up_to``, written out)."""
    return lambda speed: np.flatnonzero(speeds <= speed)


def test_each_active_bearing_is_judged_with_its_own_orbit():
    """Two bearings on a 4-DOF stand-in (fore: DOFs 0, 1; aft: DOFs 2, 3), static displacement
    (3, 4, 0, 6)·10⁻⁵ m: static offsets 5·10⁻⁵ (3-4-5) and 6·10⁻⁵ m. Spin-up to Ω_op = 3000 rpm
    (no range), orbits fore (1, 2, 1.5)·10⁻⁵, aft (4, 1, 7)·10⁻⁵ m at 1000, 2000, 3000 rpm. The aft
    bearing: 6 + 7 = 13·10⁻⁵ m at 3000 rpm against its gap 12·10⁻⁵ m, a failure by 1·10⁻⁵ m (its
    own orbit; the fore one's 2·10⁻⁵ m would pass it); the fore bearing: 5 + 2 = 7·10⁻⁵ m at
    2000 rpm against 20·10⁻⁵ m."""
    speeds = np.array([1000.0, 2000.0, 3000.0]) * RPM
    rows = {"fore": np.eye(4)[:2], "aft": np.eye(4)[2:]}
    gaps = {"fore": 2.0e-4, "aft": 1.2e-4}
    actuators = [NS(name=name, lateral_rows=rows[name], saturation_force=None) for name in ("fore", "aft")]
    p = NS(
        model=NS(actuators=actuators, design=NS(bearing=lambda name: NS(gap=gaps[name], force_capacity=None))),
        spinup=NS(
            speeds=speeds,
            up_to=_up_to(speeds),
            actuator_displacement={"fore": [1.0e-5, 2.0e-5, 1.5e-5], "aft": [4.0e-5, 1.0e-5, 7.0e-5]},
            actuator_force={"fore": [1.0, 2.0, 3.0], "aft": [3.0, 2.0, 1.0]},
        ),
        static_displacement=np.array([3.0e-5, 4.0e-5, 0.0, 6.0e-5]),
        bearing_reactions={"fore": NS(static_lateral=10.0), "aft": NS(static_lateral=20.0)},
        design=NS(operating=NS(speed_range=None)),
        operating_speed=3000.0 * RPM,
    )
    found = {a.name: a for a in gather._actuators(p)}
    assert found["fore"].peak_orbit == 2.0e-5 and found["fore"].orbit_speed == speeds[1]
    assert found["aft"].peak_orbit == 7.0e-5 and found["aft"].orbit_speed == speeds[2]
    check = actuator_orbit(Evidence(operating_speed=p.operating_speed, actuators=tuple(found.values())), Requirements())
    fore, aft = check.findings
    assert fore.value == pytest.approx(7.0e-5, rel=1e-12) and fore.limit == 2.0e-4
    assert aft.value == pytest.approx(13.0e-5, rel=1e-12) and aft.limit == 1.2e-4
    assert check.status == "fail" and check.location["actuator"] == "aft"
    assert check.margin == pytest.approx(-1.0e-5, rel=1e-9)  # 12e-5 − 13e-5: a difference, 1e-9


def test_each_metal_segment_is_judged_with_its_own_safety_factors():
    """A steel tube (fatigue 2.4, yield 1.9) and a titanium one (fatigue 2.0, yield 1.3) aft of
    it: four findings, the titanium's yield 1.3 governs, 1.3 − 1.5 = −0.2 short of the strength
    limit: the check fails (the steel tube alone would pass it)."""
    worst = {
        "steel": {"fatigue": {"safety_factor": 2.4, "station": 0.2}, "yield": {"safety_factor": 1.9, "station": 0.4}},
        "titanium": {
            "fatigue": {"safety_factor": 2.0, "station": 1.6},
            "yield": {"safety_factor": 1.3, "station": 1.8},
        },
    }
    metal = NS(
        evaluated=True,
        segments=("steel", "titanium"),
        notes=(),
        worst=lambda criterion, segment: worst[segment][criterion],
    )
    found = gather._metal(NS(metal_strength=metal), {})["metal_strength"]
    assert sorted((m.segment, m.safety_factor) for m in found) == [
        ("steel", 1.9),
        ("steel", 2.4),
        ("titanium", 1.3),
        ("titanium", 2.0),
    ]
    check = metal_strength(Evidence(operating_speed=100.0, metal_strength=found), Requirements(min_safety_factor=1.5))
    assert check.status == "fail" and check.value == 1.3 and check.location["station"] == 1.8
    assert check.margin == pytest.approx(-0.2, rel=1e-12)
    assert check.location["case"].startswith("segment titanium")


#: Ω_op = 4800 rpm, speed_range [0.9, 1.05]: the highest operating speed 5040 rpm.
OPERATING_POINT = Operating(speed_rpm=4800.0, power=0.0, speed_range=(0.9, 1.05))


def _point(criticals: tuple) -> NS:
    """A point with a spin-up scan and the given criticals, and no other result: the scan samples
    1000, 2500, 3500, 4800, 5040 and 6000 rpm with shaft peaks 1, 3, 2, 1.5, 1.4, 9 mm (the
    largest, 9 mm, above the highest operating speed); two stations at 0.5 and 1.5 m, the larger
    orbit at 1.5 m."""
    speeds = np.array([1000.0, 2500.0, 3500.0, 4800.0, 5040.0, 6000.0]) * RPM
    peaks = np.array([1.0, 3.0, 2.0, 1.5, 1.4, 9.0]) * 1e-3
    return NS(
        strength_static=None,
        strength_total=None,
        metal_strength=None,
        coupling_misalignment=None,
        buckling=None,
        criticals=NS(criticals=criticals, search_top=8000.0 * RPM, note=""),
        thermal=None,
        design=NS(thermal=NS(allowable_temperature_c=100.0), operating=OPERATING_POINT),
        spinup=NS(speeds=speeds, shaft_peak=peaks, envelope=np.vstack([0.5 * peaks, peaks]), up_to=_up_to(speeds)),
        torsional_separation=None,
        torsional_modes=None,
        bearing_loops=None,
        operating_speed=OPERATING_POINT.speed_rad_s,
        model=NS(actuators=[], dofs=NS(shaft_x=np.array([0.5, 1.5]))),
    )


def test_an_undamped_resonance_peak_between_the_samples_governs_the_spinup_orbit(monkeypatch):
    """An undamped critical (AF = ∞) at 3000 rpm, between the samples 2500 and 3500 rpm, whose
    refined peak orbit is 5 mm at station 1.2 m: the spin-up deflection is 5 mm there, not the
    sampled 3 mm (nor the 9 mm at 6000 rpm, above the highest operating speed 5040 rpm); against
    a 4 mm limit it fails by 1 mm (the samples alone would pass it).

    Undamped, as the only case the product leaves between the samples: the point's spin-up adds
    the speed of each critical with a finite amplification factor to its scan (``with_speeds`` in
    ``point_tasks._spinup``), so a damped peak is a sample itself; an undamped one (AF = ∞) is
    skipped there and reaches the verdict only through its refined peak orbit. Its fields are the
    ones ``criticals._refine`` writes for a peak on an undamped mode."""
    monkeypatch.setattr(gather, "_whirl", lambda p: {})  # no stability result: the onset is not judged here
    undamped = "undamped resonance: the mode at the peak has no damping, the response is unbounded"
    location = {"station": 1.2, "af_method": "two-sided", "peak_orbit": 5.0e-3, "detail": undamped}
    critical = LateralCritical(3000.0 * RPM, float("inf"), location)
    evidence = gather.gather_evidence(_point((critical,)))
    assert evidence.spinup_peak == 5.0e-3
    assert evidence.spinup_location["station"] == 1.2
    assert evidence.spinup_location["speed"] == pytest.approx(3000.0 * RPM, rel=1e-15)
    check = evaluate(evidence, Requirements(max_spinup_deflection=4.0e-3)).check("spinup_deflection")
    assert check.status == "fail" and check.margin == pytest.approx(-1.0e-3, rel=1e-12)


def test_the_sampled_peak_governs_without_a_refined_one(monkeypatch):
    """Without criticals the largest sample up to 5040 rpm governs: 3 mm at 2500 rpm, station
    1.5 m (the larger row of the envelope)."""
    monkeypatch.setattr(gather, "_whirl", lambda p: {})
    evidence = gather.gather_evidence(_point(()))
    assert evidence.spinup_peak == 3.0e-3 and evidence.spinup_location["station"] == 1.5
    assert evidence.spinup_location["speed"] == pytest.approx(2500.0 * RPM, rel=1e-15)


def test_the_onset_requirement_is_read_at_the_operating_speed_not_the_top_of_the_range(monkeypatch):
    """An onset at 5600 rpm with the default 15 % margin: required 1.15 × 4800 = 5520 rpm (the
    operating speed's), a pass by 80 rpm; 1.15 × 5040 = 5796 rpm (the range's top) would fail it."""
    onset = {"stability_max_speed": 8000.0 * RPM, "onset_speed": 5600.0 * RPM, "onset_location": {}}
    monkeypatch.setattr(gather, "_whirl", lambda p: onset)
    evidence = gather.gather_evidence(_point(()))
    assert evidence.operating_speed == pytest.approx(4800.0 * RPM, rel=1e-15)
    check = evaluate(evidence, Requirements()).check("whirl_onset")
    assert check.limit == pytest.approx(5520.0 * RPM, rel=1e-12)
    assert check.status == "pass" and check.margin == pytest.approx(80.0 * RPM, rel=1e-9)
